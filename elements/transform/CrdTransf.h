// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string_view>

namespace dabs::elements {

/// Coordinate transformation of a beam-column (geomTransf Linear|PDelta|Corotational), prototype
/// stored by the model builder and cloned into each element. The geometry and kinematics interface
/// is declared by the concrete 2D/3D transformation classes in this folder.
class CrdTransf {
 public:
  explicit CrdTransf(int tag) noexcept : tag_(tag) {}
  virtual ~CrdTransf() = default;
  CrdTransf(const CrdTransf&) = default;
  CrdTransf& operator=(const CrdTransf&) = delete;

  /// User tag given in the `geomTransf` command.
  int tag() const noexcept { return tag_; }
  /// "Linear", "PDelta" or "Corotational".
  virtual std::string_view typeName() const = 0;
  /// 2 or 3: the model dimension the transformation was defined for.
  virtual int dimension() const = 0;
  [[nodiscard]] virtual std::unique_ptr<CrdTransf> clone() const = 0;

 private:
  int tag_;
};

}  // namespace dabs::elements
