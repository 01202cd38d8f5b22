// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/transform/CrdTransf.h"

namespace dabs::elements {

/// Planar beam-column transformation (ndm 2, ndf 3). Global end displacements are ordered
/// [ux_i uy_i rz_i ux_j uy_j rz_j]; basic deformations are [axial elongation, rotation at i,
/// rotation at j] relative to the chord, and basic forces q = [N, M_i, M_j] (tension and
/// counter-clockwise end moments positive), as OpenSees/OpenSees:SRC/coordTransformation/
/// LinearCrdTransf2d.cpp. Joint offsets (-jntOffset) are not supported.
class CrdTransf2d : public CrdTransf {
 public:
  using Basic = Eigen::Vector3d;
  using BasicMatrix = Eigen::Matrix3d;
  using Global = Eigen::Matrix<double, 6, 1>;
  using GlobalMatrix = Eigen::Matrix<double, 6, 6>;
  using Compat = Eigen::Matrix<double, 3, 6>;

  using CrdTransf::CrdTransf;
  int dimension() const final { return 2; }
  /// Sets L0, the direction cosines and the linear compatibility matrix; throws for zero length.
  void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) override;
  double initialLength() const final { return length0_; }

  /// Sets the trial basic deformations from TOTAL global end displacements.
  virtual void update(const Global& u) = 0;
  /// Trial basic deformations [eps*L, theta_i, theta_j].
  const Basic& basicDeformation() const noexcept { return v_; }
  /// Global end forces equilibrating basic forces q at the trial geometry.
  virtual Global globalForce(const Basic& q) const;
  /// Consistent global tangent for a basic tangent kb and basic forces q at the trial geometry.
  virtual GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const;
  /// Global stiffness of kb at the undeformed geometry (no geometric terms).
  GlobalMatrix initialGlobalStiffness(const BasicMatrix& kb) const;
  /// True when d(v)/d(u) never changes (Linear, PDelta): then globalStiffness(kb, q) equals
  /// initialGlobalStiffness(kb) plus addGeometricStiffness(q), so an element with a constant kb
  /// forms B^T kb B once and adds only the geometric part per update.
  virtual bool hasConstantCompatibility() const { return false; }
  /// Adds the geometric stiffness of basic forces q to k (nothing for Linear). Only meaningful
  /// when hasConstantCompatibility().
  virtual void addGeometricStiffness(GlobalMatrix& k, const Basic& q) const {
    static_cast<void>(k);
    static_cast<void>(q);
  }
  /// T^T m T with the undeformed rotation (mass matrices given in local axes).
  GlobalMatrix globalFromLocal(const GlobalMatrix& local) const;
  /// Local end forces [N_i V_i M_i N_j V_j M_j] in OpenSees' `localForce` convention
  /// (OpenSees/OpenSees:SRC/element/elasticBeamColumn/ElasticBeam2d.cpp getResponse case 3).
  Global localForce(const Basic& q) const;
  /// Undeformed local x axis (global components).
  Eigen::Vector2d xAxis() const { return {cos_, sin_}; }

 protected:
  /// Local displacements T u (undeformed axes).
  Global toLocal(const Global& u) const;

  double length0_ = 0.0;
  double cos_ = 1.0, sin_ = 0.0;
  GlobalMatrix rot_ = GlobalMatrix::Identity();  ///< T: global -> local (undeformed)
  Compat compat0_ = Compat::Zero();              ///< linear compatibility, global
  Compat compat_ = Compat::Zero();               ///< d(v)/d(u) at the trial geometry
  Basic v_ = Basic::Zero();
};

}  // namespace dabs::elements
