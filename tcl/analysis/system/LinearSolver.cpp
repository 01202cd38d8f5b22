// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/LinearSolver.h"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <map>

#include <klu.h>

#include "materials/InputError.h"
#include "tcl/analysis/system/SparseLdlt.h"

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

/// Sparse LU by KLU (SuiteSparse; Davis & Palamadai Natarajan 2010, ACM TOMS 37(3) 36): the
/// fill-reducing ordering once per pattern, then a numeric factorisation with partial pivoting
/// for every new matrix. KLU's refactorisation (the previous pivot order, no search) would be
/// cheaper still, but it makes the round-off depend on which matrix chose the pivots, so the same
/// steps taken in one `analyze` call or in several would give results that differ in the last
/// digits, and impacts amplify such differences; a fresh pivot search keeps every solution a
/// function of its matrix alone.
class KluSolver final : public LinearSolver {
 public:
  KluSolver() {
    klu_defaults(&common_);
    common_.halt_if_singular = 1;
  }
  ~KluSolver() override { release(); }
  KluSolver(const KluSolver&) = delete;
  KluSolver& operator=(const KluSolver&) = delete;

  void analyzePattern(const Eigen::SparseMatrix<double>& A) override {
    release();
    n_ = static_cast<int>(A.rows());
    if (n_ == 0) return;
    const Eigen::SparseMatrix<double>& c = compressed(A);
    symbolic_ = klu_analyze(n_, const_cast<int*>(c.outerIndexPtr()),
                            const_cast<int*>(c.innerIndexPtr()), &common_);
  }
  Status factorize(const Eigen::SparseMatrix<double>& A) override {
    ++factorizations_;
    if (symbolic_ == nullptr || A.rows() != n_) analyzePattern(A);
    if (n_ == 0) return Status::Ok;
    if (symbolic_ == nullptr) return Status::Singular;
    const Eigen::SparseMatrix<double>& c = compressed(A);
    int* ap = const_cast<int*>(c.outerIndexPtr());
    int* ai = const_cast<int*>(c.innerIndexPtr());
    double* ax = const_cast<double*>(c.valuePtr());
    if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
    numeric_ = klu_factor(ap, ai, ax, symbolic_, &common_);
    if (numeric_ == nullptr || common_.status != KLU_OK) return Status::Singular;
    // rcond here is min |U_ii| / max |U_ii|: the same relative pivot test as the LDL^T's.
    if (!klu_rcond(symbolic_, numeric_, &common_) || !(common_.rcond > kRelativePivotTolerance))
      return Status::Singular;
    return Status::Ok;
  }
  Status solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    x = b;
    if (n_ == 0) return Status::Ok;
    if (numeric_ == nullptr || !klu_solve(symbolic_, numeric_, n_, 1, x.data(), &common_))
      return Status::NonFinite;
    return x.allFinite() ? Status::Ok : Status::NonFinite;
  }

 private:
  const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& A) {
    if (A.isCompressed()) return A;
    copy_ = A;
    copy_.makeCompressed();
    return copy_;
  }
  void release() {
    if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
    if (symbolic_ != nullptr) klu_free_symbolic(&symbolic_, &common_);
  }

  klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  int n_ = 0;
  Eigen::SparseMatrix<double> copy_;
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
      {"BandSPD", SolverKind::SparseLDLT},     {"ProfileSPD", SolverKind::SparseLDLT},
      {"SparseSYM", SolverKind::SparseLDLT},   {"SparseSPD", SolverKind::SparseLDLT},
      {"BandGeneral", SolverKind::SparseLU},   {"BandGen", SolverKind::SparseLU},
      {"SparseGeneral", SolverKind::SparseLU}, {"SparseGEN", SolverKind::SparseLU},
      {"UmfPack", SolverKind::SparseLU},       {"Umfpack", SolverKind::SparseLU},
      {"Mumps", SolverKind::SparseLU},         {"SuperLU", SolverKind::SparseLU},
      {"FullGeneral", SolverKind::DenseLU},    {"FullGen", SolverKind::DenseLU},
  };
  auto it = kNames.find(name);
  if (it == kNames.end())
    throw InputError("type", "\"" + name +
                                 "\" is not a known system (BandGeneral, BandSPD, ProfileSPD, "
                                 "SparseGeneral, UmfPack, FullGeneral, SparseSYM, Mumps)");
  return it->second;
}

std::unique_ptr<LinearSolver> LinearSolver::create(SolverKind kind, bool nonSymmetric) {
  if (kind == SolverKind::DenseLU) return std::make_unique<DenseLuSolver>();
  if (kind == SolverKind::SparseLU || nonSymmetric) return std::make_unique<KluSolver>();
  return std::make_unique<SparseLdltSolver>(false);
}

std::unique_ptr<LinearSolver> LinearSolver::createDefiniteLdlt() {
  return std::make_unique<SparseLdltSolver>(true);
}

}  // namespace dabs::analysis
