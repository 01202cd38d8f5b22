// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/SparseLdlt.h"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>

namespace dabs::analysis {

void SparseLdlt::analyze(const Eigen::SparseMatrix<double>& A) {
  n_ = static_cast<int>(A.rows());
  const auto n = static_cast<std::size_t>(n_);
  // Fill-reducing order: AMD computes the inverse permutation (Eigen's convention).
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  Eigen::AMDOrdering<int> amd;
  amd(A, inverse);
  perm_.assign(n, 0);
  if (inverse.size() == n_) {
    for (int k = 0; k < n_; ++k) perm_[static_cast<std::size_t>(inverse.indices()(k))] = k;
  } else {
    for (int k = 0; k < n_; ++k) perm_[static_cast<std::size_t>(k)] = k;
  }

  // Upper triangle of P A P^T (row <= column), and where each of A's values goes in it.
  std::vector<int> count(n + 1, 0);
  for (int j = 0; j < n_; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int pi = perm_[static_cast<std::size_t>(it.row())],
                pj = perm_[static_cast<std::size_t>(j)];
      if (pi <= pj) ++count[static_cast<std::size_t>(pj) + 1];
    }
  cp_.assign(n + 1, 0);
  for (std::size_t j = 0; j < n; ++j) cp_[j + 1] = cp_[j] + count[j + 1];
  ci_.assign(static_cast<std::size_t>(cp_[n]), 0);
  cx_.assign(static_cast<std::size_t>(cp_[n]), 0.0);
  valueTo_.assign(static_cast<std::size_t>(A.nonZeros()), -1);
  std::vector<int> next(cp_.begin(), cp_.end() - 1);
  for (int j = 0; j < n_; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int pi = perm_[static_cast<std::size_t>(it.row())],
                pj = perm_[static_cast<std::size_t>(j)];
      if (pi > pj) continue;
      const int place = next[static_cast<std::size_t>(pj)]++;
      ci_[static_cast<std::size_t>(place)] = pi;
      valueTo_[static_cast<std::size_t>(&it.value() - A.valuePtr())] = place;
    }

  // Elimination tree and column counts of L (Davis 2005, ldl_symbolic): row k of L has a
  // nonzero in column i for every node i on the tree paths from the entries of column k of the
  // upper triangle up to k.
  parent_.assign(n, -1);
  lnz_.assign(n, 0);
  flag_.assign(n, -1);
  for (int k = 0; k < n_; ++k) {
    flag_[static_cast<std::size_t>(k)] = k;
    for (int p = cp_[static_cast<std::size_t>(k)]; p < cp_[static_cast<std::size_t>(k) + 1]; ++p) {
      for (int i = ci_[static_cast<std::size_t>(p)]; flag_[static_cast<std::size_t>(i)] != k;
           i = parent_[static_cast<std::size_t>(i)]) {
        if (parent_[static_cast<std::size_t>(i)] == -1) parent_[static_cast<std::size_t>(i)] = k;
        ++lnz_[static_cast<std::size_t>(i)];
        flag_[static_cast<std::size_t>(i)] = k;
      }
    }
  }
  // Supernodes: column j+1 continues j's supernode when it is j's parent in the tree and its
  // pattern below the diagonal is j's without row j+1.
  superFirst_.assign(1, 0);
  for (int j = 1; j < n_; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    if (!(parent_[uj - 1] == j && lnz_[uj - 1] == lnz_[uj] + 1)) superFirst_.push_back(j);
  }
  if (n_ > 0) superFirst_.push_back(n_);
  const std::size_t ns = superFirst_.size() - 1;
  superHeight_.assign(ns, 0);
  superStart_.assign(ns, 0);
  colStart_.assign(n, 0);
  std::size_t size = 0;
  int maxHeight = 0;
  factorNonZeros_ = 0;
  for (std::size_t s = 0; s < ns; ++s) {
    const int f = superFirst_[s], w = superFirst_[s + 1] - f;
    const int h = lnz_[static_cast<std::size_t>(f)] + 1;
    superHeight_[s] = h;
    superStart_[s] = static_cast<int>(size);
    for (int k = 0; k < w; ++k) {
      colStart_[static_cast<std::size_t>(f + k)] = static_cast<int>(size) + k * h + k + 1;
      factorNonZeros_ += lnz_[static_cast<std::size_t>(f + k)];
    }
    size += static_cast<std::size_t>(h) * static_cast<std::size_t>(w);
    maxHeight = std::max(maxHeight, h);
  }
  li_.assign(size, 0);
  lx_.assign(size, 0.0);  // the unused upper part of each block stays zero
  gather_ = Eigen::VectorXd::Zero(maxHeight);
  d_ = Eigen::VectorXd::Zero(n_);
  y_.assign(n, 0.0);
  work_ = Eigen::VectorXd::Zero(n_);

  // The pattern of every row of L, in an order in which each entry's updates come before it (the
  // reversed tree paths of ldl_numeric). It depends on the pattern alone, so it is found once here
  // rather than at every factorisation.
  rowStart_.assign(n + 1, 0);
  rowPattern_.assign(static_cast<std::size_t>(factorNonZeros_), 0);
  std::vector<int> stack(n, 0);
  flag_.assign(n, -1);
  int filled = 0;
  for (int k = 0; k < n_; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    int top = n_;
    flag_[uk] = k;
    for (int p = cp_[uk]; p < cp_[uk + 1]; ++p) {
      int len = 0;
      for (int i = ci_[static_cast<std::size_t>(p)]; flag_[static_cast<std::size_t>(i)] != k;
           i = parent_[static_cast<std::size_t>(i)]) {
        stack[static_cast<std::size_t>(len++)] = i;
        flag_[static_cast<std::size_t>(i)] = k;
      }
      while (len > 0)
        stack[static_cast<std::size_t>(--top)] = stack[static_cast<std::size_t>(--len)];
    }
    for (; top < n_; ++top)
      rowPattern_[static_cast<std::size_t>(filled++)] = stack[static_cast<std::size_t>(top)];
    rowStart_[uk + 1] = filled;
  }
}

Status SparseLdlt::factorize(const Eigen::SparseMatrix<double>& A) {
  const double* values = A.valuePtr();
  const auto nnz = valueTo_.size();
  for (std::size_t k = 0; k < nnz; ++k)
    if (valueTo_[k] >= 0) cx_[static_cast<std::size_t>(valueTo_[k])] = values[k];

  // Row k of L by a sparse triangular solve with the rows above it (Davis 2005, ldl_numeric),
  // over the row pattern found by analyze().
  std::fill(lnz_.begin(), lnz_.end(), 0);
  for (int k = 0; k < n_; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    for (int p = cp_[uk]; p < cp_[uk + 1]; ++p)
      y_[static_cast<std::size_t>(ci_[static_cast<std::size_t>(p)])] +=
          cx_[static_cast<std::size_t>(p)];
    double dk = y_[uk];
    y_[uk] = 0.0;
    for (int r = rowStart_[uk]; r < rowStart_[uk + 1]; ++r) {
      const auto ui = static_cast<std::size_t>(rowPattern_[static_cast<std::size_t>(r)]);
      const double yi = y_[ui];
      y_[ui] = 0.0;
      const int end = colStart_[ui] + lnz_[ui];
      for (int p = colStart_[ui]; p < end; ++p)
        y_[static_cast<std::size_t>(li_[static_cast<std::size_t>(p)])] -=
            lx_[static_cast<std::size_t>(p)] * yi;
      const double lki = yi / d_(static_cast<Eigen::Index>(ui));
      dk -= lki * yi;
      li_[static_cast<std::size_t>(end)] = k;
      lx_[static_cast<std::size_t>(end)] = lki;
      ++lnz_[ui];
    }
    if (!(dk != 0.0) || !std::isfinite(dk)) return Status::Singular;
    d_(k) = dk;
  }
  return Status::Ok;
}

void SparseLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  using Column = Eigen::Map<const Eigen::VectorXd>;
  using Work = Eigen::Map<Eigen::VectorXd>;
  Eigen::VectorXd& z = work_;
  for (int i = 0; i < n_; ++i) z(perm_[static_cast<std::size_t>(i)]) = b(i);
  const std::size_t ns = superFirst_.size() > 0 ? superFirst_.size() - 1 : 0;
  double* y = gather_.data();  // a supernode's rows: its own columns, then the rows below
  // L z = P b, supernode by supernode: y holds the supernode's part of z and the updates of the
  // rows below it; each column is one contiguous update of the rows under its diagonal.
  for (std::size_t s = 0; s < ns; ++s) {
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    const double* block = lx_.data() + superStart_[s];
    const int* rows = li_.data() + superStart_[s];  // rows[r] of block row r >= w
    for (int r = 0; r < w; ++r) y[r] = z(f + r);
    std::fill(y + w, y + h, 0.0);
    for (int k = 0; k < w; ++k) {
      const double* col = block + static_cast<std::ptrdiff_t>(k) * h;
      Work(y + k + 1, h - k - 1).noalias() -= y[k] * Column(col + k + 1, h - k - 1);
    }
    for (int r = 0; r < w; ++r) z(f + r) = y[r];
    for (int r = w; r < h; ++r) z(rows[r]) += y[r];
  }
  z.array() /= d_.array();
  // L^T z = z, in reverse: each column's entry less its dot product with the rows below.
  for (std::size_t s = ns; s-- > 0;) {
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    const double* block = lx_.data() + superStart_[s];
    const int* rows = li_.data() + superStart_[s];
    for (int r = 0; r < w; ++r) y[r] = z(f + r);
    for (int r = w; r < h; ++r) y[r] = z(rows[r]);
    for (int k = w - 1; k >= 0; --k) {
      const double* col = block + static_cast<std::ptrdiff_t>(k) * h;
      y[k] -= Column(col + k + 1, h - k - 1).dot(Column(y + k + 1, h - k - 1));
    }
    for (int r = 0; r < w; ++r) z(f + r) = y[r];
  }
  if (x.size() != n_) x.resize(n_);
  for (int i = 0; i < n_; ++i) x(i) = z(perm_[static_cast<std::size_t>(i)]);
}

}  // namespace dabs::analysis
