// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/transform/CrdTransf.h"

namespace dabs::elements {

/// Spatial beam-column transformation (ndm 3, ndf 6). Global end displacements are ordered
/// [ux uy uz rx ry rz]_i [ux uy uz rx ry rz]_j. Local axes follow OpenSees
/// (OpenSees/OpenSees:SRC/coordTransformation/LinearCrdTransf3d.cpp computeElemtLengthAndOrient):
/// x from node i to node j, y = vecxz x x (normalised), z = x x y, so vecxz lies in the local x-z
/// plane. Basic deformations are [elongation, theta_z_i, theta_z_j, theta_y_i, theta_y_j, twist]
/// and basic forces q = [N, Mz_i, Mz_j, My_i, My_j, T]. Joint offsets (-jntOffset) are not
/// supported.
class CrdTransf3d : public CrdTransf {
 public:
  using Basic = Eigen::Matrix<double, 6, 1>;
  using BasicMatrix = Eigen::Matrix<double, 6, 6>;
  using Global = Eigen::Matrix<double, 12, 1>;
  using GlobalMatrix = Eigen::Matrix<double, 12, 12>;
  using Compat = Eigen::Matrix<double, 6, 12>;

  /// `vecxz`: a vector in the local x-z plane (global components); must be nonzero.
  CrdTransf3d(int tag, const Eigen::Vector3d& vecxz) : CrdTransf(tag), vecxz_(vecxz) {}
  int dimension() const final { return 3; }
  /// Sets L0, the local axes and the linear compatibility matrix; throws InputError for zero
  /// length or vecxz parallel to the element axis.
  void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) override;
  double initialLength() const final { return length0_; }

  /// Sets the trial basic deformations from TOTAL global end displacements.
  virtual void update(const Global& u) = 0;
  /// Trial basic deformations.
  const Basic& basicDeformation() const noexcept { return v_; }
  /// Global end forces equilibrating basic forces q at the trial geometry.
  virtual Global globalForce(const Basic& q) const;
  /// Global tangent for a basic tangent kb and basic forces q at the trial geometry.
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
  /// T^T m T with the undeformed axes (mass matrices given in local axes).
  GlobalMatrix globalFromLocal(const GlobalMatrix& local) const;
  /// Local end forces [N Vy Vz T My Mz]_i [..]_j in OpenSees' `localForce` convention
  /// (OpenSees/OpenSees:SRC/element/elasticBeamColumn/ElasticBeam3d.cpp getResponse case 3).
  Global localForce(const Basic& q) const;
  /// Undeformed local axes as the rows of a rotation matrix (global components).
  const Eigen::Matrix3d& axes() const noexcept { return axes_; }
  const Eigen::Vector3d& vecxz() const noexcept { return vecxz_; }

 protected:
  Global toLocal(const Global& u) const;

  Eigen::Vector3d vecxz_;
  double length0_ = 0.0;
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity();  ///< rows: local x, y, z
  Compat compat0_ = Compat::Zero();                     ///< linear compatibility, global
  Compat compat_ = Compat::Zero();                      ///< d(v)/d(u) at the trial geometry
  Basic v_ = Basic::Zero();
};

}  // namespace dabs::elements
