// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/EigenSolver.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <random>

namespace dabs::analysis {

namespace {

constexpr double kSubspaceTolerance = 1e-12;  // relative change of each wanted eigenvalue
constexpr int kSubspaceMaxIterations = 200;

// Mass-normalises each column and makes its largest component positive.
void normalise(const Eigen::SparseMatrix<double>& M, Eigen::MatrixXd& phi) {
  for (Eigen::Index j = 0; j < phi.cols(); ++j) {
    const double m = phi.col(j).dot(M * phi.col(j));
    if (m > 0.0) phi.col(j) /= std::sqrt(m);
    Eigen::Index imax = 0;
    phi.col(j).cwiseAbs().maxCoeff(&imax);
    if (phi(imax, j) < 0.0) phi.col(j) *= -1.0;
  }
}

int massRank(const Eigen::SparseMatrix<double>& M) {
  // Number of dofs carrying mass bounds the number of finite eigenvalues.
  int count = 0;
  for (Eigen::Index j = 0; j < M.outerSize(); ++j) {
    bool any = false;
    for (Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
      if (it.value() != 0.0) any = true;
    if (any) ++count;
  }
  return count;
}

}  // namespace

EigenResult solveEigenDense(const Eigen::SparseMatrix<double>& K,
                            const Eigen::SparseMatrix<double>& M, int numModes, bool largest) {
  EigenResult out;
  const Eigen::Index n = K.rows();
  const int rank = massRank(M);
  if (numModes > rank) {
    out.status = Status::Failed;
    return out;
  }
  const Eigen::MatrixXd Kd(K), Md(M);
  Eigen::LLT<Eigen::MatrixXd> llt(Kd);
  if (llt.info() != Eigen::Success) {
    out.status = Status::Singular;
    return out;
  }
  // S = L^-1 M L^-T has eigenvalues mu = 1/lambda; massless dofs give mu = 0.
  Eigen::MatrixXd S = llt.matrixL().solve(Md);
  S = llt.matrixL().solve(S.transpose()).transpose();
  S = 0.5 * (S + S.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
  if (es.info() != Eigen::Success) {
    out.status = Status::NotConverged;
    return out;
  }
  out.values.resize(numModes);
  out.vectors.resize(n, numModes);
  for (int i = 0; i < numModes; ++i) {
    // Smallest lambda: largest mu first. Largest finite lambda: the smallest of the `rank` positive
    // mu, listed in ascending lambda as OpenSees lists them.
    const Eigen::Index col = largest ? n - rank + numModes - 1 - i : n - 1 - i;
    const double mu = es.eigenvalues()(col);
    if (!(mu > 0.0)) {
      out.status = Status::Failed;
      return out;
    }
    out.values(i) = 1.0 / mu;
    out.vectors.col(i) = llt.matrixU().solve(es.eigenvectors().col(col));
  }
  normalise(M, out.vectors);
  return out;
}

EigenResult solveEigenSubspace(const Eigen::SparseMatrix<double>& K,
                               const Eigen::SparseMatrix<double>& M, int numModes) {
  EigenResult out;
  const Eigen::Index n = K.rows();
  const int rank = massRank(M);
  if (numModes > rank) {
    out.status = Status::Failed;
    return out;
  }
  const int q = std::min(rank, std::max(2 * numModes, numModes + 8));
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(K);
  if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0.0).any()) {
    out.status = Status::Singular;
    return out;
  }
  // Starting vectors: M times a fixed pseudo-random matrix, so every mode with mass is excited.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  Eigen::MatrixXd X(n, q);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int j = 0; j < q; ++j) X(i, j) = dist(rng);
  Eigen::VectorXd previous = Eigen::VectorXd::Zero(numModes);
  Eigen::MatrixXd Y, Xbar, Kr, Mr;
  for (int iter = 0; iter < kSubspaceMaxIterations; ++iter) {
    Y = M * X;
    Xbar = ldlt.solve(Y);
    Kr = Xbar.transpose() * Y;
    Mr = Xbar.transpose() * (M * Xbar);
    Kr = 0.5 * (Kr + Kr.transpose());
    Mr = 0.5 * (Mr + Mr.transpose());
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> ges(Kr, Mr);
    if (ges.info() != Eigen::Success) {
      out.status = Status::NotConverged;
      return out;
    }
    X = Xbar * ges.eigenvectors();
    const Eigen::VectorXd lambda = ges.eigenvalues().head(numModes);
    const double change =
        ((lambda - previous).cwiseAbs().array() / lambda.cwiseAbs().array()).maxCoeff();
    previous = lambda;
    if (iter > 0 && change < kSubspaceTolerance) {
      out.values = lambda;
      out.vectors = X.leftCols(numModes);
      normalise(M, out.vectors);
      return out;
    }
  }
  out.status = Status::NotConverged;
  return out;
}

}  // namespace dabs::analysis
