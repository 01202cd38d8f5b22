// SPDX-License-Identifier: MIT
// The three direct solvers behind `system`: a known solution, a singular matrix reported as such,
// and a new factorisation after the numbers change on the same pattern.
#include "tcl/analysis/system/LinearSolver.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>
#include <random>
#include <string>
#include <vector>

namespace dabs::analysis {
namespace {

// The 1D Laplacian-like tridiagonal matrix [2 -1; -1 2 -1; ...] of order n (positive definite),
// plus `skew` in the corner entry (0, n-1) only (non-symmetric when skew != 0).
Eigen::SparseMatrix<double> tridiagonal(int n, double diagonalShift, double skew) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + diagonalShift);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  t.emplace_back(0, n - 1,
                 skew);  // adds an explicit (possibly zero) entry: same pattern either way
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

struct Case {
  SolverKind kind;
  bool nonSymmetric;
};

class LinearSolverTest : public ::testing::TestWithParam<Case> {};

TEST_P(LinearSolverTest, SolvesAKnownSolutionAndRefactorisesNewNumbers) {
  const Case c = GetParam();
  const int n = 6;
  const double skew = c.nonSymmetric ? 0.5 : 0.0;
  Eigen::SparseMatrix<double> A = tridiagonal(n, 0.0, skew);
  Eigen::VectorXd xTrue(n);
  xTrue << 1.0, -2.0, 3.0, 0.5, -1.5, 4.0;
  auto solver = LinearSolver::create(c.kind, c.nonSymmetric);
  solver->analyzePattern(A);
  ASSERT_TRUE(ok(solver->factorize(A)));
  Eigen::VectorXd x;
  ASSERT_TRUE(ok(solver->solve(A * xTrue, x)));
  EXPECT_LT((x - xTrue).norm(), 1e-12 * xTrue.norm());
  // New numbers on the same pattern: the solution is that of the new matrix, not the old one.
  const Eigen::SparseMatrix<double> B = tridiagonal(n, 1.0, skew);
  ASSERT_TRUE(ok(solver->factorize(B)));
  ASSERT_TRUE(ok(solver->solve(B * xTrue, x)));
  EXPECT_LT((x - xTrue).norm(), 1e-12 * xTrue.norm());
  EXPECT_EQ(solver->factorizations(), 2);
}

TEST_P(LinearSolverTest, SingularMatrixIsReportedNotSolved) {
  const Case c = GetParam();
  // Rows 0 and 1 equal: [1 1 0; 1 1 0; 0 0 1] has rank 2.
  std::vector<Eigen::Triplet<double>> t = {
      {0, 0, 1.0}, {0, 1, 1.0}, {1, 0, 1.0}, {1, 1, 1.0}, {2, 2, 1.0}};
  Eigen::SparseMatrix<double> A(3, 3);
  A.setFromTriplets(t.begin(), t.end());
  auto solver = LinearSolver::create(c.kind, c.nonSymmetric);
  solver->analyzePattern(A);
  EXPECT_EQ(solver->factorize(A), Status::Singular);
}

// A random non-symmetric matrix on a fixed pattern (a 2D grid's 5-point stencil plus some far
// couplings, n = 64): each row's diagonal is `diagonalWeight` times a random number in [0.5, 1],
// the off-diagonal entries random in [-1, 1]. With a weight well below KLU's threshold (0.001)
// the off-diagonal entries win
// its pivot search; with a large one the diagonal does.
Eigen::SparseMatrix<double> randomOnPattern(std::mt19937& rng, double diagonalWeight) {
  constexpr int kSide = 8, n = kSide * kSide;
  std::uniform_real_distribution<double> offDiagonal(-1.0, 1.0), diagonal(0.5, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    const int r = i / kSide, c = i % kSide;
    t.emplace_back(i, i, diagonalWeight * diagonal(rng));
    if (c + 1 < kSide) t.emplace_back(i, i + 1, offDiagonal(rng));
    if (c > 0) t.emplace_back(i, i - 1, offDiagonal(rng));
    if (r + 1 < kSide) t.emplace_back(i, i + kSide, offDiagonal(rng));
    if (r > 0) t.emplace_back(i, i - kSide, offDiagonal(rng));
    if (i % 7 == 0) t.emplace_back(i, (i * 13 + 5) % n, offDiagonal(rng));
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());  // a repeated (i, j) sums: the pattern stays the same
  return A;
}

// The sparse LU keeps the previous pivots when KLU's own rule would choose them again: every
// solution of a sequence of matrices on one pattern must then be, bit for bit, the one a new
// solver finds for that matrix alone, whether the pivots were kept or had to be searched again.
TEST(KluSolverTest, KeptPivotsGiveTheFreshFactorisationsBits) {
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  auto kept = LinearSolver::create(SolverKind::SparseLU, true);
  int factorised = 0;
  for (int m = 0; m < 60; ++m) {
    // Runs of diagonally strong matrices (pivots kept), broken by weak ones (pivots change).
    const double weight = (m % 10 == 9) ? 1e-5 : (m % 10 == 0 ? 20.0 : 4.0 + 0.1 * (m % 10));
    const Eigen::SparseMatrix<double> A = randomOnPattern(rng, weight);
    Eigen::VectorXd b(A.rows());
    for (Eigen::Index i = 0; i < b.size(); ++i) b(i) = entry(rng);
    if (m == 0) kept->analyzePattern(A);
    auto fresh = LinearSolver::create(SolverKind::SparseLU, true);
    fresh->analyzePattern(A);
    const Status keptStatus = kept->factorize(A);
    ASSERT_EQ(keptStatus, fresh->factorize(A)) << "matrix " << m;
    if (!ok(keptStatus)) continue;
    ++factorised;
    Eigen::VectorXd xKept, xFresh;
    ASSERT_TRUE(ok(kept->solve(b, xKept)));
    ASSERT_TRUE(ok(fresh->solve(b, xFresh)));
    for (Eigen::Index i = 0; i < b.size(); ++i)
      ASSERT_EQ(xKept(i), xFresh(i)) << "matrix " << m << ", component " << i;
    EXPECT_LT((A * xKept - b).norm(), 1e-10 * b.norm()) << "matrix " << m;
  }
  // Both ways were taken: most matrices kept the pivots, the weak ones and the first did not.
  EXPECT_GE(factorised, 55);
  EXPECT_GE(kept->keptPivots(), 30);
  EXPECT_LE(kept->keptPivots(), factorised - 7);
}

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  static const char* const kNames[] = {"LdlT", "KluLu", "DenseLu"};
  return std::string(kNames[static_cast<int>(info.param.kind)]) +
         (info.param.nonSymmetric ? "NonSymmetric" : "Symmetric");
}

INSTANTIATE_TEST_SUITE_P(Kinds, LinearSolverTest,
                         ::testing::Values(Case{SolverKind::SparseLDLT, false},
                                           Case{SolverKind::SparseLU, false},
                                           Case{SolverKind::SparseLU, true},
                                           Case{SolverKind::DenseLU, false},
                                           Case{SolverKind::DenseLU, true}),
                         caseName);

}  // namespace
}  // namespace dabs::analysis
