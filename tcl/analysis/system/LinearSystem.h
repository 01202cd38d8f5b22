// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>

#include "tcl/analysis/model/AnalysisModel.h"
#include "tcl/analysis/system/LinearSolver.h"

namespace dabs::analysis {

/// The system A x = B of one iteration: assembles A and B through the AnalysisModel, factorises
/// only when A may have changed, and solves. Modal damping's dense rank-m term is kept out of the
/// sparse matrix and applied with the Sherman-Morrison-Woodbury identity, so A stays sparse.
class LinearSystem {
 public:
  LinearSystem(AnalysisModel& model, SolverKind kind);

  /// Re-creates the solver and analyses the pattern (after AnalysisModel::build).
  void patternChanged();
  /// Assembles the tangent with coefficients c and factorises it. When `reuse` is true and the
  /// same coefficients were factorised last time, nothing is done (linear models, -initial).
  [[nodiscard]] Status formTangent(const AssemblyCoefficients& c, bool reuse = false);
  /// Assembles the residual into B.
  void formResidual(const AssemblyCoefficients& c);
  /// Solves A X = B with the last factorisation.
  [[nodiscard]] Status solve();
  /// Solves A x = b with the last factorisation (e.g. for a reference load).
  [[nodiscard]] Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Forgets the last factorisation, so the next formTangent factorises.
  void invalidate() noexcept { factored_ = false; }

  Eigen::VectorXd B;  ///< residual
  Eigen::VectorXd X;  ///< last solution (integrators may overwrite it with the applied increment)

  long factorizations() const noexcept;
  /// Of them, the sparse LU's that kept the previous pivots (LinearSolver::keptPivots).
  long keptPivots() const noexcept;
  AnalysisModel& model() noexcept { return model_; }

 private:
  /// A count of the solvers (factorisations, kept pivots), summed over the ones created.
  long sumOverSolvers(long (LinearSolver::*count)() const noexcept) const noexcept;
  AnalysisModel& model_;
  SolverKind kind_;
  // A symmetric system is factorised with LDL^T while every active element is symmetric and with
  // LU while one is not (a sliding contact); a general system with LDL^T while the matrix is
  // symmetric and positive definite, with LU otherwise; each solver analyses the pattern once.
  std::unique_ptr<LinearSolver> primary_;
  std::unique_ptr<LinearSolver> general_;
  std::unique_ptr<LinearSolver>
      definite_;  ///< LDL^T for symmetric definite matrices of a general system
  LinearSolver* solver_ = nullptr;
  bool factored_ = false;
  AssemblyCoefficients lastCoefficients_;
  // Woodbury data for modal damping: W = A^-1 U, S = (D^-1 + U^T W)^-1.
  Eigen::MatrixXd modalW_;
  Eigen::MatrixXd modalS_;
  double modalScale_ = 0.0;
};

}  // namespace dabs::analysis
