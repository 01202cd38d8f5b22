// SPDX-License-Identifier: MIT
#include "materials/section/geometry/StraightLayer.h"

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::materials::section {

void StraightLayer::validate() const {
  if (numBars < 1) throw InputError("numBars", "must be at least 1");
  if (!(barArea > 0.0)) throw InputError("areaBar", "must be positive");
}

void StraightLayer::discretize(FiberList& out) const {
  if (numBars == 1) {
    out.push_back({0.5 * (yStart + yEnd), 0.5 * (zStart + zEnd), barArea, materialTag});
    return;
  }
  for (int i = 0; i < numBars; ++i) {
    const double s = double(i) / (numBars - 1);
    out.push_back(
        {yStart + s * (yEnd - yStart), zStart + s * (zEnd - zStart), barArea, materialTag});
  }
}

void CircLayer::validate() const {
  if (numBars < 1) throw InputError("numBars", "must be at least 1");
  if (!(barArea > 0.0)) throw InputError("areaBar", "must be positive");
  if (!(radius >= 0.0)) throw InputError("radius", "must be zero or positive");
}

void CircLayer::discretize(FiberList& out) const {
  const double deg = std::numbers::pi / 180.0;
  const double span = endAngle - startAngle;
  const bool full = std::abs(std::abs(span) - 360.0) < 1e-12;
  const double step = full ? span / numBars : (numBars > 1 ? span / (numBars - 1) : 0.0);
  for (int i = 0; i < numBars; ++i) {
    const double t = (startAngle + i * step) * deg;
    out.push_back(
        {yCenter + radius * std::cos(t), zCenter + radius * std::sin(t), barArea, materialTag});
  }
}

}  // namespace dabs::materials::section
