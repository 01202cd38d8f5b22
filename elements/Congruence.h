// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

namespace dabs::elements {

/// B^T k B for fixed-size B (rows: the basic or local system, columns: the element's dofs) by
/// coefficient-based (unrolled) products. At an element's sizes (12 x 6 x 12) Eigen's default is
/// its general blocked matrix product, whose packing costs several times the arithmetic.
template <class BDerived, class KDerived>
Eigen::Matrix<double, BDerived::ColsAtCompileTime, BDerived::ColsAtCompileTime> congruence(
    const Eigen::MatrixBase<BDerived>& b, const Eigen::MatrixBase<KDerived>& k) {
  const Eigen::Matrix<double, BDerived::ColsAtCompileTime, BDerived::RowsAtCompileTime> bk =
      b.transpose().lazyProduct(k);
  Eigen::Matrix<double, BDerived::ColsAtCompileTime, BDerived::ColsAtCompileTime> result;
  result.noalias() = bk.lazyProduct(b);
  return result;
}

}  // namespace dabs::elements
