// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <utility>
#include <vector>

#include "materials/Status.h"

namespace dabs::analysis {

/// Sparse L D L^T of a symmetric matrix: AMD order, elimination tree and column counts as in
/// Davis (2005), "Algorithm 849: A concise sparse Cholesky factorization package", ACM TOMS 31(4);
/// the numeric factorisation by supernodes, left-looking (Ng & Peyton 1993, "Block sparse
/// Cholesky algorithms on advanced uniprocessor computers", SIAM J. Sci. Comput. 14(5)).
///
/// analyze() takes the matrix's full (symmetric) pattern once: the fill-reducing order (AMD, or the
/// split order below), the elimination tree, the column counts and the rows of L, the supernodes,
/// and a map from each value of the given matrix on or above the diagonal of P A P^T to its mirror
/// place in L's storage. factorize() then scatters the values through that map and factorises with
/// no permutation pass and no allocation, and solve() allocates nothing once x has its size. No
/// pivoting: stable for definite matrices.
///
/// L is stored by supernodes: consecutive columns with the same pattern below the diagonal block
/// (column j+1 is j's parent and has one entry fewer; Liu, Ng & Peyton 1993, "On finding
/// supernodes for sparse matrix computations", SIAM J. Matrix Anal. Appl. 14(1)) share one dense
/// column-major block whose rows are the supernode's own columns and then its common rows below.
/// The factorisation updates a block by each descendant block with one dense product per column
/// and factorises it densely, instead of one short sparse loop per entry of L; the solve gathers a
/// supernode's rows once into a dense work vector and updates it column by column with
/// contiguous vector operations, so it reads each row index once per supernode instead of once per
/// entry (a 6-dof node gives at least 6 columns).
///
/// A matrix whose graph a small set of equations cuts into two halves of about equal size (a
/// long bridge: one cross-section of its middle) is ordered as the two halves and then that
/// separator, each by constrained minimum degree (CAMD; a one-level nested dissection, George
/// 1973, "Nested dissection of a regular finite element mesh", SIAM J. Numer. Anal. 10(2)): the
/// halves' columns then update only their own half and the separator, so two threads factorise
/// and solve them at once (setThreads). The order depends on the pattern alone, and the
/// updates of the separator are applied in the order one thread applies them, so the factors
/// and solutions are the same bit for bit at any thread count.
class SparseLdlt {
 public:
  /// Symbolic analysis of `A`'s pattern, which must be structurally symmetric with every
  /// diagonal entry present (the assembled stiffness pattern is).
  void analyze(const Eigen::SparseMatrix<double>& A);
  /// Numeric factorisation of a matrix with the analysed pattern (values in the same order as
  /// A.valuePtr() of the analysed matrix). Status::Singular on a zero or non-finite pivot.
  [[nodiscard]] Status factorize(const Eigen::SparseMatrix<double>& A);
  /// Solves A x = b with the last factorisation.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x);
  /// Threads for the two halves of a split order (1: one after the other). Results do not
  /// depend on it.
  void setThreads(int threads) noexcept { threads_ = threads < 1 ? 1 : threads; }
  /// Equations in the first half, the second half and the separator of a split order (all in
  /// the first when the order is not split).
  struct Split {
    int first = 0, second = 0, separator = 0;
  };
  Split split() const noexcept { return split_; }

  /// Pivots D of the last factorisation (in the permuted order).
  const Eigen::VectorXd& pivots() const noexcept { return d_; }
  int size() const noexcept { return n_; }
  /// Nonzeros of L below the diagonal.
  int factorNonZeros() const noexcept { return factorNonZeros_; }
  /// Number of supernodes of L.
  int supernodes() const noexcept {
    return superFirst_.empty() ? 0 : static_cast<int>(superFirst_.size()) - 1;
  }

 private:
  int n_ = 0;
  std::vector<int> perm_;  ///< new index of old row i
  /// (index in A's values, place in lx_) of each value on or above the diagonal of P A P^T, by
  /// supernode
  std::vector<std::pair<int, int>> scatter_;
  std::vector<int> scatterStart_;  ///< supernode s's entries of scatter_ start here
  std::vector<int> parent_;        ///< elimination tree
  /// L's strictly lower part: column j's row indices (ascending) and values start at
  /// colStart_[j] in li_ and lx_ (inside its supernode's block, below the block's diagonal).
  std::vector<int> colStart_, li_;
  std::vector<double> lx_;
  int factorNonZeros_ = 0;
  /// Supernode s holds columns superFirst_[s] .. superFirst_[s+1]-1; its block (height
  /// superHeight_[s], column-major) starts at superStart_[s] in lx_ and li_.
  std::vector<int> superFirst_, superHeight_, superStart_;
  std::vector<int> colSuper_;  ///< supernode of each column
  Eigen::VectorXd d_;
  // Workspace of the factorisation, per supernode: the first of the descendants waiting to
  // update it, the next one in the list of the supernode it waits for, and the first of its rows
  // not yet applied.
  std::vector<int> firstUpdate_, nextUpdate_, updateRow_;
  Eigen::VectorXd work_;
  /// What each of the two halves' threads needs of its own: the block row of each row index in
  /// the supernode being factorised (relative), room for the tallest supernode's rows (gather),
  /// the waits of its supernodes on the separator's, (supernode, separator supernode) in the
  /// order they arose (waiting), and the second half's contributions to the separator's rows in
  /// the forward solve, (row, value) in order (toSeparator).
  struct Workspace {
    std::vector<int> relative;
    Eigen::VectorXd gather;
    std::vector<std::pair<int, int>> waiting;
    std::vector<std::pair<int, double>> toSeparator;
  };
  Workspace workspace_[2];
  Split split_;
  /// Supernodes [0, superSecond_) hold the first half's columns, [superSecond_, superSeparator_)
  /// the second's and the rest the separator's (all in the first half when not split).
  int superSecond_ = 0, superSeparator_ = 0;
  int threads_ = 1;

  /// Factorises supernodes [begin, end); the waits of their descendants on supernodes from
  /// `deferFrom` on go to ws.waiting instead of those supernodes' lists.
  [[nodiscard]] Status factorizeRange(const double* values, int begin, int end, int deferFrom,
                                      Workspace& ws);
  /// Adds the waits of ws.waiting to the separator supernodes' lists, in order.
  void addWaiting(Workspace& ws);
  /// The forward substitution over supernodes [begin, end); with `deferRowsFrom` >= 0 the
  /// contributions to rows from there on go to ws.toSeparator.
  void forwardRange(int begin, int end, int deferRowsFrom, Workspace& ws);
  /// The backward substitution over supernodes [begin, end), from the last.
  void backwardRange(int begin, int end, Workspace& ws);
};

}  // namespace dabs::analysis
