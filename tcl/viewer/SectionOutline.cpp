// SPDX-License-Identifier: MIT
#include "tcl/viewer/SectionOutline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace dabs::domain {

std::vector<double> circleOutline(double d) {
  constexpr int kSides = 32;
  std::vector<double> out;
  for (int k = 0; k < kSides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / kSides;
    out.push_back(0.5 * d * std::cos(a));
    out.push_back(0.5 * d * std::sin(a));
  }
  return out;
}

std::vector<double> fiberOutline(const materials::section::FiberSection3d& s) {
  struct P {
    double y, z;
  };
  std::vector<P> p;
  double area = 0.0, cy = 0.0, cz = 0.0;
  for (int i = 0; i < s.numFibers(); ++i) {
    p.push_back({s.fiberY(i), s.fiberZ(i)});
    area += s.fiberArea(i);
    cy += s.fiberArea(i) * s.fiberY(i);
    cz += s.fiberArea(i) * s.fiberZ(i);
  }
  if (p.size() < 3 || area <= 0.0) return {};
  cy /= area;
  cz /= area;
  std::sort(p.begin(), p.end(), [](P a, P b) { return a.y < b.y || (a.y == b.y && a.z < b.z); });
  auto cross = [](P o, P a, P b) { return (a.y - o.y) * (b.z - o.z) - (a.z - o.z) * (b.y - o.y); };
  std::vector<P> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  if (hull.size() < 3) return {};
  double hullArea = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const P a = hull[i], b = hull[(i + 1) % hull.size()];
    hullArea += 0.5 * (a.y * b.z - b.y * a.z);
  }
  const double scale = hullArea > 0.0 ? std::sqrt(area / hullArea) : 1.0;
  std::vector<double> out;
  for (const P& h : hull) {
    out.push_back(cy + scale * (h.y - cy));
    out.push_back(cz + scale * (h.z - cz));
  }
  return out;
}

}  // namespace dabs::domain
