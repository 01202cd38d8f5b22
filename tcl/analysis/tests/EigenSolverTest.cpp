// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/EigenSolver.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace dabs::analysis {
namespace {

// Fixed-free chain of n equal springs k and masses m: omega_j^2 = 4 k/m sin^2((2j-1) pi /
// (2(2n+1))) (e.g. Meirovitch, Fundamentals of Vibrations, sec. 8.x, lumped chain).
void chain(int n, double k, double m, Eigen::SparseMatrix<double>& K,
           Eigen::SparseMatrix<double>& M, int massless = 0) {
  const int size = n + massless;
  std::vector<Eigen::Triplet<double>> kt, mt;
  for (int i = 0; i < n; ++i) {
    kt.emplace_back(i, i, i + 1 < n ? 2 * k : k);
    if (i + 1 < n) {
      kt.emplace_back(i, i + 1, -k);
      kt.emplace_back(i + 1, i, -k);
    }
    mt.emplace_back(i, i, m);
  }
  // Massless dofs on stiff independent springs: infinite eigenvalues that must not appear.
  for (int i = n; i < size; ++i) kt.emplace_back(i, i, 10 * k);
  K.resize(size, size);
  M.resize(size, size);
  K.setFromTriplets(kt.begin(), kt.end());
  M.setFromTriplets(mt.begin(), mt.end());
}

double exact(int j, int n, double k, double m) {
  const double s = std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * n + 1)));
  return 4.0 * k / m * s * s;
}

TEST(EigenSolverTest, DenseAndSubspaceMatchTheChainClosedForm) {
  Eigen::SparseMatrix<double> K, M;
  const int n = 40;
  chain(n, 3.0, 2.0, K, M, 5);
  const EigenResult dense = solveEigenDense(K, M, 6);
  const EigenResult subspace = solveEigenSubspace(K, M, 6);
  ASSERT_TRUE(ok(dense.status));
  ASSERT_TRUE(ok(subspace.status));
  for (int j = 1; j <= 6; ++j) {
    EXPECT_NEAR(dense.values(j - 1), exact(j, n, 3.0, 2.0), 1e-10 * exact(j, n, 3.0, 2.0));
    EXPECT_NEAR(subspace.values(j - 1), exact(j, n, 3.0, 2.0), 1e-9 * exact(j, n, 3.0, 2.0));
  }
  // Mass-orthonormal vectors.
  const Eigen::MatrixXd orth = subspace.vectors.transpose() * (M * subspace.vectors);
  EXPECT_LT((orth - Eigen::MatrixXd::Identity(6, 6)).norm(), 1e-8);
}

// `eigen -findLargest`: the highest finite eigenvalues, ascending, with massless dofs (infinite
// eigenvalues) left out.
TEST(EigenSolverTest, LargestFiniteEigenvaluesInAscendingOrder) {
  Eigen::SparseMatrix<double> K, M;
  const int n = 12;
  chain(n, 3.0, 2.0, K, M, 3);
  const EigenResult r = solveEigenDense(K, M, 3, true);
  ASSERT_TRUE(ok(r.status));
  for (int i = 0; i < 3; ++i) {
    const double expected = exact(n - 2 + i, n, 3.0, 2.0);
    EXPECT_NEAR(r.values(i), expected, 1e-10 * expected);
  }
  const Eigen::VectorXd residual = K * r.vectors.col(2) - r.values(2) * (M * r.vectors.col(2));
  EXPECT_LT(residual.norm(), 1e-8 * r.values(2));
}

TEST(EigenSolverTest, AskingForMoreModesThanMassesFails) {
  Eigen::SparseMatrix<double> K, M;
  chain(3, 1.0, 1.0, K, M, 4);
  EXPECT_FALSE(ok(solveEigenDense(K, M, 4).status));
  EXPECT_FALSE(ok(solveEigenSubspace(K, M, 4).status));
}

TEST(EigenSolverTest, SingularStiffnessIsReported) {
  Eigen::SparseMatrix<double> K(2, 2), M(2, 2);
  K.insert(0, 0) = 1.0;  // second dof has no stiffness
  M.insert(0, 0) = 1.0;
  M.insert(1, 1) = 1.0;
  EXPECT_FALSE(ok(solveEigenSubspace(K, M, 1).status));
  EXPECT_FALSE(ok(solveEigenDense(K, M, 1).status));
}

}  // namespace
}  // namespace dabs::analysis
