// SPDX-License-Identifier: MIT
// The three direct solvers behind `system`: a known solution, a singular matrix reported as such,
// and a new factorisation after the numbers change on the same pattern.
#include "tcl/analysis/system/LinearSolver.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCore>
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
