// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/Element.h"

namespace dabs::elements {

/// Base for elements whose size is known at compile time: owns the force vector and the
/// stiffness, damping and mass matrices as fixed-size Eigen members and exposes them through
/// Eigen::Ref without copying (style.md section 3; the idea of xara's FiniteElement<nen,ndm,ndf>).
template <int NumNodes, int DofPerNode>
class FixedSizeElement : public Element {
 public:
  static constexpr int kNumDof = NumNodes * DofPerNode;
  using Vector = Eigen::Matrix<double, kNumDof, 1>;
  using Matrix = Eigen::Matrix<double, kNumDof, kNumDof>;

  FixedSizeElement(int tag, std::vector<int> nodes) : Element(tag), nodes_(std::move(nodes)) {}

  const std::vector<int>& nodeTags() const final { return nodes_; }
  int numDof() const final { return kNumDof; }
  int dofPerNode() const final { return DofPerNode; }

  Eigen::Ref<const Eigen::VectorXd> resistingForce() const override { return f_; }
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const override { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> initialStiff() const override { return k0_; }
  Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const override { return c_; }
  Eigen::Ref<const Eigen::MatrixXd> mass() const override { return m_; }

 protected:
  std::vector<int> nodes_;
  Vector f_ = Vector::Zero();   ///< resisting force at the last update (global)
  Matrix k_ = Matrix::Zero();   ///< tangent stiffness at the last update (global)
  Matrix k0_ = Matrix::Zero();  ///< initial stiffness (global)
  /// Tangent at the last commit (global), for elements that override committedStiff() with it.
  Matrix kc_ = Matrix::Zero();
  Matrix c_ = Matrix::Zero();  ///< element's own viscous tangent (global)
  Matrix m_ = Matrix::Zero();  ///< mass matrix (global)
};

}  // namespace dabs::elements
