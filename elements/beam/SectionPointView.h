// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/beam/SectionInterpolation.h"

namespace dabs::elements {

/// Views of one integration point's section arrays for a beam-column's section loop: fixed-size
/// maps when every section of the element has order `Order` (the arrays then hold Order rows
/// each, stored contiguously, so the products are unrolled instead of going through Eigen's
/// dynamic-size kernels), the arrays themselves when the orders differ (Order = Eigen::Dynamic).
/// The arithmetic is the same either way.
template <int Order, int Nb>
struct SectionPointView {
  using Vec = Eigen::Matrix<double, Order, 1>;
  using Mat = Eigen::Matrix<double, Order, Order>;
  static Eigen::Map<Vec> vec(SectionVector& v) { return Eigen::Map<Vec>(v.data()); }
  static Eigen::Map<const Vec> vec(const SectionVector& v) {
    return Eigen::Map<const Vec>(v.data());
  }
  static Eigen::Map<Mat> mat(SectionMatrix& m) { return Eigen::Map<Mat>(m.data()); }
  static Eigen::Map<const Mat> mat(const SectionMatrix& m) {
    return Eigen::Map<const Mat>(m.data());
  }
  static Eigen::Map<const Eigen::Matrix<double, Order, Nb>> interp(
      const SectionBasicMatrix<Nb>& b) {
    return Eigen::Map<const Eigen::Matrix<double, Order, Nb>>(b.data());
  }
};

template <int Nb>
struct SectionPointView<Eigen::Dynamic, Nb> {
  using Vec = SectionVector;
  using Mat = SectionMatrix;
  static SectionVector& vec(SectionVector& v) { return v; }
  static const SectionVector& vec(const SectionVector& v) { return v; }
  static SectionMatrix& mat(SectionMatrix& m) { return m; }
  static const SectionMatrix& mat(const SectionMatrix& m) { return m; }
  static const SectionBasicMatrix<Nb>& interp(const SectionBasicMatrix<Nb>& b) { return b; }
};

}  // namespace dabs::elements
