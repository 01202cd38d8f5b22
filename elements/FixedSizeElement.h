// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <type_traits>

#include "elements/Element.h"

namespace dabs::elements {

/// Matrices a FixedSizeElement keeps as members (bits of its `Stored` parameter). One it does not
/// keep reads as zero, unless the element keeps its own and overrides the getter (a contact pair
/// keeps its tangent after its state, so that the state sits next to the start of the object).
enum StoredMatrix : unsigned {
  kStoreTangent = 1u,    ///< k_: tangentStiff()
  kStoreInitial = 2u,    ///< k0_: initialStiff()
  kStoreCommitted = 4u,  ///< kc_: for elements whose committedStiff() returns it
  kStoreDamping = 8u,    ///< c_: dampingTangent()
  kStoreMass = 16u,      ///< m_: mass()
  kStoreAll = 31u,
};

/// Base for elements whose size is known at compile time: owns the force vector and the
/// stiffness, damping and mass matrices as fixed-size Eigen members and exposes them through
/// Eigen::Ref without copying (style.md section 3; the idea of xara's FiniteElement<nen,ndm,ndf>).
/// An element that needs fewer matrices says so with `Stored` (a 15 x 15 matrix is 1.8 kB; an
/// element with no mass or committed tangent need not carry them).
template <int NumNodes, int DofPerNode, unsigned Stored = kStoreAll>
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
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const override {
    return keptOrZero<kStoreTangent>(k_);
  }
  Eigen::Ref<const Eigen::MatrixXd> initialStiff() const override {
    return keptOrZero<kStoreInitial>(k0_);
  }
  Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const override {
    return keptOrZero<kStoreDamping>(c_);
  }
  Eigen::Ref<const Eigen::MatrixXd> mass() const override { return keptOrZero<kStoreMass>(m_); }

 protected:
  struct NoMatrix {};
  template <unsigned Bit>
  using MatrixIf = std::conditional_t<(Stored & Bit) != 0, Matrix, NoMatrix>;
  template <unsigned Bit>
  static MatrixIf<Bit> zeroIf() {
    if constexpr ((Stored & Bit) != 0)
      return Matrix::Zero();
    else
      return NoMatrix{};
  }
  /// `m` when the element keeps the matrix of `Bit`, else the shared zero matrix.
  template <unsigned Bit, class Kept>
  static Eigen::Ref<const Eigen::MatrixXd> keptOrZero(const Kept& m) {
    if constexpr ((Stored & Bit) != 0)
      return m;
    else
      return zero();
  }
  /// The zero matrix the getters of matrices not kept return (constant, never written).
  static const Matrix& zero() {
    static const Matrix kZero = Matrix::Zero();
    return kZero;
  }

  std::vector<int> nodes_;
  Vector f_ = Vector::Zero();  ///< resisting force at the last update (global)
  [[no_unique_address]] MatrixIf<kStoreTangent> k_ =
      zeroIf<kStoreTangent>();  ///< tangent stiffness at the last update (global)
  [[no_unique_address]] MatrixIf<kStoreInitial> k0_ =
      zeroIf<kStoreInitial>();  ///< initial stiffness (global)
  /// Tangent at the last commit (global), for elements that override committedStiff() with it.
  [[no_unique_address]] MatrixIf<kStoreCommitted> kc_ = zeroIf<kStoreCommitted>();
  [[no_unique_address]] MatrixIf<kStoreDamping> c_ =
      zeroIf<kStoreDamping>();  ///< element's own viscous tangent (global)
  [[no_unique_address]] MatrixIf<kStoreMass> m_ = zeroIf<kStoreMass>();  ///< mass matrix (global)
};

}  // namespace dabs::elements
