// SPDX-License-Identifier: MIT
#include "tcl/analysis/LinearSolver.h"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <map>

#include "materials/InputError.h"
#include "tcl/analysis/SparseLdlt.h"

namespace dabs::analysis {

namespace {

// A pivot smaller than this fraction of the largest one is treated as zero: the stiffness is
// singular to working precision (a mechanism, or a free dof without stiffness).
constexpr double kRelativePivotTolerance = 1e-14;

class SparseLdltSolver final : public LinearSolver {
 public:
  /// `definiteOnly`: report Singular unless every pivot is positive, so a caller can fall back to
  /// a pivoting LU (LDL^T without pivoting is backward stable for definite matrices only).
  explicit SparseLdltSolver(bool definiteOnly) : definiteOnly_(definiteOnly) {}
  void analyzePattern(const Eigen::SparseMatrix<double>& A) override { ldlt_.analyze(A); }
  Status factorize(const Eigen::SparseMatrix<double>& A) override {
    ++factorizations_;
    if (!ok(ldlt_.factorize(A))) return Status::Singular;
    const auto& d = ldlt_.pivots();
    if (d.size() == 0) return Status::Ok;
    if (!d.allFinite()) return Status::Singular;
    const double largest = d.cwiseAbs().maxCoeff();
    if (d.cwiseAbs().minCoeff() <= kRelativePivotTolerance * largest) return Status::Singular;
    if (definiteOnly_ && d.minCoeff() <= 0.0) return Status::Singular;
    return Status::Ok;
  }
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    ldlt_.solve(b, x);
    return x.allFinite() ? Status::Ok : Status::NonFinite;
  }

 private:
  SparseLdlt ldlt_;
  bool definiteOnly_;
};

class SparseLuSolver final : public LinearSolver {
 public:
  void analyzePattern(const Eigen::SparseMatrix<double>& A) override {
    lu_.analyzePattern(A);
    analyzed_ = true;
  }
  Status factorize(const Eigen::SparseMatrix<double>& A) override {
    ++factorizations_;
    if (!analyzed_) analyzePattern(A);
    lu_.factorize(A);
    // SparseLU reports exactly zero pivots; a negligible pivot shows up as a non-finite solve.
    return lu_.info() == Eigen::Success ? Status::Ok : Status::Singular;
  }
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = lu_.solve(b);
    return x.allFinite() ? Status::Ok : Status::NonFinite;
  }

 private:
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
  bool analyzed_ = false;
};

class DenseLuSolver final : public LinearSolver {
 public:
  void analyzePattern(const Eigen::SparseMatrix<double>& /*A*/) override {}
  Status factorize(const Eigen::SparseMatrix<double>& A) override {
    ++factorizations_;
    dense_ = Eigen::MatrixXd(A);
    lu_.compute(dense_);
    if (A.rows() > 0 && !(lu_.rcond() > kRelativePivotTolerance)) return Status::Singular;
    return Status::Ok;
  }
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = lu_.solve(b);
    return x.allFinite() ? Status::Ok : Status::NonFinite;
  }

 private:
  Eigen::MatrixXd dense_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
};

}  // namespace

SolverKind solverKindFromName(const std::string& name) {
  static const std::map<std::string, SolverKind> kNames = {
      {"BandSPD", SolverKind::SparseLDLT},      {"ProfileSPD", SolverKind::SparseLDLT},
      {"SparseSYM", SolverKind::SparseLDLT},    {"SparseSPD", SolverKind::SparseLDLT},
      {"BandGeneral", SolverKind::SparseLU},    {"BandGen", SolverKind::SparseLU},
      {"SparseGeneral", SolverKind::SparseLU},  {"SparseGEN", SolverKind::SparseLU},
      {"UmfPack", SolverKind::SparseLU},        {"Umfpack", SolverKind::SparseLU},
      {"Mumps", SolverKind::SparseLU},          {"SuperLU", SolverKind::SparseLU},
      {"FullGeneral", SolverKind::DenseLU},     {"FullGen", SolverKind::DenseLU},
  };
  auto it = kNames.find(name);
  if (it == kNames.end())
    throw InputError("type", "\"" + name + "\" is not a known system (BandGeneral, BandSPD, ProfileSPD, "
                             "SparseGeneral, UmfPack, FullGeneral, SparseSYM, Mumps)");
  return it->second;
}

std::unique_ptr<LinearSolver> LinearSolver::create(SolverKind kind, bool nonSymmetric) {
  if (kind == SolverKind::DenseLU) return std::make_unique<DenseLuSolver>();
  if (kind == SolverKind::SparseLU || nonSymmetric) return std::make_unique<SparseLuSolver>();
  return std::make_unique<SparseLdltSolver>(false);
}

std::unique_ptr<LinearSolver> LinearSolver::createDefiniteLdlt() {
  return std::make_unique<SparseLdltSolver>(true);
}

}  // namespace dabs::analysis
