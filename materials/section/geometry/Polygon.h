// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "materials/section/geometry/Fiber.h"

namespace dabs::materials::section {

/// Signed area of a quadrilateral with vertices (y[a], z[a]) (shoelace formula; > 0 when
/// counter-clockwise in the y-z plane).
inline double quadArea(const std::array<double, 4>& y, const std::array<double, 4>& z) {
  double a = 0.0;
  for (int i = 0; i < 4; ++i) a += y[i] * z[(i + 1) % 4] - y[(i + 1) % 4] * z[i];
  return 0.5 * a;
}

/// Area and centroid of a quadrilateral (polygon centroid formula), as a fiber without material.
inline FiberPoint quadCentroid(const std::array<double, 4>& y, const std::array<double, 4>& z) {
  double a = 0.0, cy = 0.0, cz = 0.0;
  for (int i = 0; i < 4; ++i) {
    const int k = (i + 1) % 4;
    const double c = y[i] * z[k] - y[k] * z[i];
    a += c;
    cy += (y[i] + y[k]) * c;
    cz += (z[i] + z[k]) * c;
  }
  a *= 0.5;
  return FiberPoint{cy / (6.0 * a), cz / (6.0 * a), a, 0};
}

}  // namespace dabs::materials::section
