// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "materials/section/FiberSection.h"

namespace dabs::domain {

// Outlines of member cross-sections for the Viewer page, as flat lists of local (y, z) vertices.

/// Vertices of a circle of diameter d as a polygon of 32 sides.
std::vector<double> circleOutline(double d);
/// Outline of a fiber section: the convex hull of the fiber positions (Andrew's monotone chain),
/// scaled about the area centroid so that it encloses the section's area. The outermost fibers
/// sit at their patch cells' centroids, inside the true edge; scaling to the area puts the
/// drawn edge where the area says it is (exact for a rectangle of equal cells, within 1 % of the
/// radius for a circle of 12 sectors). Empty for fewer than three fibers off one line.
std::vector<double> fiberOutline(const materials::section::FiberSection3d& s);

}  // namespace dabs::domain
