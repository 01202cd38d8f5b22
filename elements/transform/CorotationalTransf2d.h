// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/transform/CrdTransf2d.h"

namespace dabs::elements {

/// The corotational transformation of an Ndm-dimensional model: one specialisation per dimension.
template <int Ndm>
class CorotationalTransf;

/// Exact planar corotational transformation (the 2D specialisation; the 3D one differs as a whole)
/// (`geomTransf Corotational tag`) for large displacements and rotations, small strains (Crisfield
/// 1991, Non-linear Finite Element Analysis of Solids and Structures vol. 1, sec. 7.4; the
/// kinematics of OpenSees/OpenSees: SRC/coordTransformation/CorotCrdTransf2d.cpp). With the
/// deformed chord length Ln and chord rotation alpha: v0 = Ln - L0, v1 = rz_i - alpha, v2 = rz_j -
/// alpha. The tangent is B^T kb B + N z z^T/Ln + (M_i + M_j)(r z^T + z r^T)/Ln^2 (Crisfield
/// eq. 7.63), r and z the chord's unit axial and normal vectors spread over the translational dofs.
template <>
class CorotationalTransf<2> final : public CrdTransf2d {
 public:
  using CrdTransf2d::CrdTransf2d;
  std::string_view typeName() const override { return "Corotational"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<CorotationalTransf>(*this);
  }
  void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) override;
  void update(const Global& u) override;
  GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const override;

 private:
  double lengthN_ = 0.0;       ///< deformed chord length
  Global r_ = Global::Zero();  ///< d(Ln)/du
  Global z_ = Global::Zero();  ///< Ln d(chord angle)/du
};

using CorotationalTransf2d = CorotationalTransf<2>;

}  // namespace dabs::elements
