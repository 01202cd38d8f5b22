// SPDX-License-Identifier: MIT
#include "materials/section/geometry/CircPatch.h"

#include <array>
#include <cmath>
#include <numbers>

#include "materials/InputError.h"
#include "materials/section/geometry/Polygon.h"

namespace dabs::materials::section {

void CircPatch::validate() const {
  if (divCirc < 1) throw InputError("numSubdivCirc", "must be at least 1");
  if (divRad < 1) throw InputError("numSubdivRad", "must be at least 1");
  if (!(rInt >= 0.0)) throw InputError("intRad", "must be zero or positive");
  if (!(rExt > rInt)) throw InputError("extRad", "must exceed intRad");
  if (!(endAngle > startAngle)) throw InputError("endAng", "must exceed startAng");
}

void CircPatch::discretize(FiberList& out) const {
  const double deg = std::numbers::pi / 180.0;
  const double dTheta = (endAngle - startAngle) * deg / divCirc;
  const double dR = (rExt - rInt) / divRad;
  for (int k = 0; k < divRad; ++k) {
    const double r0 = rInt + k * dR, r1 = r0 + dR;
    for (int i = 0; i < divCirc; ++i) {
      const double t0 = startAngle * deg + i * dTheta, t1 = t0 + dTheta;
      const std::array<double, 4> y{yCenter + r0 * std::cos(t0), yCenter + r1 * std::cos(t0),
                                    yCenter + r1 * std::cos(t1), yCenter + r0 * std::cos(t1)};
      const std::array<double, 4> z{zCenter + r0 * std::sin(t0), zCenter + r1 * std::sin(t0),
                                    zCenter + r1 * std::sin(t1), zCenter + r0 * std::sin(t1)};
      FiberPoint f = quadCentroid(y, z);
      f.materialTag = materialTag;
      out.push_back(f);
    }
  }
}

}  // namespace dabs::materials::section
