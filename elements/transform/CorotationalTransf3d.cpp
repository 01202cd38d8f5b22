// SPDX-License-Identifier: MIT
#include "elements/transform/CorotationalTransf3d.h"

#include <cmath>

#include "elements/transform/Dual.h"

namespace dabs::elements {

namespace {

template <class S>
using V3 = std::array<S, 3>;
template <class S>
using M3 = std::array<S, 9>;  // row-major

template <class S>
V3<S> cross(const V3<S>& a, const V3<S>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class S>
S dot(const V3<S>& a, const V3<S>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
template <class S>
V3<S> scaled(const S& s, const V3<S>& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

/// exp of a rotation vector (Rodrigues): I + a [psi]x + b [psi]x^2, a = sin t/t, b = (1-cos t)/t^2,
/// written in t^2 with a Taylor series near 0 so that derivatives stay finite at psi = 0.
template <class S>
M3<S> expRotation(const V3<S>& psi) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const S t2 = dot(psi, psi);
  S a, b;
  if (value(t2) < 1e-4) {
    // sin t/t = sum (-t2)^k/(2k+1)!, (1 - cos t)/t2 = sum (-t2)^k/(2k+2)!
    a = S(1.0) - (1.0 / 6.0) * t2 + (1.0 / 120.0) * (t2 * t2) - (1.0 / 5040.0) * (t2 * t2 * t2) +
        (1.0 / 362880.0) * (t2 * t2 * t2 * t2);
    b = S(0.5) - (1.0 / 24.0) * t2 + (1.0 / 720.0) * (t2 * t2) - (1.0 / 40320.0) * (t2 * t2 * t2) +
        (1.0 / 3628800.0) * (t2 * t2 * t2 * t2);
  } else {
    const S t = sqrt(t2);
    a = sin(t) / t;
    b = (S(1.0) - cos(t)) / t2;
  }
  const S &x = psi[0], &y = psi[1], &z = psi[2];
  // [psi]x^2 = psi psi^T - t2 I
  return {S(1.0) + b * (x * x - t2), b * (x * y) - a * z,       b * (x * z) + a * y,
          b * (y * x) + a * z,       S(1.0) + b * (y * y - t2), b * (y * z) - a * x,
          b * (z * x) - a * y,       b * (z * y) + a * x,       S(1.0) + b * (z * z - t2)};
}

/// log of a rotation matrix as a rotation vector: w = axial(R - R^T)/2 = sin(phi) n, phi =
/// atan2(|w|, (tr R - 1)/2), theta = phi/sin(phi) w; series in |w|^2 near 0 (asin(s)/s).
template <class S>
V3<S> logRotation(const M3<S>& r) {
  using std::atan2;
  using std::sqrt;
  const V3<S> w{0.5 * (r[7] - r[5]), 0.5 * (r[2] - r[6]), 0.5 * (r[3] - r[1])};
  const S s2 = dot(w, w);
  const S c = 0.5 * (r[0] + r[4] + r[8] - S(1.0));
  S f;
  if (value(s2) < 1e-4 && value(c) > 0.0) {
    f = S(1.0) + (1.0 / 6.0) * s2 + (3.0 / 40.0) * (s2 * s2) + (5.0 / 112.0) * (s2 * s2 * s2) +
        (35.0 / 1152.0) * (s2 * s2 * s2 * s2);
  } else {
    const S s = sqrt(s2);
    f = atan2(s, c) / s;
  }
  return scaled(f, w);
}

}  // namespace

void CorotationalTransf<3>::initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
  CrdTransf3d::initialize(xi, xj);
  xi_ = xi;
  xj_ = xj;
  revertToStart();
}

template <class S>
std::array<S, 6> CorotationalTransf<3>::kinematics(const std::array<S, 12>& u) const {
  using std::sqrt;
  // Nodal triads R = exp(dpsi) R_c; their images of the undeformed local axes, g[n][a] = R e0_a.
  std::array<std::array<V3<S>, 3>, 2> g;
  for (int n = 0; n < 2; ++n) {
    const int o = 6 * n + 3;
    const V3<S> dpsi{u[o] - S(thetaCommitted_[n](0)), u[o + 1] - S(thetaCommitted_[n](1)),
                     u[o + 2] - S(thetaCommitted_[n](2))};
    const M3<S> dr = expRotation(dpsi);
    const Eigen::Matrix3d rc0 = rotCommitted_[n] * axes_.transpose();  // columns R_c e0_a
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < 3; ++i)
        g[n][a][i] = rc0(0, a) * dr[3 * i] + rc0(1, a) * dr[3 * i + 1] + rc0(2, a) * dr[3 * i + 2];
  }
  // Corotated frame (Battini & Pacoste 2002, eq. 6).
  V3<S> d;
  for (int i = 0; i < 3; ++i) d[i] = S(xj_(i) - xi_(i)) + u[6 + i] - u[i];
  const S ln = sqrt(dot(d, d));
  const V3<S> e1 = scaled(S(1.0) / ln, d);
  V3<S> q;
  for (int i = 0; i < 3; ++i) q[i] = 0.5 * (g[0][1][i] + g[1][1][i]);
  V3<S> e3 = cross(e1, q);
  e3 = scaled(S(1.0) / sqrt(dot(e3, e3)), e3);
  const V3<S> e2 = cross(e3, e1);
  const std::array<V3<S>, 3> e{e1, e2, e3};
  // Local rotations theta = log(E^T R E0): entry (a, b) = e_a . (R e0_b).
  std::array<V3<S>, 2> th;
  for (int n = 0; n < 2; ++n) {
    M3<S> rl;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) rl[3 * a + b] = dot(e[a], g[n][b]);
    th[n] = logRotation(rl);
  }
  return {ln - S(length0_), th[0][2], th[1][2], th[0][1], th[1][1], th[1][0] - th[0][0]};
}

