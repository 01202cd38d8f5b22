// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string>

#include "materials/Status.h"

namespace dabs::analysis {

/// Which factorisation a `system` name maps onto. OpenSees' banded, profile and sparse symmetric
/// solvers become a sparse LDL^T; its general solvers a sparse LU; FullGeneral a dense LU.
enum class SolverKind { SparseLDLT, SparseLU, DenseLU };

/// Maps an OpenSees `system` name onto a solver kind; throws InputError for unknown names.
SolverKind solverKindFromName(const std::string& name);

/// Direct solver of A x = b. The sparsity pattern is analysed once per model change
/// (analyzePattern), the numbers factorised only when the matrix changed (factorize).
class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Symbolic analysis of the pattern (ordering, elimination tree).
  virtual void analyzePattern(const Eigen::SparseMatrix<double>& A) = 0;
  /// Numeric factorisation; Status::Singular on a zero (or negligible) pivot.
  [[nodiscard]] virtual Status factorize(const Eigen::SparseMatrix<double>& A) = 0;
  /// Solves with the last factorisation; Status::NonFinite when the result is not finite.
  [[nodiscard]] virtual Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  /// Threads the factorisation and the solve may use (a sparse LDL^T of a split order; the
  /// others use one). Results do not depend on it.
  virtual void setThreads(int /*threads*/) noexcept {}
  /// Number of numeric factorisations so far (for benchmarks).
  long factorizations() const noexcept { return factorizations_; }
  /// Of those, the ones that kept the previous pivots (the sparse LU only; see KluSolver).
  long keptPivots() const noexcept { return keptPivots_; }

  /// Creates a solver; `nonSymmetric` forces an LU even when an LDL^T was asked for.
  static std::unique_ptr<LinearSolver> create(SolverKind kind, bool nonSymmetric);
  /// A sparse LDL^T whose factorize() reports Singular unless the matrix is positive definite.
  static std::unique_ptr<LinearSolver> createDefiniteLdlt();

 protected:
  long factorizations_ = 0;
  long keptPivots_ = 0;
};

}  // namespace dabs::analysis
