// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>

namespace dabs::contact {

/// Geometry of a contactor node k against a target quad a, b, c, d (style.md section 3: geometry
/// apart from the normal and friction laws).
///
/// Frame. The surface frame (n, t1, t2) is fixed at the reference (undeformed) geometry: n is the
/// unit outward normal of the quad, oriented by the right-hand rule over a, b, c, d, i.e. along
/// (b - a) x (d - a); the mean normal (c - a) x (d - b) gives its direction, which is the same for
/// a planar quad and the best plane for a slightly warped one. t1 is (b - a) projected on the
/// plane, t2 = n x t1. Girder faces translate far but rotate little, so a fixed frame is the
/// small-rotation assumption of this element (stated in NodeToSurfaceContact3d.h).
///
/// Coordinates. Every point x has in-plane coordinates s = (t1.x, t2.x) and height z = n.x. The
/// target surface is the bilinear map x(xi, eta) = sum N_i(xi, eta) x_i with
///   N_a = (1-xi)(1-eta)/4, N_b = (1+xi)(1-eta)/4, N_c = (1+xi)(1+eta)/4, N_d = (1-xi)(1+eta)/4,
/// (xi along a->b, eta along a->d). The projection p of k is the surface point with the same
/// in-plane coordinates as k (projection along n), found by Newton's method on
/// S(xi) = sum N_i s_i = s_k. The gap is g = z_k - sum N_i(xi_p) z_i: g > 0 open, g < 0
/// penetration.
struct SurfaceFrame {
  Eigen::Vector3d n = Eigen::Vector3d::UnitZ();   ///< unit outward normal
  Eigen::Vector3d t1 = Eigen::Vector3d::UnitX();  ///< first unit tangent (along a->b)
  Eigen::Vector3d t2 = Eigen::Vector3d::UnitY();  ///< second unit tangent, n x t1
  double size = 1.0;                              ///< longest diagonal of the reference quad
};

/// Builds the frame from reference coordinates of a, b, c, d. Throws InputError for a degenerate
/// quad (zero area, nodes not distinct) or one whose diagonal normal disagrees with (b-a) x (d-a)
/// (a non-convex or badly ordered quad).
SurfaceFrame makeSurfaceFrame(const std::array<Eigen::Vector3d, 4>& target);

/// Bilinear shape functions at (xi, eta), in node order a, b, c, d.
template <class T>
std::array<T, 4> shapeFunctions(const T& xi, const T& eta) {
  return {(1.0 - xi) * (1.0 - eta) * 0.25, (1.0 + xi) * (1.0 - eta) * 0.25,
          (1.0 + xi) * (1.0 + eta) * 0.25, (1.0 - xi) * (1.0 + eta) * 0.25};
}

/// Derivatives dN_i/dxi (first array) and dN_i/deta (second) at (xi, eta).
template <class T>
std::array<std::array<T, 4>, 2> shapeDerivatives(const T& xi, const T& eta) {
  return {{{-(1.0 - eta) * 0.25, (1.0 - eta) * 0.25, (1.0 + eta) * 0.25, -(1.0 + eta) * 0.25},
           {-(1.0 - xi) * 0.25, -(1.0 + xi) * 0.25, (1.0 + xi) * 0.25, (1.0 - xi) * 0.25}}};
}

/// Solves sum N_i(xi) s_i = target for xi by Newton's method (in-plane coordinates s_i of the
/// target nodes). Returns nullopt when the map is singular or Newton does not converge; the result
/// may lie outside [-1, 1]^2 (the point is then off the quad). `tolerance` is on |S(xi) - target|.
std::optional<Eigen::Vector2d> inverseBilinear(const std::array<Eigen::Vector2d, 4>& s,
                                               const Eigen::Vector2d& target, double tolerance);

/// True when (xi, eta) lies on the closed quad [-1, 1]^2 (edges and corners included, within a
/// relative tolerance of 1e-9 so a point exactly on an edge counts as on the quad).
bool onQuad(const Eigen::Vector2d& xi) noexcept;

/// Centre (mean of the nodes) and radius (largest node distance) of a quad's bounding sphere.
struct BoundingSphere {
  Eigen::Vector3d center;
  double radius;
};
BoundingSphere boundingSphere(const std::array<Eigen::Vector3d, 4>& x) noexcept;

}  // namespace dabs::contact
