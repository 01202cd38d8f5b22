// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

namespace dabs::materials::section {

/// One fiber of a section: centroid (y, z) in section axes, area, and the uniaxial material tag.
struct FiberPoint {
  double y = 0.0;
  double z = 0.0;
  double area = 0.0;
  int materialTag = 0;
};

using FiberList = std::vector<FiberPoint>;

}  // namespace dabs::materials::section
