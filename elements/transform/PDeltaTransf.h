// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/transform/CrdTransfNd.h"

namespace dabs::elements {

/// Linear transformation plus the P-Delta (leaning column) effect of the axial force on the chord
/// rotation (`geomTransf PDelta tag` in 2D, `geomTransf PDelta tag vx vy vz` in 3D), as OpenSees/
/// OpenSees:SRC/coordTransformation/PDeltaCrdTransf2d.cpp and PDeltaCrdTransf3d.cpp: the local
/// end shears get +-N delta/L, with delta the difference of the transverse end displacements in
/// each bending plane (local y; 3D also local z), and the tangent the geometric matrix
/// N/L [1 -1; -1 1] on those translations. Like OpenSees, the tangent omits the term from
/// d(N)/du times the chord rotation, so it stays symmetric; it is exact when the transverse end
/// displacements are equal.
template <int Ndm>
class PDeltaTransf final : public CrdTransfNd<Ndm> {
 public:
  using Base = CrdTransfNd<Ndm>;
  using Base::Base;
  using typename Base::Basic;
  using typename Base::BasicMatrix;
  using typename Base::Global;
  using typename Base::GlobalMatrix;
  std::string_view typeName() const override { return "PDelta"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<PDeltaTransf>(*this);
  }
  void update(const Global& u) override;
  Global globalForce(const Basic& q) const override;
  GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const override;
  bool hasConstantCompatibility() const override { return true; }
  void addGeometricStiffness(GlobalMatrix& k, const Basic& q) const override;

 private:
  /// ul(y_i) - ul(y_j) (and ul(z_i) - ul(z_j) in 3D): transverse end displacement differences.
  Eigen::Matrix<double, Ndm - 1, 1> delta_ = Eigen::Matrix<double, Ndm - 1, 1>::Zero();
};

extern template class PDeltaTransf<2>;
extern template class PDeltaTransf<3>;

using PDeltaTransf2d = PDeltaTransf<2>;
using PDeltaTransf3d = PDeltaTransf<3>;

}  // namespace dabs::elements