void CorotationalTransf<3>::update(const Global& u) {
  using Inner = Dual<double, 12>;
  using Outer = Dual<Inner, 12>;
  std::array<Outer, 12> x;
  for (int i = 0; i < 12; ++i) {
    x[i].v = Inner(u(i), i);
    x[i].d[i] = Inner(1.0);
  }
  const std::array<Outer, 6> v = kinematics(x);
  for (int k = 0; k < 6; ++k) {
    v_(k) = v[k].v.v;
    for (int i = 0; i < 12; ++i) {
      compat_(k, i) = v[k].v.d[i];
      for (int j = 0; j < 12; ++j) hessian_[k](i, j) = v[k].d[i].d[j];
    }
  }
  uTrial_ = u;
}

CorotationalTransf<3>::GlobalMatrix CorotationalTransf<3>::globalStiffness(const BasicMatrix& kb,
                                                                           const Basic& q) const {
  GlobalMatrix k = congruence(compat_, kb);
  for (int i = 0; i < 6; ++i) k += q(i) * hessian_[i];
  return k;
}

Eigen::Matrix3d CorotationalTransf<3>::nodalTriad(int n) const {
  std::array<double, 3> dpsi;
  for (int i = 0; i < 3; ++i) dpsi[i] = uTrial_(6 * n + 3 + i) - thetaCommitted_[n](i);
  const std::array<double, 9> dr = expRotation(dpsi);
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = dr[3 * i + j];
  return r * rotCommitted_[n];
}

void CorotationalTransf<3>::commitState() {
  for (int n = 0; n < 2; ++n) {
    rotCommitted_[n] = nodalTriad(n);
    thetaCommitted_[n] = uTrial_.segment<3>(6 * n + 3);
  }
}

void CorotationalTransf<3>::revertToStart() {
  for (int n = 0; n < 2; ++n) {
    rotCommitted_[n].setIdentity();
    thetaCommitted_[n].setZero();
  }
  update(Global::Zero());
}

template std::array<double, 6> CorotationalTransf<3>::kinematics(
    const std::array<double, 12>&) const;

}  // namespace dabs::elements
