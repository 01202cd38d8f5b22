// SPDX-License-Identifier: MIT
#include "tcl/analysis/system/SparseLdlt.h"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string>

#include <camd.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

namespace dabs::analysis {

namespace {

// A split pays when the halves are worth two threads and the separator, eliminated last with
// its fill, is small: at most a sixteenth of the equations, the halves within 40/60. On a deck's
// chain of 6-dof nodes two threads factorised and solved 132 equations in 0.97 to 1.3 times the
// one-thread time, 180 in 1.03 to 1.46 and 270 or more in 1.5 to 1.8
// (verification/bench/sparse-ldlt-split.cpp).
constexpr int kSplitAtLeast = 192;
constexpr int kSeparatorShare = 16;

/// product[r] += sum over q of (column q's entry 0 times d[q]) times column q's entry r, for r <
/// rows and the `width` columns of `columns` (`stride` apart): a descendant supernode's update of
/// one column. Four columns at a time, so that product is loaded and stored once per four; each
/// row still takes its terms one by one in column order, so the result of one column at a time,
/// bit for bit.
void addColumnProducts(const double* __restrict columns, int stride, int width,
                       const double* __restrict d, int rows, double* __restrict product) {
  const auto column = [columns, stride](int q) {
    return columns + static_cast<std::ptrdiff_t>(q) * stride;
  };
  int q = 0;
  for (; q + 4 <= width; q += 4) {
    const double* c0 = column(q);
    const double* c1 = column(q + 1);
    const double* c2 = column(q + 2);
    const double* c3 = column(q + 3);
    const double s0 = c0[0] * d[q], s1 = c1[0] * d[q + 1], s2 = c2[0] * d[q + 2],
                 s3 = c3[0] * d[q + 3];
    for (int r = 0; r < rows; ++r)
      product[r] = (((product[r] + s0 * c0[r]) + s1 * c1[r]) + s2 * c2[r]) + s3 * c3[r];
  }
  for (; q < width; ++q) {
    const double* c = column(q);
    const double scaled = c[0] * d[q];
    for (int r = 0; r < rows; ++r) product[r] += scaled * c[r];
  }
}

/// target[r] -= (column k's entry j times d[k]) times column k's entry r, for rows r from j down
/// to the block's height and the block's columns k < j in order: the updates of a supernode's
/// column j by its earlier columns. Four columns at a time, each row's subtractions still one by
/// one in column order (bit for bit those of one column at a time).
void subtractColumnProducts(const double* block, int height, int j, const double* __restrict d,
                            double* target) {
  const auto column = [block, height](int k) {
    return block + static_cast<std::ptrdiff_t>(k) * height;
  };
  int k = 0;
  for (; k + 4 <= j; k += 4) {
    const double* c0 = column(k);
    const double* c1 = column(k + 1);
    const double* c2 = column(k + 2);
    const double* c3 = column(k + 3);
    const double l0 = c0[j] * d[k], l1 = c1[j] * d[k + 1], l2 = c2[j] * d[k + 2],
                 l3 = c3[j] * d[k + 3];
    for (int r = j; r < height; ++r)
      target[r] = (((target[r] - l0 * c0[r]) - l1 * c1[r]) - l2 * c2[r]) - l3 * c3[r];
  }
  for (; k < j; ++k) {
    const double* c = column(k);
    const double l = c[j] * d[k];
    for (int r = j; r < height; ++r) target[r] -= l * c[r];
  }
}

/// The forward substitution inside one supernode's block (w columns of height h, column-major;
/// column k's entries below the diagonal from row k + 1): y[k + 1, h) -= y[k] * column k for
/// k = 0 .. w - 1. Four columns at a time, so that each row below is loaded and stored once per
/// four columns instead of once per column; every row still takes its subtractions one by one in
/// column order, so the result is that of one column at a time, bit for bit.
void forwardInBlock(const double* __restrict block, int w, int h, double* __restrict y) {
  int k = 0;
  for (; k + 4 <= w; k += 4) {
    const double* c0 = block + static_cast<std::ptrdiff_t>(k) * h;
    const double* c1 = c0 + h;
    const double* c2 = c1 + h;
    const double* c3 = c2 + h;
    y[k + 1] -= y[k] * c0[k + 1];
    y[k + 2] = (y[k + 2] - y[k] * c0[k + 2]) - y[k + 1] * c1[k + 2];
    y[k + 3] = ((y[k + 3] - y[k] * c0[k + 3]) - y[k + 1] * c1[k + 3]) - y[k + 2] * c2[k + 3];
    const double a0 = y[k], a1 = y[k + 1], a2 = y[k + 2], a3 = y[k + 3];
    for (int r = k + 4; r < h; ++r)
      y[r] = (((y[r] - a0 * c0[r]) - a1 * c1[r]) - a2 * c2[r]) - a3 * c3[r];
  }
  for (; k < w; ++k) {
    const double* c = block + static_cast<std::ptrdiff_t>(k) * h;
    const double a = y[k];
    for (int r = k + 1; r < h; ++r) y[r] -= a * c[r];
  }
}

/// Sums of products as two partial sums, of the even and the odd terms, added at the end: in
/// SSE2 registers (lane 0 even, lane 1 odd) where the processor has them, else in two doubles,
/// the same operations in the same order, so the same bits.
#if defined(__SSE2__)
struct PairSum {
  __m128d lanes = _mm_setzero_pd();
  void addTwo(const double* c, const double* y) {
    lanes = _mm_add_pd(lanes, _mm_mul_pd(_mm_loadu_pd(c), _mm_loadu_pd(y)));
  }
  void addEven(double c, double y) { lanes = _mm_add_sd(lanes, _mm_set_sd(c * y)); }
  double total() const {
    return _mm_cvtsd_f64(lanes) + _mm_cvtsd_f64(_mm_unpackhi_pd(lanes, lanes));
  }
};
#else
struct PairSum {
  double even = 0.0, odd = 0.0;
  void addTwo(const double* c, const double* y) {
    even += c[0] * y[0];
    odd += c[1] * y[1];
  }
  void addEven(double c, double y) { even += c * y; }
  double total() const { return even + odd; }
};
#endif

/// The backward substitution inside one supernode's block (as forwardInBlock): y[k] -= column k
/// . y over rows k + 1 .. h - 1, for k = w - 1 down to 0. Four columns at a time (k down to
/// k - 3): their dot products over the rows below k, which are final, in one pass that loads
/// each row once (PairSum, pairs of rows from k + 1); then the terms of rows k - 2 .. k inside
/// the four, from the last row.
void backwardInBlock(const double* __restrict block, int w, int h, double* __restrict y) {
  const auto column = [block, h](int k) { return block + static_cast<std::ptrdiff_t>(k) * h; };
  int k = w - 1;
  for (; k >= 3; k -= 4) {
    const double* c0 = column(k);
    const double* c1 = column(k - 1);
    const double* c2 = column(k - 2);
    const double* c3 = column(k - 3);
    PairSum s0, s1, s2, s3;
    int r = k + 1;
    for (; r + 2 <= h; r += 2) {
      s0.addTwo(c0 + r, y + r);
      s1.addTwo(c1 + r, y + r);
      s2.addTwo(c2 + r, y + r);
      s3.addTwo(c3 + r, y + r);
    }
    if (r < h) {
      s0.addEven(c0[r], y[r]);
      s1.addEven(c1[r], y[r]);
      s2.addEven(c2[r], y[r]);
      s3.addEven(c3[r], y[r]);
    }
    y[k] -= s0.total();
    y[k - 1] -= s1.total() + c1[k] * y[k];
    y[k - 2] -= (s2.total() + c2[k] * y[k]) + c2[k - 1] * y[k - 1];
    y[k - 3] -= ((s3.total() + c3[k] * y[k]) + c3[k - 1] * y[k - 1]) + c3[k - 2] * y[k - 2];
  }
  for (; k >= 0; --k) {
    const double* c = column(k);
    PairSum sum;
    int r = k + 1;
    for (; r + 2 <= h; r += 2) sum.addTwo(c + r, y + r);
    if (r < h) sum.addEven(c[r], y[r]);
    y[k] -= sum.total();
  }
}

/// A one-level dissection of the graph of A's pattern: each equation's part (0 and 1 the
/// halves, 2 the separator), or empty when no small separator splits it evenly. The separator
/// is a level of a breadth-first search from a pseudo-peripheral equation (George & Liu 1979,
/// "An implementation of a pseudoperipheral node finder", ACM TOMS 5(3)): a level meets only
/// its two neighbour levels, so it cuts the levels before it from those after it.
std::vector<int> bisect(const Eigen::SparseMatrix<double>& A) {
  const int n = static_cast<int>(A.rows());
  if (n < kSplitAtLeast) return {};
  const int* p = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int* nz = A.innerNonZeroPtr();  // null when compressed
  auto end = [&](int j) { return nz ? p[j] + nz[j] : p[j + 1]; };
  auto degree = [&](int j) { return end(j) - p[j]; };
  std::vector<int> level(static_cast<std::size_t>(n)), queue(static_cast<std::size_t>(n));
  // Levels from `root`; returns the count of equations reached and sets `levels`.
  int levels = 0;
  auto search = [&](int root) {
    std::fill(level.begin(), level.end(), -1);
    int head = 0, tail = 0;
    queue[static_cast<std::size_t>(tail++)] = root;
    level[static_cast<std::size_t>(root)] = 0;
    while (head < tail) {
      const int j = queue[static_cast<std::size_t>(head++)];
      for (int q = p[j]; q < end(j); ++q) {
        const int i = inner[q];
        if (level[static_cast<std::size_t>(i)] >= 0) continue;
        level[static_cast<std::size_t>(i)] = level[static_cast<std::size_t>(j)] + 1;
        queue[static_cast<std::size_t>(tail++)] = i;
      }
    }
    levels = level[static_cast<std::size_t>(queue[static_cast<std::size_t>(tail - 1)])] + 1;
    return tail;
  };
  int root = 0;
  for (int j = 1; j < n; ++j)
    if (degree(j) < degree(root)) root = j;
  int reached = search(root);
  for (int round = 0; round < 8; ++round) {
    // The last level's equation of least degree; it becomes the root while the depth grows.
    int candidate = -1;
    for (int t = 0; t < reached; ++t) {
      const int j = queue[static_cast<std::size_t>(t)];
      if (level[static_cast<std::size_t>(j)] == levels - 1 &&
          (candidate < 0 || degree(j) < degree(candidate)))
        candidate = j;
    }
    const int before = levels;
    const std::vector<int> kept = level;
    const int keptReached = reached;
    reached = search(candidate);
    if (levels <= before) {
      level = kept;
      levels = before;
      reached = keptReached;
      break;
    }
  }
  std::vector<int> count(static_cast<std::size_t>(levels), 0);
  for (int j = 0; j < n; ++j)
    if (level[static_cast<std::size_t>(j)] >= 0)
      ++count[static_cast<std::size_t>(level[static_cast<std::size_t>(j)])];
  const int unreached = n - reached;
  int best = -1, bestSize = 0, bestImbalance = 0, before = 0;
  for (int l = 0; l < levels; ++l) {
    const int size = count[static_cast<std::size_t>(l)];
    int a = before, b = reached - before - size;
    (a <= b ? a : b) += unreached;  // other components go to the smaller half
    before += size;
    if (a == 0 || b == 0 || 5 * std::abs(a - b) > a + b) continue;
    const int imbalance = std::abs(a - b);
    if (best < 0 || size < bestSize || (size == bestSize && imbalance < bestImbalance)) {
      best = l;
      bestSize = size;
      bestImbalance = imbalance;
    }
  }
  if (best < 0 || kSeparatorShare * bestSize > n) return {};
  int firstSize = 0;
  for (int l = 0; l < best; ++l) firstSize += count[static_cast<std::size_t>(l)];
  const int secondSize = reached - firstSize - bestSize;
  const int unreachedPart = firstSize <= secondSize ? 0 : 1;
  std::vector<int> part(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const int l = level[static_cast<std::size_t>(j)];
    part[static_cast<std::size_t>(j)] = l < 0 ? unreachedPart : l < best ? 0 : l == best ? 2 : 1;
  }
  return part;
}

}  // namespace

void SparseLdlt::analyze(const Eigen::SparseMatrix<double>& A) {
  n_ = static_cast<int>(A.rows());
  const auto n = static_cast<std::size_t>(n_);
  perm_.assign(n, 0);
  split_ = Split{n_, 0, 0};
  if (std::vector<int> part = bisect(A); !part.empty()) {
    // The halves and then the separator, each by minimum degree (CAMD orders the equations of
    // constraint set 0 first, then set 1, then set 2).
    Eigen::SparseMatrix<double> compressed = A;
    compressed.makeCompressed();
    std::vector<int> order(n, 0);
    double control[CAMD_CONTROL];
    double info[CAMD_INFO];
    camd_defaults(control);
    const int status = camd_order(n_, compressed.outerIndexPtr(), compressed.innerIndexPtr(),
                                  order.data(), control, info, part.data());
    if (status != CAMD_OK && status != CAMD_OK_BUT_JUMBLED)
      throw std::runtime_error("sparse LDL^T: CAMD failed to order " + std::to_string(n_) +
                               " equations (status " + std::to_string(status) + ")");
    for (int k = 0; k < n_; ++k)
      perm_[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = k;
    split_.first = static_cast<int>(std::count(part.begin(), part.end(), 0));
    split_.second = static_cast<int>(std::count(part.begin(), part.end(), 1));
    split_.separator = n_ - split_.first - split_.second;
    // The factorisation relies on the sets being in order: the first half's equations, then
    // the second's, then the separator's.
    for (int k = 0; k < n_; ++k) {
      const int expected = k < split_.first ? 0 : k < split_.first + split_.second ? 1 : 2;
      if (part[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] != expected)
        throw std::logic_error("sparse LDL^T: CAMD did not keep the constraint sets in order");
    }
  } else {
    // Fill-reducing order: AMD computes the inverse permutation (Eigen's convention).
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
    Eigen::AMDOrdering<int> amd;
    amd(A, inverse);
    if (inverse.size() == n_) {
      for (int k = 0; k < n_; ++k) perm_[static_cast<std::size_t>(inverse.indices()(k))] = k;
    } else {
      for (int k = 0; k < n_; ++k) perm_[static_cast<std::size_t>(k)] = k;
    }
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
  // pattern below the diagonal is j's without row j+1; a split order's halves and separator
  // start supernodes of their own.
  const int secondFrom = split_.first, separatorFrom = split_.first + split_.second;
  superFirst_.assign(1, 0);
  superSecond_ = superSeparator_ = -1;
  for (int j = 1; j < n_; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    const bool boundary = split_.separator > 0 && (j == secondFrom || j == separatorFrom);
    if (boundary || !(parent_[uj - 1] == j && lnz[uj - 1] == lnz[uj] + 1)) superFirst_.push_back(j);
    if (boundary && j == secondFrom) superSecond_ = static_cast<int>(superFirst_.size()) - 1;
    if (boundary && j == separatorFrom) superSeparator_ = static_cast<int>(superFirst_.size()) - 1;
  }
  if (n_ > 0) superFirst_.push_back(n_);
  const std::size_t ns = superFirst_.size() - 1;
  if (superSecond_ < 0 || superSeparator_ < 0)
    superSecond_ = superSeparator_ = static_cast<int>(ns);
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
  for (Workspace& ws : workspace_) {
    ws.relative.assign(n, 0);
    ws.gather = Eigen::VectorXd::Zero(maxHeight);
    ws.waiting.clear();
    ws.waiting.reserve(ns);
    ws.toSeparator.clear();
  }
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
  std::size_t toSeparator = 0;  // the second half's rows in the separator, for the solve
  for (int s = superSecond_; s < superSeparator_; ++s) {
    const auto us = static_cast<std::size_t>(s);
    const int w = superFirst_[us + 1] - superFirst_[us];
    for (int r = w; r < superHeight_[us]; ++r)
      if (li_[static_cast<std::size_t>(superStart_[us] + r)] >= separatorFrom) ++toSeparator;
  }
  workspace_[1].toSeparator.reserve(toSeparator);

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
  // Split: the halves' supernodes on two threads (or one after the other), their waits on the
  // separator added to its lists afterwards in the order one thread would have added them (the
  // first half's, then the second's), then the separator.
  const double* values = A.valuePtr();
  const int ns = static_cast<int>(superFirst_.size() > 0 ? superFirst_.size() - 1 : 0);
  std::fill(firstUpdate_.begin(), firstUpdate_.end(), -1);
  Status status[2] = {Status::Ok, Status::Ok};
  auto half = [&](int h) {
    status[h] = h == 0 ? factorizeRange(values, 0, superSecond_, superSeparator_, workspace_[0])
                       : factorizeRange(values, superSecond_, superSeparator_, superSeparator_,
                                        workspace_[1]);
  };
  if (threads_ > 1 && superSecond_ < superSeparator_) {
#pragma omp parallel num_threads(2)
    {
#ifdef _OPENMP
      if (omp_get_num_threads() == 2) {
        half(omp_get_thread_num());
      } else {
        half(0);
        half(1);
      }
#else
      half(0);
      half(1);
#endif
    }
  } else {
    half(0);
    half(1);
  }
  if (!ok(status[0]) || !ok(status[1])) return Status::Singular;
  addWaiting(workspace_[0]);
  addWaiting(workspace_[1]);
  return factorizeRange(values, superSeparator_, ns, ns, workspace_[0]);
}

void SparseLdlt::addWaiting(Workspace& ws) {
  for (const auto& [k, t] : ws.waiting) {
    nextUpdate_[static_cast<std::size_t>(k)] = firstUpdate_[static_cast<std::size_t>(t)];
    firstUpdate_[static_cast<std::size_t>(t)] = k;
  }
  ws.waiting.clear();
}

Status SparseLdlt::factorizeRange(const double* values, int begin, int end, int deferFrom,
                                  Workspace& ws) {
  ws.waiting.clear();
  double* dd = d_.data();
  double* product = ws.gather.data();  // one column of a descendant's update
  int* relative = ws.relative.data();
  // Supernode k waits next for supernode t (t's list, or the deferred waits).
  auto wait = [&](int k, int t) {
    if (t >= deferFrom) {
      ws.waiting.emplace_back(k, t);
      return;
    }
    nextUpdate_[static_cast<std::size_t>(k)] = firstUpdate_[static_cast<std::size_t>(t)];
    firstUpdate_[static_cast<std::size_t>(t)] = k;
  };
  for (int si = begin; si < end; ++si) {
    const auto s = static_cast<std::size_t>(si);
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    double* block = lx_.data() + superStart_[s];
    const int* rows = li_.data() + superStart_[s];
    // The block's values of A (its fill and the unused upper part of its diagonal block zero).
    std::fill(block, block + static_cast<std::ptrdiff_t>(w) * h, 0.0);
    for (int e = scatterStart_[s]; e < scatterStart_[s + 1]; ++e) {
      const auto& [from, to] = scatter_[static_cast<std::size_t>(e)];
      lx_[static_cast<std::size_t>(to)] = values[static_cast<std::size_t>(from)];
    }
    for (int r = 0; r < h; ++r) relative[r < w ? f + r : rows[r]] = r;
    // Updates from the descendants: with Lk their rows from the first in s's columns down,
    // block(rows, cols) -= Lk D Lk(cols)^T over the rows of Lk in s's columns.
    for (int k = firstUpdate_[s]; k >= 0;) {
      const auto uk = static_cast<std::size_t>(k);
      const int next = nextUpdate_[uk];
      const int fk = superFirst_[uk], wk = superFirst_[uk + 1] - fk, hk = superHeight_[uk];
      const double* blockK = lx_.data() + superStart_[uk];
      const int* rowsK = li_.data() + superStart_[uk];
      const int first = updateRow_[uk];
      int last = first;  // one past the last row of Lk in s's columns
      while (last < hk && rowsK[last] < f + w) ++last;
      for (int c = first; c < last; ++c) {
        // Column rowsK[c] of s, rows from rowsK[c] down: product = Lk(c.., :) D Lk(c, :)^T, one
        // contiguous multiply-add per column of the descendant (short columns: plain loops beat
        // a library product's set-up here).
        const int rowsFromC = hk - c;
        std::fill(product, product + rowsFromC, 0.0);
        addColumnProducts(blockK + c, hk, wk, dd + fk, rowsFromC, product);
        double* column = block + static_cast<std::ptrdiff_t>(rowsK[c] - f) * h;
        for (int r = 0; r < rowsFromC; ++r) column[relative[rowsK[c + r]]] -= product[r];
      }
      // The descendant waits next for the supernode of its first row below s's columns.
      updateRow_[uk] = last;
      if (last < hk) wait(k, colSuper_[static_cast<std::size_t>(rowsK[last])]);
      k = next;
    }
    // Dense L D L^T of the block, column by column (left-looking): the updates of column j by
    // the columns before it (rows from the diagonal down), the pivot, and the column of L below
    // it. Each entry takes its updates in column order, as in the right-looking order of the
    // textbook (each column updating all later ones at once), so the same numbers.
    for (int j = 0; j < w; ++j) {
      double* column = block + static_cast<std::ptrdiff_t>(j) * h;
      subtractColumnProducts(block, h, j, dd + f, column);
      const double dj = column[j];
      if (!(dj != 0.0) || !std::isfinite(dj)) return Status::Singular;
      dd[f + j] = dj;
      for (int r = j + 1; r < h; ++r) column[r] /= dj;
    }
    if (h > w) {
      updateRow_[s] = w;
      wait(si, colSuper_[static_cast<std::size_t>(rows[w])]);
    }
  }
  return Status::Ok;
}

void SparseLdlt::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) {
  Eigen::VectorXd& z = work_;
  for (int i = 0; i < n_; ++i) z(perm_[static_cast<std::size_t>(i)]) = b(i);
  const int ns = static_cast<int>(superFirst_.size() > 0 ? superFirst_.size() - 1 : 0);
  // Split: the halves' forward substitutions at once, the second's contributions to the
  // separator's rows added after the first's (the order of one thread), the separator both
  // ways, then the halves' backward substitutions at once.
  const int separatorRow = split_.first + split_.second;
  auto forwardHalf = [&](int h) {
    if (h == 0)
      forwardRange(0, superSecond_, -1, workspace_[0]);
    else
      forwardRange(superSecond_, superSeparator_, separatorRow, workspace_[1]);
  };
  auto backwardHalf = [&](int h) {
    if (h == 0)
      backwardRange(0, superSecond_, workspace_[0]);
    else
      backwardRange(superSecond_, superSeparator_, workspace_[1]);
  };
  auto separator = [&] {
    for (const auto& [row, value] : workspace_[1].toSeparator) z(row) += value;
    workspace_[1].toSeparator.clear();
    forwardRange(superSeparator_, ns, -1, workspace_[0]);
    z.array() /= d_.array();
    backwardRange(superSeparator_, ns, workspace_[0]);
  };
  auto inTurn = [&] {
    forwardHalf(0);
    forwardHalf(1);
    separator();
    backwardHalf(0);
    backwardHalf(1);
  };
  if (threads_ > 1 && superSecond_ < superSeparator_) {
#pragma omp parallel num_threads(2)
    {
#ifdef _OPENMP
      const bool two = omp_get_num_threads() == 2;
      const int h = omp_get_thread_num();
#else
      const bool two = false;
      const int h = 0;
#endif
      if (two) {
        forwardHalf(h);
#pragma omp barrier
#pragma omp single
        separator();
        backwardHalf(h);
      } else {
        inTurn();
      }
    }
  } else {
    inTurn();
  }
  if (x.size() != n_) x.resize(n_);
  for (int i = 0; i < n_; ++i) x(i) = z(perm_[static_cast<std::size_t>(i)]);
}

void SparseLdlt::forwardRange(int begin, int end, int deferRowsFrom, Workspace& ws) {
  Eigen::VectorXd& z = work_;
  double* y = ws.gather.data();  // a supernode's rows: its own columns, then the rows below
  // L z = P b, supernode by supernode: y holds the supernode's part of z and the updates of the
  // rows below it.
  for (int si = begin; si < end; ++si) {
    const auto s = static_cast<std::size_t>(si);
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    const int* rows = li_.data() + superStart_[s];  // rows[r] of block row r >= w
    for (int r = 0; r < w; ++r) y[r] = z(f + r);
    std::fill(y + w, y + h, 0.0);
    forwardInBlock(lx_.data() + superStart_[s], w, h, y);
    for (int r = 0; r < w; ++r) z(f + r) = y[r];
    for (int r = w; r < h; ++r) {
      if (deferRowsFrom >= 0 && rows[r] >= deferRowsFrom)
        ws.toSeparator.emplace_back(rows[r], y[r]);
      else
        z(rows[r]) += y[r];
    }
  }
}

void SparseLdlt::backwardRange(int begin, int end, Workspace& ws) {
  Eigen::VectorXd& z = work_;
  double* y = ws.gather.data();
  // L^T z = z, in reverse: each column's entry less its dot product with the rows below.
  for (int si = end; si-- > begin;) {
    const auto s = static_cast<std::size_t>(si);
    const int f = superFirst_[s], w = superFirst_[s + 1] - f, h = superHeight_[s];
    const int* rows = li_.data() + superStart_[s];
    for (int r = 0; r < w; ++r) y[r] = z(f + r);
    for (int r = w; r < h; ++r) y[r] = z(rows[r]);
    backwardInBlock(lx_.data() + superStart_[s], w, h, y);
    for (int r = 0; r < w; ++r) z(f + r) = y[r];
  }
}

}  // namespace dabs::analysis
