// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransf2d.h"

namespace dabs::elements {

/// Linear transformation plus the P-Delta (leaning column) effect of the axial force on the chord
/// rotation (`geomTransf PDelta tag`), as OpenSees/OpenSees:SRC/coordTransformation/
/// PDeltaCrdTransf2d.cpp: local end shears get +-N (ul1 - ul4)/L and the tangent gets the
/// geometric matrix N/L [1 -1; -1 1] on the transverse dofs. Like OpenSees, the tangent omits the
/// term from d(N)/du times the chord rotation, so it stays symmetric; it is exact when the
/// transverse end displacements are equal.
class PDeltaTransf2d final : public CrdTransf2d {
 public:
  using CrdTransf2d::CrdTransf2d;
  std::string_view typeName() const override { return "PDelta"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<PDeltaTransf2d>(*this);
  }
  void update(const Global& u) override;
  Global globalForce(const Basic& q) const override;
  GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const override;
  bool hasConstantCompatibility() const override { return true; }
  void addGeometricStiffness(GlobalMatrix& k, const Basic& q) const override;

 private:
  double delta_ = 0.0;  ///< ul1 - ul4: transverse end displacement difference (local y)
};

}  // namespace dabs::elements
