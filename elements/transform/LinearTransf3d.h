// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransf3d.h"

namespace dabs::elements {

/// Small-displacement spatial transformation (`geomTransf Linear tag vx vy vz`): v = B0 u.
class LinearTransf3d final : public CrdTransf3d {
 public:
  using CrdTransf3d::CrdTransf3d;
  std::string_view typeName() const override { return "Linear"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<LinearTransf3d>(*this);
  }
  bool isLinear() const override { return true; }
  bool hasConstantCompatibility() const override { return true; }
  void update(const Global& u) override { v_ = compat0_ * u; }
};

}  // namespace dabs::elements
