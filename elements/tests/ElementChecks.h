// SPDX-License-Identifier: MIT
#pragma once

// Shared checks for element unit tests (any folder's tests may include this header):
// finite-difference tangents of resistingForce with respect to u and v.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "elements/Element.h"

namespace dabs::elements::testing {

/// Trial kinematics holder, so tests can build Kinematics from plain vectors.
struct TrialState {
  Eigen::VectorXd u, v, a;
  double time = 0.0, dt = 0.0;
  Kinematics kinematics() const { return Kinematics{u, v, a, time, dt}; }
};

/// Central-difference d(resistingForce)/du at `state`, perturbing each dof by h. Each perturbed
/// update starts from the element's committed state (the element contract), and the element is
/// left updated at `state` afterwards.
inline Eigen::MatrixXd numericalStiffness(Element& e, const TrialState& state, double h) {
  const int n = e.numDof();
  Eigen::MatrixXd k(n, n);
  TrialState s = state;
  for (int j = 0; j < n; ++j) {
    s.u = state.u;
    s.u(j) += h;
    if (!ok(e.update(s.kinematics()))) return Eigen::MatrixXd::Constant(n, n, NAN);
    const Eigen::VectorXd fp = e.resistingForce();
    s.u(j) -= 2 * h;
    if (!ok(e.update(s.kinematics()))) return Eigen::MatrixXd::Constant(n, n, NAN);
    const Eigen::VectorXd fm = e.resistingForce();
    k.col(j) = (fp - fm) / (2 * h);
  }
  (void)e.update(state.kinematics());
  return k;
}

/// Central-difference d(resistingForce)/dv at `state` (the element's own dashpots).
inline Eigen::MatrixXd numericalDamping(Element& e, const TrialState& state, double h) {
  const int n = e.numDof();
  Eigen::MatrixXd c(n, n);
  TrialState s = state;
  for (int j = 0; j < n; ++j) {
    s.v = state.v;
    s.v(j) += h;
    if (!ok(e.update(s.kinematics()))) return Eigen::MatrixXd::Constant(n, n, NAN);
    const Eigen::VectorXd fp = e.resistingForce();
    s.v(j) -= 2 * h;
    if (!ok(e.update(s.kinematics()))) return Eigen::MatrixXd::Constant(n, n, NAN);
    const Eigen::VectorXd fm = e.resistingForce();
    c.col(j) = (fp - fm) / (2 * h);
  }
  (void)e.update(state.kinematics());
  return c;
}

/// Relative difference of two matrices, scaled by the larger norm (0 when both are zero).
inline double relativeDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  const double scale = std::max({a.norm(), b.norm(), 1e-300});
  return (a - b).norm() / scale;
}

}  // namespace dabs::elements::testing
