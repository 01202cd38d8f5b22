// SPDX-License-Identifier: MIT
#pragma once

#include "materials/section/geometry/Fiber.h"

namespace dabs::materials::section {

/// Circular (annular sector) patch `patch circ matTag nCirc nRad yC zC rInt rExt ?startAng
/// endAng?` (angles in degrees, default 0 to 360). Each of the nCirc x nRad cells is an exact
/// annular sector (area and centroid), as OpenSees/OpenSees:SRC/material/section/repres/patch/
/// CircPatch.cpp with CircSectionCell, so the total area is the exact annulus area.
struct CircPatch {
  int materialTag = 0;
  int divCirc = 1, divRad = 1;
  double yCenter = 0.0, zCenter = 0.0;
  double rInt = 0.0, rExt = 0.0;
  double startAngle = 0.0, endAngle = 360.0;  ///< degrees

  /// Throws InputError for nonpositive divisions or radii with rExt <= rInt.
  void validate() const;
  void discretize(FiberList& out) const;
};

}  // namespace dabs::materials::section
