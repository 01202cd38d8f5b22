// SPDX-License-Identifier: MIT
#pragma once

#include "elements/transform/CrdTransf2d.h"

namespace dabs::elements {

/// Small-displacement planar transformation (`geomTransf Linear tag`):
/// v = B0 u with the undeformed compatibility matrix B0.
class LinearTransf2d final : public CrdTransf2d {
 public:
  using CrdTransf2d::CrdTransf2d;
  std::string_view typeName() const override { return "Linear"; }
  std::unique_ptr<CrdTransf> clone() const override {
    return std::make_unique<LinearTransf2d>(*this);
  }
  bool isLinear() const override { return true; }
  bool hasConstantCompatibility() const override { return true; }
  void update(const Global& u) override { v_ = compat0_ * u; }
};

}  // namespace dabs::elements
