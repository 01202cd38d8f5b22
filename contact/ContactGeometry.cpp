// SPDX-License-Identifier: MIT
#include "contact/ContactGeometry.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::contact {

SurfaceFrame makeSurfaceFrame(const std::array<Eigen::Vector3d, 4>& x) {
  const auto& [a, b, c, d] = x;
  SurfaceFrame f;
  f.size = std::max((c - a).norm(), (d - b).norm());
  if (!(f.size > 0.0)) throw InputError("surface", "nodes a, b, c, d coincide");
  const Eigen::Vector3d rightHand = (b - a).cross(d - a);  // orientation: right-hand rule
  const Eigen::Vector3d mean = (c - a).cross(d - b);       // direction: mean plane of the quad
  const double areaTol = 1e-12 * f.size * f.size;
  if (rightHand.norm() <= areaTol || mean.norm() <= areaTol)
    throw InputError("surface", "quad a b c d has zero area");
  if (rightHand.dot(mean) <= 0.0)
    throw InputError("surface", "quad a b c d is not convex or its nodes are not in order");
  f.n = mean.normalized();
  Eigen::Vector3d t1 = (b - a) - (b - a).dot(f.n) * f.n;
  if (t1.norm() <= 1e-12 * f.size) throw InputError("surface", "edge a-b is along the normal");
  f.t1 = t1.normalized();
  f.t2 = f.n.cross(f.t1);
  return f;
}

std::optional<Eigen::Vector2d> inverseBilinear(const std::array<Eigen::Vector2d, 4>& s,
                                               const Eigen::Vector2d& target, double tolerance) {
  // S(xi, eta) = a0 + a1 xi + a2 eta + a3 xi eta, expanded from the shape functions.
  const Eigen::Vector2d a0 = 0.25 * (s[0] + s[1] + s[2] + s[3]);
  const Eigen::Vector2d a1 = 0.25 * (-s[0] + s[1] + s[2] - s[3]);
  const Eigen::Vector2d a2 = 0.25 * (-s[0] - s[1] + s[2] + s[3]);
  const Eigen::Vector2d a3 = 0.25 * (s[0] - s[1] + s[2] - s[3]);
  constexpr int kMaxIterations = 25;
  Eigen::Vector2d xi = Eigen::Vector2d::Zero();
  for (int it = 0; it < kMaxIterations; ++it) {
    const Eigen::Vector2d r = a0 + a1 * xi(0) + a2 * xi(1) + a3 * (xi(0) * xi(1)) - target;
    if (r.norm() <= tolerance) return xi;
    Eigen::Matrix2d J;
    J.col(0) = a1 + a3 * xi(1);
    J.col(1) = a2 + a3 * xi(0);
    const double det = J.determinant();
    if (!(std::abs(det) > 1e-14 * J.squaredNorm())) return std::nullopt;
    xi -= J.inverse() * r;
    if (!xi.allFinite() || xi.cwiseAbs().maxCoeff() > 1e3) return std::nullopt;
  }
  return std::nullopt;
}

bool onQuad(const Eigen::Vector2d& xi) noexcept {
  constexpr double kEdgeTolerance = 1e-9;
  return std::abs(xi(0)) <= 1.0 + kEdgeTolerance && std::abs(xi(1)) <= 1.0 + kEdgeTolerance;
}

BoundingSphere boundingSphere(const std::array<Eigen::Vector3d, 4>& x) noexcept {
  const Eigen::Vector3d c = 0.25 * (x[0] + x[1] + x[2] + x[3]);
  double r2 = 0.0;
  for (const auto& p : x) r2 = std::max(r2, (p - c).squaredNorm());
  return {c, std::sqrt(r2)};
}

}  // namespace dabs::contact
