// SPDX-License-Identifier: MIT
// Sparse LDL^T against a dense factorisation of the same matrices: definite and indefinite
// stiffness-like matrices, refactorisation with new values, singular matrices, and the solvers
// that the `system` names map onto.
#include "tcl/analysis/system/SparseLdlt.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cstring>
#include <random>
#include <utility>

#include "tcl/analysis/system/LinearSolver.h"

namespace dabs::analysis {
namespace {

constexpr double kSolveTol = 1e-11;  // relative residual of a well-conditioned solve

/// A stiffness-like matrix: random symmetric 6x6 blocks coupling neighbouring 3-dof nodes of a
/// chain with a few long-range links (so the order matters), plus `shift` on the diagonal.
Eigen::SparseMatrix<double> chain(int nodes, double shift, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 3 * nodes;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  auto couple = [&](int a, int b) {
    Eigen::Matrix<double, 6, 6> r;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) r(i, j) = u(rng);
    const Eigen::Matrix<double, 6, 6> k = r * r.transpose();  // positive semidefinite
    const int idx[6] = {3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2};
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) dense(idx[i], idx[j]) += k(i, j);
  };
  for (int e = 0; e + 1 < nodes; ++e) couple(e, e + 1);
  for (int e = 0; e + 7 < nodes; e += 5) couple(e, e + 7);
  dense.diagonal().array() += shift;
  // Keep every entry of the block pattern, zero or not, as the assembled pattern does.
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (dense(i, j) != 0.0 || i == j) t.emplace_back(i, j, dense(i, j));
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

void addToDiagonal(Eigen::SparseMatrix<double>& A, double s) {
  for (int i = 0; i < A.rows(); ++i) A.coeffRef(i, i) += s;
}

double relativeResidual(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x,
                        const Eigen::VectorXd& b) {
  return (A * x - b).norm() / b.norm();
}

TEST(SparseLdltTest, SolvesDefiniteMatrixLikeDenseCholesky) {
  const Eigen::SparseMatrix<double> A = chain(40, 0.1, 1);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  const Eigen::VectorXd expected = Eigen::MatrixXd(A).llt().solve(b);
  EXPECT_LT((x - expected).norm(), kSolveTol * expected.norm());
  EXPECT_LT(relativeResidual(A, x, b), kSolveTol);
  EXPECT_GT(ldlt.pivots().minCoeff(), 0.0);
}

TEST(SparseLdltTest, RefactorisesNewValuesOnTheSamePattern) {
  Eigen::SparseMatrix<double> A = chain(30, 0.5, 2);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] *= 1.0 + 0.1 * round;
    addToDiagonal(A, 0.2 * round);
    ASSERT_TRUE(ok(ldlt.factorize(A)));
    const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
    Eigen::VectorXd x;
    ldlt.solve(b, x);
    EXPECT_LT(relativeResidual(A, x, b), kSolveTol) << "round " << round;
  }
}

TEST(SparseLdltTest, IndefiniteMatrixGivesNegativePivotsAndTheRightSolution) {
  // A shift below the smallest eigenvalue makes the matrix indefinite but nonsingular.
  Eigen::SparseMatrix<double> A = chain(20, 0.0, 3);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(A)};
  const double shift = 0.5 * (eig.eigenvalues()(0) + eig.eigenvalues()(1));
  addToDiagonal(A, -shift);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  EXPECT_LT(ldlt.pivots().minCoeff(),
            0.0);  // Sylvester: one negative eigenvalue, one negative pivot
  EXPECT_EQ((ldlt.pivots().array() < 0.0).count(), 1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 3.0);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  EXPECT_LT(relativeResidual(A, x, b), 1e-8);
}

