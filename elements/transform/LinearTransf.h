// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/transform/CrdTransfNd.h"

namespace dabs::elements {

/// Small-displacement transformation (`geomTransf Linear tag` in 2D, `geomTransf Linear tag vx vy
/// vz` in 3D): v = B0 u with the undeformed compatibility matrix B0.
template <int Ndm>
class LinearTransf final : public CrdTransfNd<Ndm> {
 public:
  using Base = CrdTransfNd<Ndm>;
  using Base::Base;
  std::string_view typeName() const override { return "Linear"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<LinearTransf>(*this);
  }
  bool isLinear() const override { return true; }
  bool hasConstantCompatibility() const override { return true; }
  void update(const typename Base::Global& u) override { this->v_ = this->compat0_ * u; }
  // B = B0 at every geometry: read the one matrix that update() reads too.
  typename Base::Global globalForce(const typename Base::Basic& q) const override {
    return this->compat0_.transpose() * q;
  }
  typename Base::GlobalMatrix globalStiffness(const typename Base::BasicMatrix& kb,
                                              const typename Base::Basic& /*q*/) const override {
    return Base::congruence(this->compat0_, kb);
  }
};

using LinearTransf2d = LinearTransf<2>;
using LinearTransf3d = LinearTransf<3>;

}  // namespace dabs::elements
