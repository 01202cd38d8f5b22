// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/AssemblyPattern.h"

#include <algorithm>
#include <cassert>

namespace dabs::analysis {

Eigen::SparseMatrix<double> AssemblyPattern::build(int n) {
  for (int i = 0; i < n; ++i) entries_.emplace_back(i, i, 0.0);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries_.begin(), entries_.end());
  A.makeCompressed();
  entries_.clear();
  entries_.shrink_to_fit();
  return A;
}

int AssemblyPattern::valueIndex(const Eigen::SparseMatrix<double>& A, int row, int col) {
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int* begin = inner + outer[col];
  const int* end = inner + outer[col + 1];
  const int* it = std::lower_bound(begin, end, row);
  assert(it != end && *it == row);
  return static_cast<int>(it - inner);
}

}  // namespace dabs::analysis