TEST(SparseLdltTest, ZeroRowIsSingular) {
  Eigen::SparseMatrix<double> A = chain(10, 1.0, 4);
  for (Eigen::SparseMatrix<double>::InnerIterator it(A, 7); it; ++it) it.valueRef() = 0.0;
  for (int j = 0; j < A.cols(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (it.row() == 7) it.valueRef() = 0.0;
  SparseLdlt ldlt;
  ldlt.analyze(A);
  EXPECT_EQ(ldlt.factorize(A), Status::Singular);
}

TEST(SparseLdltTest, GeneralSystemOfASymmetricMatrixSolvesLikeLu) {
  // `system UmfPack` on a symmetric definite matrix is factorised with LDL^T: same solution.
  const Eigen::SparseMatrix<double> A = chain(25, 0.3, 5);
  auto lu = LinearSolver::create(SolverKind::SparseLU, false);
  auto definite = LinearSolver::createDefiniteLdlt();
  lu->analyzePattern(A);
  definite->analyzePattern(A);
  ASSERT_TRUE(ok(lu->factorize(A)));
  ASSERT_TRUE(ok(definite->factorize(A)));
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -2.0, 1.0);
  Eigen::VectorXd xLu, xLdlt;
  ASSERT_TRUE(ok(lu->solve(b, xLu)));
  ASSERT_TRUE(ok(definite->solve(b, xLdlt)));
  EXPECT_LT((xLu - xLdlt).norm(), kSolveTol * xLu.norm());
}

TEST(SparseLdltTest, DefiniteOnlySolverRefusesIndefiniteMatrix) {
  Eigen::SparseMatrix<double> A = chain(12, 0.0, 6);
  addToDiagonal(A, -1e3);  // far below every eigenvalue: negative definite parts
  auto definite = LinearSolver::createDefiniteLdlt();
  definite->analyzePattern(A);
  EXPECT_EQ(definite->factorize(A), Status::Singular);
}

TEST(SparseLdltTest, DenseMatrixIsOneSupernodeWithTheFullTriangle) {
  // A full n x n matrix: every column of L below the diagonal is full, each column's pattern is
  // the next one's plus that column, so the whole factor is one supernode of n(n-1)/2 entries.
  constexpr int n = 9;
  Eigen::MatrixXd r = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd dense = r * r.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  const Eigen::SparseMatrix<double> A = dense.sparseView(0.0, 0.0);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  EXPECT_EQ(ldlt.supernodes(), 1);
  EXPECT_EQ(ldlt.factorNonZeros(), n * (n - 1) / 2);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 3.0);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  EXPECT_LT(relativeResidual(A, x, b), kSolveTol);
}

TEST(SparseLdltTest, DiagonalMatrixIsOneSupernodePerColumn) {
  // No coupling: L is the identity, every column its own supernode (no parent in the tree).
  constexpr int n = 7;
  Eigen::SparseMatrix<double> A(n, n);
  for (int i = 0; i < n; ++i) A.insert(i, i) = 1.0 + i;
  A.makeCompressed();
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  EXPECT_EQ(ldlt.supernodes(), n);
  EXPECT_EQ(ldlt.factorNonZeros(), 0);
  Eigen::VectorXd x;
  ldlt.solve(Eigen::VectorXd::Ones(n), x);
  for (int i = 0; i < n; ++i) EXPECT_DOUBLE_EQ(x(i), 1.0 / (1.0 + i));
}

TEST(SparseLdltTest, NodeBlocksFormSupernodesOfAtLeastTheNodesDofs) {
  // A chain of 3-dof nodes with full 6 x 6 couplings: a node's 3 dofs have the same pattern, so
  // the factor has at most one supernode per node, and the solve agrees with a dense one.
  const Eigen::SparseMatrix<double> A = chain(50, 0.2, 7);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  EXPECT_LE(ldlt.supernodes(), 50);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 2.0, -1.0);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  const Eigen::VectorXd expected = Eigen::MatrixXd(A).llt().solve(b);
  EXPECT_LT((x - expected).norm(), kSolveTol * expected.norm());
}

/// A random symmetric definite matrix with an irregular scalar pattern (no node blocks): about
/// `perRow` off-diagonal entries a row at random places, diagonally dominant.
Eigen::SparseMatrix<double> scattered(int n, int perRow, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < perRow; ++k) {
      const int j = pick(rng);
      if (j == i) continue;
      const double v = u(rng);
      dense(i, j) += v;
      dense(j, i) += v;
    }
  dense.diagonal() = dense.cwiseAbs().rowwise().sum().array() + 1.0;
  Eigen::SparseMatrix<double> A = dense.sparseView(0.0, 0.0);
  A.makeCompressed();
  return A;
}

