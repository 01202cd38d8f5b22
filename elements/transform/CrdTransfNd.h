// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/Congruence.h"
#include "elements/transform/CrdTransf.h"
#include "elements/transform/FrameTraits.h"

namespace dabs::elements {

/// Beam-column transformation of an Ndm-dimensional model (the fixed-size kinematics interface;
/// conventions of each dimension in CrdTransf2d.h and CrdTransf3d.h). Holds the undeformed
/// geometry (length, local axes, the linear compatibility matrix B0 of OpenSees/OpenSees:SRC/
/// coordTransformation/LinearCrdTransf2d.cpp and LinearCrdTransf3d.cpp) and the trial basic
/// deformations; the derived transformations say how v and d(v)/d(u) follow from u. Joint
/// offsets (-jntOffset) are not supported.
template <int Ndm>
class CrdTransfNd : public CrdTransf {
 public:
  using Traits = FrameTraits<Ndm>;
  using Basic = typename Traits::Basic;
  using BasicMatrix = typename Traits::BasicMatrix;
  using Global = typename Traits::Global;
  using GlobalMatrix = typename Traits::GlobalMatrix;
  using Compat = typename Traits::Compat;
  using Axes = typename Traits::Axes;
  static constexpr int kDofPerNode = Traits::kDofPerNode;

  /// 2D: the local z axis is the global Z axis.
  explicit CrdTransfNd(int tag) noexcept requires(Ndm == 2) : CrdTransf(tag) {}
  /// 3D: `vecxz`, a vector in the local x-z plane (global components); must be nonzero.
  CrdTransfNd(int tag, const Eigen::Vector3d& vecxz) requires(Ndm == 3)
      : CrdTransf(tag), vecxz_(vecxz) {}

  int dimension() const final { return Ndm; }
  /// Sets L0, the local axes and the linear compatibility matrix; throws InputError for a zero
  /// length or (3D) vecxz parallel to the element axis.
  void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) override;
  double initialLength() const final { return length0_; }

  /// Sets the trial basic deformations from TOTAL global end displacements.
  virtual void update(const Global& u) = 0;
  /// Trial basic deformations.
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
  /// T^T m T with the undeformed axes (mass matrices given in local axes).
  GlobalMatrix globalFromLocal(const GlobalMatrix& local) const;
  /// T^T p: end forces given in the undeformed local axes, in global components.
  Global globalFromLocal(const Global& local) const;
  /// Local end forces in OpenSees' `localForce` convention: 2D [N V M]_i [N V M]_j, 3D
  /// [N Vy Vz T My Mz]_i [..]_j (OpenSees/OpenSees:SRC/element/elasticBeamColumn/
  /// ElasticBeam2d.cpp and ElasticBeam3d.cpp, getResponse case 3).
  Global localForce(const Basic& q) const;
  /// Undeformed local axes as the rows of a rotation matrix (global components).
  const Axes& axes() const noexcept { return axes_; }
  /// The vector given for the local x-z plane (2D: global Z).
  const Eigen::Vector3d& vecxz() const noexcept { return vecxz_; }

 protected:
  /// Local displacements T u (undeformed axes).
  Global toLocal(const Global& u) const;
  /// B^T kb B (elements/Congruence.h).
  static GlobalMatrix congruence(const Compat& b, const BasicMatrix& kb) {
    return elements::congruence(b, kb);
  }

  Eigen::Vector3d vecxz_ = Eigen::Vector3d::UnitZ();
  double length0_ = 0.0;
  Axes axes_ = Axes::Identity();     ///< rows: local x, y (, z)
  Compat compat0_ = Compat::Zero();  ///< linear compatibility, global
  Compat compat_ = Compat::Zero();   ///< d(v)/d(u) at the trial geometry
  Basic v_ = Basic::Zero();
};

extern template class CrdTransfNd<2>;
extern template class CrdTransfNd<3>;

}  // namespace dabs::elements
