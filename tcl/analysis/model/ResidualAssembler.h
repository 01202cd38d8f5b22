// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <span>
#include <utility>
#include <vector>

#include "tcl/analysis/model/ConstraintHandler.h"
#include "tcl/analysis/model/Scatter.h"
#include "tcl/analysis/model/TangentAssembler.h"

namespace dabs::analysis {

/// What the residual reads of the model besides its own matrices.
struct ResidualInputs {
  const Eigen::VectorXd& P;                              ///< external load (equation space)
  std::span<const ElementScatter> elements;              ///< the awake elements
  std::span<const NodeScatter> nodes;                    ///< every node
  std::span<const std::pair<domain::Node*, int>> eqDof;  ///< node and dof of each equation
  std::span<const PenaltyRow> penalties;
  std::span<const SupportSlot> slots;
  bool imposedMotion = false;  ///< some support moves with an imposed velocity
};

/// Forms the residual B = P - F_int (- inertia - damping when dynamic). The inertia and damping
/// forces come from constant global matrices M a + C v, assembled once per pattern (masses,
/// alphaM and betaK0 terms, the betaK/betaKc terms of linear elements), unless a support moves
/// with an imposed velocity, whose damping and inertia coupling only the element-level forces
/// carry; an element that may turn inactive with mass or damping always forms its own. Modal
/// damping (modalDamping) is added to either. The elements whose force is their initial
/// stiffness times their displacements (ElementScatter::deferred) give theirs as one product
/// with their stiffness assembled here once.
class ResidualAssembler {
 public:
  /// The constant dynamic matrices and the deferred elements' stiffness on `pattern` (every
  /// element's ownDynamics is set here).
  void build(std::span<ElementScatter> elements, std::span<const NodeScatter> nodes,
             const Eigen::SparseMatrix<double>& pattern);
  /// Residual into B.
  void form(const AssemblyCoefficients& c, const ResidualInputs& in, Eigen::VectorXd& B) const;
  /// The deferred elements' force K_d u at the nodes' trial displacements, formed ahead for
  /// form(), which takes it while the displacements are the same bit for bit (else forms it
  /// again): the element pass calls it on whichever of its threads is free first, so on two
  /// threads the product is not left to the serial part of the iteration.
  void formDeferredForce(std::span<const std::pair<domain::Node*, int>> eqDof) const;

  /// Modal damping: C_modal = sum_i 2 zeta_i omega_i (M phi_i)(M phi_i)^T.
  void setModalDamping(const Eigen::MatrixXd& Mphi, const Eigen::VectorXd& coefficients);
  bool hasModalDamping() const noexcept { return modalCoefficients_.size() > 0; }
  const Eigen::MatrixXd& modalBasis() const noexcept { return modalMphi_; }
  const Eigen::VectorXd& modalCoefficients() const noexcept { return modalCoefficients_; }

 private:
  Eigen::SparseMatrix<double> massGlobal_, dampingGlobal_;
  /// Sum of the deferred elements' K0: symmetric, so its rows are its columns; row by row, each
  /// entry of the product is one sum in a fixed order.
  Eigen::SparseMatrix<double, Eigen::RowMajor> deferredStiffness_;
  bool anyDeferred_ = false;
  /// The displacements the last deferred force was formed at (NaN before the first).
  mutable Eigen::VectorXd deferredAt_, deferredForce_;
  std::vector<char> rayleighLeft_;  // per element: Rayleigh stiffness terms left to the element
  mutable Eigen::VectorXd eqDisp_, eqVel_, eqAcc_;
  Eigen::MatrixXd modalMphi_;
  Eigen::VectorXd modalCoefficients_;
};

}  // namespace dabs::analysis
