// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/SparseCore>
#include <vector>

namespace dabs::analysis {

/// The sparse pattern of an assembled matrix and the place of each coupling in its value array:
/// the analysis notes every pair of coupled equations once per model change, builds the
/// compressed matrix, and keeps each element entry's value index, so assembly is an indexed add
/// (style.md section 10).
class AssemblyPattern {
 public:
  /// Notes that equations `row` and `col` are coupled (repeats are merged).
  void couple(int row, int col) { entries_.emplace_back(row, col, 0.0); }
  /// The compressed n x n matrix of the noted couplings and the whole diagonal, values zero;
  /// forgets the notes.
  Eigen::SparseMatrix<double> build(int n);
  /// Index of entry (row, col) in A.valuePtr(), found by a binary search in the column's sorted
  /// row indices: no row * n + column product, which would overflow an int past 46,340
  /// equations. The entry must be in the pattern.
  static int valueIndex(const Eigen::SparseMatrix<double>& A, int row, int col);

 private:
  std::vector<Eigen::Triplet<double>> entries_;
};

}  // namespace dabs::analysis
