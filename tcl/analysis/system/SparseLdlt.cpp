// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/SparseLdlt.h"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
  std::vector<int> cp(n + 1, 0);  // the permuted upper triangle's pattern, compressed columns
  for (std::size_t j = 0; j < n; ++j) cp[j + 1] = cp[j] + count[j + 1];
  std::vector<int> ci(static_cast<std::size_t>(cp[n]), 0);
  std::vector<int> next(cp.begin(), cp.end() - 1);
  for (int j = 0; j < n_; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int pi = perm_[static_cast<std::size_t>(it.row())],
                pj = perm_[static_cast<std::size_t>(j)];
      if (pi > pj) continue;
      ci[static_cast<std::size_t>(next[static_cast<std::size_t>(pj)]++)] = pi;
    }

  // Elimination tree and column counts of L (Davis 2005, ldl_symbolic): row k of L has a
  // nonzero in column i for every node i on the tree paths from the entries of column k of the
  // upper triangle up to k.
  parent_.assign(n, -1);
  std::vector<int> lnz(n, 0), flag(n, -1);  // column counts of L; marks of the tree walks
  for (int k = 0; k < n_; ++k) {
    flag[static_cast<std::size_t>(k)] = k;
    for (int p = cp[static_cast<std::size_t>(k)]; p < cp[static_cast<std::size_t>(k) + 1]; ++p) {
      for (int i = ci[static_cast<std::size_t>(p)]; flag[static_cast<std::size_t>(i)] != k;
           i = parent_[static_cast<std::size_t>(i)]) {
        if (parent_[static_cast<std::size_t>(i)] == -1) parent_[static_cast<std::size_t>(i)] = k;
        ++lnz[static_cast<std::size_t>(i)];
        flag[static_cast<std::size_t>(i)] = k;
      }
    }
  }
  // Supernodes: column j+1 continues j's supernode when it is j's parent in the tree and its
  // pattern below the diagonal is j's without row j+1.
  superFirst_.assign(1, 0);
  for (int j = 1; j < n_; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    if (!(parent_[uj - 1] == j && lnz[uj - 1] == lnz[uj] + 1)) superFirst_.push_back(j);
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
    const int h = lnz[static_cast<std::size_t>(f)] + 1;
    // Offsets into the blocks are ints: a factor past 2^31 - 1 entries (16 GiB of values) is
    // refused rather than addressed wrongly.
    if (size + static_cast<std::size_t>(h) * static_cast<std::size_t>(w) >
        static_cast<std::size_t>(std::numeric_limits<int>::max()))
      throw std::length_error("sparse LDL^T of " + std::to_string(n_) +
                              " equations: its factor needs more than 2^31 - 1 entries");
    superHeight_[s] = h;
    superStart_[s] = static_cast<int>(size);
    for (int k = 0; k < w; ++k) {
      colStart_[static_cast<std::size_t>(f + k)] = static_cast<int>(size) + k * h + k + 1;
      factorNonZeros_ += lnz[static_cast<std::size_t>(f + k)];
    }
    size += static_cast<std::size_t>(h) * static_cast<std::size_t>(w);
    maxHeight = std::max(maxHeight, h);
  }
  li_.assign(size, 0);
  lx_.assign(size, 0.0);  // the unused upper part of each block stays zero
  gather_ = Eigen::VectorXd::Zero(maxHeight);
  d_ = Eigen::VectorXd::Zero(n_);
  work_ = Eigen::VectorXd::Zero(n_);

  // The rows of every column of L, ascending: row k of L has a nonzero in column i for every i
  // on the tree paths from the entries of column k of the upper triangle up to k (ldl_symbolic
  // again), and k grows. A supernode's block rows are those of its first column.
  std::fill(lnz.begin(), lnz.end(), 0);
  flag.assign(n, -1);
  for (int k = 0; k < n_; ++k) {
    flag[static_cast<std::size_t>(k)] = k;
    for (int p = cp[static_cast<std::size_t>(k)]; p < cp[static_cast<std::size_t>(k) + 1]; ++p)
      for (int i = ci[static_cast<std::size_t>(p)]; flag[static_cast<std::size_t>(i)] != k;
           i = parent_[static_cast<std::size_t>(i)]) {
        const auto ui = static_cast<std::size_t>(i);
        li_[static_cast<std::size_t>(colStart_[ui] + lnz[ui]++)] = k;
        flag[ui] = k;
      }
  }
  colSuper_.assign(n, 0);
  for (std::size_t s = 0; s < ns; ++s)
    for (int j = superFirst_[s]; j < superFirst_[s + 1]; ++j)
      colSuper_[static_cast<std::size_t>(j)] = static_cast<int>(s);

  // Each value of A on or above the diagonal of P A P^T (the triangle the tree was formed from)
  // goes straight to its mirror place in L's blocks (row r of column k of supernode s:
  // superStart_[s] + k h + r); the entries below are their mirror images and are not read.
  // The list is in the order of L's storage, so each supernode's entries are one run
  // (scatterStart_): the factorisation clears and fills a block just before it works on it, while
  // the block is in the cache.
  scatter_.clear();
  for (int j = 0; j < n_; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const int col = perm_[static_cast<std::size_t>(it.row())],
                row = perm_[static_cast<std::size_t>(j)];
      if (row < col) continue;
      const auto s = static_cast<std::size_t>(colSuper_[static_cast<std::size_t>(col)]);
      const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
      int local = row - f;
      if (local >= w) {
        const int* rows = li_.data() + superStart_[s];
        local = static_cast<int>(std::lower_bound(rows + w, rows + h, row) - rows);
      }
      scatter_.emplace_back(static_cast<int>(&it.value() - A.valuePtr()),
                            superStart_[s] + (col - f) * h + local);
    }
  std::sort(scatter_.begin(), scatter_.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  scatterStart_.assign(ns + 1, static_cast<int>(scatter_.size()));
  for (std::size_t s = 0; s < ns; ++s)
    scatterStart_[s] = static_cast<int>(
        std::lower_bound(scatter_.begin(), scatter_.end(), superStart_[s],
                         [](const auto& entry, int start) { return entry.second < start; }) -
        scatter_.begin());
  relative_.assign(n, 0);
  nextUpdate_.assign(ns, -1);
  firstUpdate_.assign(ns, -1);
  updateRow_.assign(ns, 0);
}

