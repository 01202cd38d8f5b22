// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string_view>

namespace dabs::elements {

/// Coordinate transformation of a beam-column (geomTransf Linear|PDelta|Corotational), prototype
/// stored by the model builder and cloned into each element. It maps the element's global end
/// displacements to the basic deformations of a simply supported beam, and basic forces back to
/// global end forces and stiffness (OpenSees/OpenSees:SRC/coordTransformation/CrdTransf.h).
/// The fixed-size kinematics interface is declared by CrdTransfNd<Ndm> (CrdTransfNd.h).
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

  /// Sets the undeformed geometry from the end nodes' coordinates (global, 2D padded with z = 0).
  /// Throws InputError for a zero length or (3D) a vecxz parallel to the element axis.
  virtual void initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) = 0;
  /// Undeformed length L0.
  virtual double initialLength() const = 0;
  /// True when the basic deformations are linear in the displacements (Linear).
  virtual bool isLinear() const { return false; }

  /// Trial/commit protocol; only path-dependent transformations (3D corotational) keep state.
  virtual void commitState() {}
  virtual void revertToLastCommit() {}
  virtual void revertToStart() {}

 private:
  int tag_;
};

}  // namespace dabs::elements
