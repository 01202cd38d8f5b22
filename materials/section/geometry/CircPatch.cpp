// SPDX-License-Identifier: MIT
#include "materials/section/geometry/CircPatch.h"

#include <array>
#include <cmath>
#include <numbers>

#include "materials/InputError.h"

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
      const double t0 = startAngle * deg + i * dTheta;
      // Exact annular sector: area d/2 (r1^2 - r0^2), centroid on the bisector at radius
      // (2/3)(r1^3 - r0^3)/(r1^2 - r0^2) sin(d/2)/(d/2).
      const double half = 0.5 * dTheta, mid = t0 + half;
      const double rc =
          2.0 / 3.0 * (r1 * r1 * r1 - r0 * r0 * r0) / (r1 * r1 - r0 * r0) * std::sin(half) / half;
      FiberPoint f{yCenter + rc * std::cos(mid), zCenter + rc * std::sin(mid),
                   half * (r1 * r1 - r0 * r0), materialTag};
      out.push_back(f);
    }
  }
}

}  // namespace dabs::materials::section
