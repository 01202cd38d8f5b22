// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <memory>

#include "elements/transform/CrdTransf3d.h"

namespace dabs::elements {

/// The corotational transformation of an Ndm-dimensional model: one specialisation per dimension.
template <int Ndm>
class CorotationalTransf;

/// Spatial corotational transformation (the 3D specialisation) (`geomTransf Corotational tag vx vy
/// vz`) for large displacements and rotations with small strains (Crisfield 1990, Comput. Methods
/// Appl. Mech. Eng. 81; the element-independent form of Battini & Pacoste 2002, Comput. Methods
/// Appl. Mech. Eng. 191, whose corotated frame is used here).
///  - Nodal triads: R = exp(dpsi) R_c, with R_c the committed triad and dpsi the increment of the
///    rotation dofs since the last commit, taken as a spatial rotation vector (as OpenSees/
///    OpenSees:SRC/coordTransformation/CorotCrdTransf3d.cpp treats rotation increments), so the
///    transformation keeps state across commits.
///  - Corotated frame: e1 along the deformed chord; with q = (R_i + R_j) y0 / 2 the mean image of
///    the initial local y axis, e3 = e1 x q / |e1 x q|, e2 = e3 x e1 (Battini & Pacoste eq. 6).
///  - Local rotations: theta = log(E^T R E0) (rotation vector of the nodal triad seen from the
///    corotated frame; E0 the undeformed axes); basic deformations [Ln - L0, theta_z,i,
///    theta_z,j, theta_y,i, theta_y,j, theta_x,j - theta_x,i], which reduce to the Linear ones
///    for small displacements.
/// B = dv/du and the geometric stiffness sum_k q_k d2v_k/du2 are exact: they are computed by
/// forward-mode automatic differentiation (nested dual numbers) of the kinematics above, so the
/// tangent is consistent (and symmetric) for the increment parameterisation used.
template <>
class CorotationalTransf<3> final : public CrdTransf3d {
 public:
  using CrdTransf3d::CrdTransf3d;
  std::string_view typeName() const override { return "Corotational"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<CorotationalTransf>(*this);
  }
  void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) override;
  void update(const Global& u) override;
  GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const override;
  void commitState() override;
  void revertToLastCommit() override {}
  void revertToStart() override;

  /// Trial nodal triad of end n (0: i, 1: j), global components (columns: images of the global
  /// axes).
  Eigen::Matrix3d nodalTriad(int n) const;

  /// Evaluates the basic deformations for total displacements u (any scalar type). Public so that
  /// tests can evaluate the kinematics with plain doubles.
  template <class S>
  std::array<S, 6> kinematics(const std::array<S, 12>& u) const;

 private:
  Eigen::Vector3d xi_ = Eigen::Vector3d::Zero(), xj_ = Eigen::Vector3d::Zero();
  std::array<Eigen::Matrix3d, 2> rotCommitted_{Eigen::Matrix3d::Identity(),
                                               Eigen::Matrix3d::Identity()};
  std::array<Eigen::Vector3d, 2> thetaCommitted_{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  Global uTrial_ = Global::Zero();
  std::array<GlobalMatrix, 6> hessian_{};  ///< d2 v_k / du2 at the trial state
};

using CorotationalTransf3d = CorotationalTransf<3>;

}  // namespace dabs::elements
