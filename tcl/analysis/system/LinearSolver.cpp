// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/LinearSolver.h"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

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
  void setThreads(int threads) noexcept override { ldlt_.setThreads(threads); }
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
/// (diagonal preference, threshold tol) of every new matrix, as if it were the first.
///
/// A fresh factorisation searches every column for its pivot and allocates its factors anew. So
/// the previous factors' pivots are tried first: KLU's refactorisation (klu_refactor) redoes
/// the arithmetic with them, and the result is kept only if KLU's own pivot rule, applied to the
/// columns just computed, would have chosen the same pivot in every column, with a margin that
/// no rounding of the stored quotients can cross (samePivotsAsFresh). With the same pivots the
/// two routines perform the same operations in the same order (klu_kernel.c and
/// klu_refactor.c: the column's updates in the stored topological order, one division by the
/// pivot), so the factors, and every solution, are bit for bit those of a fresh factorisation:
/// a function of the matrix alone, whatever matrices came before. Otherwise the matrix is
/// factorised afresh. The check reads KLU's documented Numeric object and the layout of its
/// L columns (each column's row indices, then its values, in units of a double).
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
    if (symbolic_ == nullptr) return;
    const auto n = static_cast<std::size_t>(n_);
    symbolicPosition_.assign(n, 0);
    for (int k = 0; k < n_; ++k) symbolicPosition_[static_cast<std::size_t>(symbolic_->P[k])] = k;
    pivotRow_.assign(n, 0);
    rowPosition_.assign(n, 0);
    diagonalRow_.assign(n, 0);
    rowState_.assign(n, 0);
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
    if (pivotsKept_ && klu_refactor(ap, ai, ax, symbolic_, numeric_, &common_) &&
        common_.status == KLU_OK && samePivotsAsFresh()) {
      ++keptPivots_;
    } else {
      if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
      numeric_ = klu_factor(ap, ai, ax, symbolic_, &common_);
      // A factorisation that stopped at a zero pivot has no complete pivot order to reuse.
      pivotsKept_ = numeric_ != nullptr && common_.status == KLU_OK;
      if (!pivotsKept_) return Status::Singular;
    }
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
  /// Whether a fresh factorisation of the matrix just refactorised would pick the pivots it was
  /// refactorised with. KLU's rule (lpivot in klu_kernel.c), column k of a diagonal block: among
  /// the rows not yet pivotal in the column's pattern, take the "diagonal" row if its magnitude
  /// is at least tol times the largest, else the first largest. The diagonal row starts as row k
  /// of the block and moves as off-diagonal pivots are taken (the bookkeeping of P and Pinv in
  /// klu_kernel.c, followed here with the stored pivots). The stored column of L is the column's
  /// other candidates divided by the pivot, each quotient correctly rounded, so the tests are
  /// made on |L| with a relative margin of 1e-9: kept pivot = diagonal when tol max|L| < 1, an
  /// off-diagonal one when every |L| < 1 (the unique largest) and the diagonal's |L| < tol.
  bool samePivotsAsFresh() {
    constexpr double kMargin = 1.0 - 1e-9;
    const double tol = common_.tol;  // klu_factor keeps it within [0, 1]
    const int* blockStart = symbolic_->R;
    const auto* udiagAll = static_cast<const double*>(numeric_->Udiag);
    // KLU marks a row not yet pivotal by "flipping" its index: -i - 2 (its own inverse).
    auto flip = [](int i) { return -i - 2; };
    for (int block = 0; block < symbolic_->nblocks; ++block) {
      const int k1 = blockStart[block], nk = blockStart[block + 1] - k1;
      if (nk == 1) continue;  // a singleton has no choice
      // Block-local rows: row r is the original row symbolic P[k1 + r].
      for (int k = 0; k < nk; ++k) {
        const int row = symbolicPosition_[static_cast<std::size_t>(numeric_->Pnum[k1 + k])] - k1;
        pivotRow_[static_cast<std::size_t>(k)] = row;
        rowPosition_[static_cast<std::size_t>(row)] = k;
        diagonalRow_[static_cast<std::size_t>(k)] = k;
        rowState_[static_cast<std::size_t>(k)] = flip(k);
      }
      const auto* lu = static_cast<const double*>(numeric_->LUbx[block]);
      const int* lip = numeric_->Lip + k1;
      const int* llen = numeric_->Llen + k1;
      const double* udiag = udiagAll + k1;
      for (int k = 0; k < nk; ++k) {
        const auto uk = static_cast<std::size_t>(k);
        const int diagonal = diagonalRow_[uk], pivot = pivotRow_[uk];
        const double u = udiag[k];
        if (!(u != 0.0) || !std::isfinite(u)) return false;
        // Column k of L: its row indices (block-local pivot positions), then its values.
        const int len = llen[k];
        const auto* indices = reinterpret_cast<const int*>(lu + lip[k]);
        const double* values =
            lu + lip[k] +
            (static_cast<std::size_t>(len) * sizeof(int) + sizeof(double) - 1) / sizeof(double);
        const bool diagonalWaits =
            diagonal != pivot && rowState_[static_cast<std::size_t>(diagonal)] < 0;
        const int diagonalPosition =
            diagonalWaits ? rowPosition_[static_cast<std::size_t>(diagonal)] : -1;
        double largest = 0.0, atDiagonal = -1.0;
        for (int p = 0; p < len; ++p) {
          const double a = std::fabs(values[p]);
          if (!(a <= std::numeric_limits<double>::max())) return false;
          largest = std::max(largest, a);
          if (indices[p] == diagonalPosition) atDiagonal = a;
        }
        if (diagonal == pivot) {
          if (!(tol * largest < kMargin)) return false;
        } else {
          if (!(largest < kMargin)) return false;
          if (atDiagonal >= 0.0 && !(atDiagonal < tol * kMargin)) return false;
        }
        // KLU's bookkeeping after column k: an off-diagonal pivot hands its "diagonal" duty to
        // the row it displaced, if that row is not pivotal yet.
        if (diagonalWaits) {
          const int kbar = flip(rowState_[static_cast<std::size_t>(pivot)]);
          diagonalRow_[static_cast<std::size_t>(kbar)] = diagonal;
          rowState_[static_cast<std::size_t>(diagonal)] = flip(kbar);
        }
        diagonalRow_[uk] = pivot;
        rowState_[static_cast<std::size_t>(pivot)] = k;
      }
    }
    return true;
  }
  const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& A) {
    if (A.isCompressed()) return A;
    copy_ = A;
    copy_.makeCompressed();
    return copy_;
  }
  void release() {
    if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
    if (symbolic_ != nullptr) klu_free_symbolic(&symbolic_, &common_);
    pivotsKept_ = false;
  }

  klu_common common_{};
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
  bool pivotsKept_ = false;  ///< numeric_ holds a complete factorisation whose pivots may serve
  int n_ = 0;
  Eigen::SparseMatrix<double> copy_;
  // Pivot check: the symbolic order's position of each original row; per block, each column's
  // pivot row and each row's pivot position; KLU's diagonal row of each column and its Pinv.
  std::vector<int> symbolicPosition_, pivotRow_, rowPosition_, diagonalRow_, rowState_;
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
