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
};

using LinearTransf2d = LinearTransf<2>;
using LinearTransf3d = LinearTransf<3>;

}  // namespace dabs::elements