TEST(SparseLdltTest, IrregularPatternsSolveLikeDenseCholesky) {
  // Scalar patterns give narrow supernodes, long update lists and rows of a descendant that reach
  // several later supernodes: each is checked against a dense factorisation, refactorised once.
  for (unsigned seed = 11; seed < 17; ++seed) {
    Eigen::SparseMatrix<double> A = scattered(60 + 13 * static_cast<int>(seed % 4), 3, seed);
    SparseLdlt ldlt;
    ldlt.analyze(A);
    for (int round = 0; round < 2; ++round) {
      if (round == 1) addToDiagonal(A, 0.7);
      ASSERT_TRUE(ok(ldlt.factorize(A))) << "seed " << seed;
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.5);
      Eigen::VectorXd x;
      ldlt.solve(b, x);
      const Eigen::VectorXd expected = Eigen::MatrixXd(A).llt().solve(b);
      EXPECT_LT((x - expected).norm(), kSolveTol * expected.norm()) << "seed " << seed;
    }
  }
}

TEST(SparseLdltTest, GridOfSixDofNodesSolvesLikeDenseCholesky) {
  // A 4 x 4 x 4 lattice of 6-dof nodes (a space frame's pattern) coupled to their neighbours:
  // a tree with several children per supernode and a wide dense root block.
  constexpr int side = 4, ndf = 6;
  const int nodes = side * side * side, n = ndf * nodes;
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  auto index = [&](int x, int y, int z) { return (x * side + y) * side + z; };
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z)
        for (const auto& [dx, dy, dz] : {std::array{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}) {
          if (x + dx >= side || y + dy >= side || z + dz >= side) continue;
          const int a = index(x, y, z), b = index(x + dx, y + dy, z + dz);
          Eigen::MatrixXd r(2 * ndf, 2 * ndf);
          for (int i = 0; i < r.size(); ++i) r.data()[i] = u(rng);
          const Eigen::MatrixXd k = r * r.transpose();
          for (int i = 0; i < 2 * ndf; ++i)
            for (int j = 0; j < 2 * ndf; ++j) {
              const int gi = (i < ndf ? a : b) * ndf + i % ndf;
              const int gj = (j < ndf ? a : b) * ndf + j % ndf;
              dense(gi, gj) += k(i, j);
            }
        }
  dense.diagonal().array() += 0.05;
  const Eigen::SparseMatrix<double> A = dense.sparseView(0.0, 0.0);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_TRUE(ok(ldlt.factorize(A)));
  EXPECT_LE(ldlt.supernodes(), nodes);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 2.0, -1.0);
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  const Eigen::VectorXd expected = dense.llt().solve(b);
  EXPECT_LT((x - expected).norm(), 1e-9 * expected.norm());
  EXPECT_LT(relativeResidual(A, x, b), kSolveTol);
}

/// Factorises and solves A x = b with `threads` threads; the pivots and x.
std::pair<Eigen::VectorXd, Eigen::VectorXd> factorAndSolve(SparseLdlt& ldlt,
                                                           const Eigen::SparseMatrix<double>& A,
                                                           const Eigen::VectorXd& b, int threads) {
  ldlt.setThreads(threads);
  EXPECT_TRUE(ok(ldlt.factorize(A))) << threads << " threads";
  Eigen::VectorXd x;
  ldlt.solve(b, x);
  return {ldlt.pivots(), x};
}

bool sameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), static_cast<std::size_t>(a.size()) * sizeof(double)) == 0;
}

TEST(SparseLdltTest, LongChainIsSplitIntoTwoHalvesAndASmallSeparator) {
  // 150 nodes in a row (450 equations): a breadth-first level across the middle cuts it, a
  // few nodes wide (the long links reach 7 nodes on), into halves within 40/60 of each other.
  const Eigen::SparseMatrix<double> A = chain(150, 0.1, 31);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  const SparseLdlt::Split split = ldlt.split();
  const int n = static_cast<int>(A.rows());
  EXPECT_EQ(split.first + split.second + split.separator, n);
  EXPECT_GT(split.separator, 0);
  EXPECT_LE(16 * split.separator, n);
  EXPECT_LE(5 * std::abs(split.first - split.second), split.first + split.second);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
  const auto [pivots, x] = factorAndSolve(ldlt, A, b, 1);
  const Eigen::VectorXd expected = Eigen::MatrixXd(A).llt().solve(b);
  EXPECT_LT((x - expected).norm(), kSolveTol * expected.norm());
  EXPECT_LT(relativeResidual(A, x, b), kSolveTol);
  EXPECT_GT(pivots.minCoeff(), 0.0);
}