Status SparseLdlt::factorize(const Eigen::SparseMatrix<double>& A) {
  // Supernodal left-looking L D L^T (the arrangement of Ng & Peyton 1993, "Block sparse Cholesky
  // algorithms on advanced uniprocessor computers", SIAM J. Sci. Comput. 14(5), with D): each
  // supernode's block gathers its columns of A, subtracts the updates of the supernodes below it
  // in the tree whose rows reach its columns (one dense column product for each of its columns a
  // descendant reaches), and is factorised densely.
  // A descendant waits in the list of the supernode that holds its next row (updateRow_), so
  // every block is visited once per supernode it updates.
  const double* values = A.valuePtr();
  const std::size_t ns = superFirst_.size() > 0 ? superFirst_.size() - 1 : 0;
  std::fill(firstUpdate_.begin(), firstUpdate_.end(), -1);
  double* dd = d_.data();
  double* product = gather_.data();  // one column of a descendant's update
  for (std::size_t s = 0; s < ns; ++s) {
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    double* block = lx_.data() + superStart_[s];
    const int* rows = li_.data() + superStart_[s];
    // The block's values of A (its fill and the unused upper part of its diagonal block zero).
    std::fill(block, block + static_cast<std::ptrdiff_t>(w) * h, 0.0);
    for (int e = scatterStart_[s]; e < scatterStart_[s + 1]; ++e) {
      const auto& [from, to] = scatter_[static_cast<std::size_t>(e)];
      lx_[static_cast<std::size_t>(to)] = values[static_cast<std::size_t>(from)];
    }
    for (int r = 0; r < h; ++r) relative_[static_cast<std::size_t>(r < w ? f + r : rows[r])] = r;
    // Updates from the descendants: with Lk their rows from the first in s's columns down,
    // block(rows, cols) -= Lk D Lk(cols)^T over the rows of Lk in s's columns.
    for (int k = firstUpdate_[s]; k >= 0;) {
      const auto uk = static_cast<std::size_t>(k);
      const int next = nextUpdate_[uk];
      const int fk = superFirst_[uk], wk = superFirst_[uk + 1] - fk, hk = superHeight_[uk];
      const double* blockK = lx_.data() + superStart_[uk];
      const int* rowsK = li_.data() + superStart_[uk];
      const int begin = updateRow_[uk];
      int end = begin;
      while (end < hk && rowsK[end] < f + w) ++end;
      for (int c = begin; c < end; ++c) {
        // Column rowsK[c] of s, rows from rowsK[c] down: product = Lk(c.., :) D Lk(c, :)^T, one
        // contiguous multiply-add per column of the descendant (short columns: plain loops beat
        // a library product's set-up here).
        const int rowsFromC = hk - c;
        std::fill(product, product + rowsFromC, 0.0);
        for (int q = 0; q < wk; ++q) {
          const double* colK = blockK + static_cast<std::ptrdiff_t>(q) * hk + c;
          const double scaled = colK[0] * dd[fk + q];
          for (int r = 0; r < rowsFromC; ++r) product[r] += scaled * colK[r];
        }
        double* column = block + static_cast<std::ptrdiff_t>(rowsK[c] - f) * h;
        for (int r = 0; r < rowsFromC; ++r)
          column[relative_[static_cast<std::size_t>(rowsK[c + r])]] -= product[r];
      }
      // The descendant waits next for the supernode of its first row below s's columns.
      updateRow_[uk] = end;
      if (end < hk) {
        const auto t = static_cast<std::size_t>(colSuper_[static_cast<std::size_t>(rowsK[end])]);
        nextUpdate_[uk] = firstUpdate_[t];
        firstUpdate_[t] = k;
      }
      k = next;
    }
    // Dense L D L^T of the block, column by column: the pivot, the column of L below it, and the
    // update of the block's later columns (their rows from the diagonal down).
    for (int k = 0; k < w; ++k) {
      double* col = block + static_cast<std::ptrdiff_t>(k) * h;
      const double dk = col[k];
      if (!(dk != 0.0) || !std::isfinite(dk)) return Status::Singular;
      dd[f + k] = dk;
      for (int r = k + 1; r < h; ++r) col[r] /= dk;
      for (int j = k + 1; j < w; ++j) {
        const double ljk = col[j] * dk;
        double* target = block + static_cast<std::ptrdiff_t>(j) * h;
        for (int r = j; r < h; ++r) target[r] -= ljk * col[r];
      }
    }
    if (h > w) {
      updateRow_[s] = w;
      const auto t = static_cast<std::size_t>(colSuper_[static_cast<std::size_t>(rows[w])]);
      nextUpdate_[s] = firstUpdate_[t];
      firstUpdate_[t] = static_cast<int>(s);
    }
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
