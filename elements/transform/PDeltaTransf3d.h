// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransf3d.h"

namespace dabs::elements {

/// Linear transformation plus the P-Delta effect in both transverse planes (`geomTransf PDelta
/// tag vx vy vz`), as OpenSees/OpenSees:SRC/coordTransformation/PDeltaCrdTransf3d.cpp: local end
/// shears get +-N (ul1 - ul7)/L and +-N (ul2 - ul8)/L, and the tangent the geometric matrices
/// N/L [1 -1; -1 1] on the local y and z translations. Like OpenSees, the tangent omits d(N)/du
/// times the chord rotations (symmetric; exact when the chord does not rotate).
class PDeltaTransf3d final : public CrdTransf3d {
 public:
  using CrdTransf3d::CrdTransf3d;
  std::string_view typeName() const override { return "PDelta"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<PDeltaTransf3d>(*this);
  }
  void update(const Global& u) override;
  Global globalForce(const Basic& q) const override;
  GlobalMatrix globalStiffness(const BasicMatrix& kb, const Basic& q) const override;
  bool hasConstantCompatibility() const override { return true; }
  void addGeometricStiffness(GlobalMatrix& k, const Basic& q) const override;

 private:
  double deltaY_ = 0.0;  ///< ul1 - ul7 (local y)
  double deltaZ_ = 0.0;  ///< ul2 - ul8 (local z)
};

}  // namespace dabs::elements