TEST(SparseLdltTest, SplitOrderGivesTheSameBitsOnOneAndTwoThreads) {
  // The halves on two threads (or one after the other when the team has one): the pivots and
  // the solution are the one-thread ones bit for bit, over refactorisations with new values
  // and for an indefinite matrix (negative pivots in either half).
  Eigen::SparseMatrix<double> A = chain(120, 0.05, 32);
  SparseLdlt ldlt;
  ldlt.analyze(A);
  ASSERT_GT(ldlt.split().separator, 0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 3.0, -1.0);
  for (int round = 0; round < 3; ++round) {
    if (round == 1) addToDiagonal(A, 0.3);
    if (round == 2) {
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig{Eigen::MatrixXd(A)};
      addToDiagonal(A, -0.5 * (eig.eigenvalues()(2) + eig.eigenvalues()(3)));
    }
    const auto [pivots1, x1] = factorAndSolve(ldlt, A, b, 1);
    const auto [pivots2, x2] = factorAndSolve(ldlt, A, b, 2);
    EXPECT_TRUE(sameBits(pivots1, pivots2)) << "round " << round;
    EXPECT_TRUE(sameBits(x1, x2)) << "round " << round;
    EXPECT_LT(relativeResidual(A, x2, b), 1e-8) << "round " << round;
    if (round == 2) {
      EXPECT_EQ((pivots2.array() < 0.0).count(), 3);  // Sylvester's law of inertia
    }
  }
}

TEST(SparseLdltTest, SmallOrWellConnectedMatricesAreNotSplit) {
  // Below 192 equations the halves are not worth a thread; a lattice whose every level is a
  // large share of it has no small separator: both keep the one minimum-degree order.
  SparseLdlt small;
  small.analyze(chain(40, 0.1, 33));
  EXPECT_EQ(small.split().separator, 0);
  constexpr int n = 200;  // every equation coupled to the next 30: levels of 30 equations
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < std::min(n, i + 31); ++j) dense(i, j) = dense(j, i) = -0.01;
  dense.diagonal().array() = 1.0;
  SparseLdlt wide;
  const Eigen::SparseMatrix<double> A = dense.sparseView(0.0, 0.0);
  wide.analyze(A);
  EXPECT_EQ(wide.split().separator, 0);
  EXPECT_EQ(wide.split().first, n);
}

TEST(SparseLdltTest, SplitOrderOfTwoUnconnectedChainsSolvesLikeDense) {
  // Two chains with no coupling: the search reaches one, whose middle level is the separator,
  // and the other joins the smaller half.
  const Eigen::SparseMatrix<double> a = chain(90, 0.2, 34), c = chain(30, 0.2, 35);
  const int na = static_cast<int>(a.rows()), n = na + static_cast<int>(c.rows());
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < a.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, j); it; ++it)
      t.emplace_back(it.row(), it.col(), it.value());
  for (int j = 0; j < c.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(c, j); it; ++it)
      t.emplace_back(na + it.row(), na + it.col(), it.value());
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  SparseLdlt ldlt;
  ldlt.analyze(A);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, -2.0);
  const auto [pivots1, x1] = factorAndSolve(ldlt, A, b, 1);
  const auto [pivots2, x2] = factorAndSolve(ldlt, A, b, 2);
  const Eigen::VectorXd expected = Eigen::MatrixXd(A).llt().solve(b);
  EXPECT_LT((x1 - expected).norm(), kSolveTol * expected.norm());
  EXPECT_TRUE(sameBits(x1, x2));
}

TEST(SparseLdltTest, ZeroPivotInEitherHalfIsSingularOnTwoThreads) {
  for (const int row : {10, 400}) {
    Eigen::SparseMatrix<double> A = chain(150, 1.0, 36);
    for (int j = 0; j < A.cols(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
        if (it.row() == row || j == row) it.valueRef() = 0.0;
    SparseLdlt ldlt;
    ldlt.analyze(A);
    ASSERT_GT(ldlt.split().separator, 0);
    for (const int threads : {1, 2}) {
      ldlt.setThreads(threads);
      EXPECT_EQ(ldlt.factorize(A), Status::Singular) << "row " << row << ", " << threads;
    }
  }
}

}  // namespace
}  // namespace dabs::analysis
