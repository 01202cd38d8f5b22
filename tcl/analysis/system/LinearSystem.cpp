// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/LinearSystem.h"

#include <Eigen/LU>

namespace dabs::analysis {

LinearSystem::LinearSystem(AnalysisModel& model, SolverKind kind) : model_(model), kind_(kind) {}

void LinearSystem::patternChanged() {
  primary_ = LinearSolver::create(kind_, false);
  if (model_.numEquations() > 0) primary_->analyzePattern(model_.pattern());
  general_.reset();
  definite_.reset();
  solver_ = primary_.get();
  factored_ = false;
  B = X = Eigen::VectorXd::Zero(model_.numEquations());
}

long LinearSystem::sumOverSolvers(long (LinearSolver::*count)() const noexcept) const noexcept {
  long sum = 0;
  for (const LinearSolver* solver : {primary_.get(), general_.get(), definite_.get()})
    if (solver != nullptr) sum += (solver->*count)();
  return sum;
}

long LinearSystem::factorizations() const noexcept {
  return sumOverSolvers(&LinearSolver::factorizations);
}

long LinearSystem::keptPivots() const noexcept { return sumOverSolvers(&LinearSolver::keptPivots); }

Status LinearSystem::formTangent(const AssemblyCoefficients& c, bool reuse) {
  if (reuse && factored_ && c.sameMatrix(lastCoefficients_)) return Status::Ok;
  if (model_.numEquations() == 0) {  // everything is prescribed: nothing to factorise
    factored_ = true;
    lastCoefficients_ = c;
    modalScale_ = 0.0;
    return Status::Ok;
  }
  const auto& A = model_.formTangent(c);
  factored_ = false;
  // The model's threads, for a factorisation that can share its work (results do not change).
  for (LinearSolver* solver : {primary_.get(), general_.get(), definite_.get()})
    if (solver != nullptr) solver->setThreads(model_.threads());
  solver_ = primary_.get();
  const bool symmetric = !model_.nonSymmetricNow();
  if (kind_ == SolverKind::SparseLDLT && !symmetric) {
    if (!general_) {
      general_ = LinearSolver::create(SolverKind::SparseLU, true);
      general_->setThreads(model_.threads());
      general_->analyzePattern(model_.pattern());
    }
    solver_ = general_.get();
  }
  // A general solver was named (UmfPack, BandGeneral, ...) but the matrix is symmetric: a sparse
  // LDL^T costs a fraction of an LU and gives the same solution to round-off while the matrix is
  // positive definite, the usual case for K + c1 C + c2 M. When it is not (softening, buckling),
  // the pivoting LU the script asked for takes over for that matrix.
  bool factorized = false;
  if (kind_ == SolverKind::SparseLU && symmetric) {
    if (!definite_) {
      definite_ = LinearSolver::createDefiniteLdlt();
      definite_->setThreads(model_.threads());
      definite_->analyzePattern(model_.pattern());
    }
    if (ok(definite_->factorize(A))) {
      solver_ = definite_.get();
      factorized = true;
    }
  }
  const Status s = factorized ? Status::Ok : solver_->factorize(A);
  if (!ok(s)) return s;
  lastCoefficients_ = c;
  factored_ = true;
  // Modal damping adds cC * U diag(d) U^T to A (OpenSees
  // IncrementalIntegrator::addModalDampingMatrix).
  modalScale_ = model_.hasModalDamping() ? c.cC : 0.0;
  if (modalScale_ != 0.0) {
    const Eigen::MatrixXd& U = model_.modalBasis();
    const Eigen::VectorXd d = modalScale_ * model_.modalCoefficients();
    modalW_.resize(U.rows(), U.cols());
    Eigen::VectorXd col;
    for (Eigen::Index j = 0; j < U.cols(); ++j) {
      const Status sj = solver_->solve(U.col(j), col);
      if (!ok(sj)) return sj;
      modalW_.col(j) = col;
    }
    Eigen::MatrixXd core = U.transpose() * modalW_;
    for (Eigen::Index j = 0; j < d.size(); ++j) {
      if (d(j) != 0.0)
        core(j, j) += 1.0 / d(j);
      else
        core(j, j) += 1e300;  // a mode without damping drops out
    }
    modalS_ = core.inverse();
  }
  return Status::Ok;
}

void LinearSystem::formResidual(const AssemblyCoefficients& c) { model_.formResidual(c, B); }

Status LinearSystem::solve() { return solve(B, X); }

Status LinearSystem::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  if (!factored_) return Status::Singular;
  if (b.size() == 0) {
    x.resize(0);
    return Status::Ok;
  }
  Status s = solver_->solve(b, x);
  if (!ok(s)) return s;
  if (modalScale_ != 0.0) {
    // (A + U D U^T)^-1 b = y - W S U^T y with y = A^-1 b.
    const Eigen::VectorXd t = modalS_ * (model_.modalBasis().transpose() * x);
    x.noalias() -= modalW_ * t;
    if (!x.allFinite()) return Status::NonFinite;
  }
  return Status::Ok;
}

}  // namespace dabs::analysis
