// SPDX-License-Identifier: MIT
#pragma once

#include <array>
#include <cmath>

namespace dabs::elements {

/// Forward-mode dual number with N derivative components (Griewank & Walther 2008, Evaluating
/// Derivatives, ch. 3). Nesting Dual<Dual<double, N>, N> gives exact first and second
/// derivatives, used for the consistent tangent of the 3D corotational transformation. Only the
/// operations that transformation needs are defined. Fixed size: no heap allocation.
template <class T, int N>
struct Dual {
  T v{};                 ///< value
  std::array<T, N> d{};  ///< derivatives with respect to the N seeds

  Dual() = default;
  Dual(double x) : v(x) {}  // NOLINT(google-explicit-constructor): constants mix freely
  Dual(const T& x, int seed) : v(x) { d[static_cast<std::size_t>(seed)] = T(1.0); }

  /// Chain rule for a scalar function with value f and derivative df at v.
  static Dual chain(const Dual& a, const T& f, const T& df) {
    Dual r;
    r.v = f;
    for (int i = 0; i < N; ++i) r.d[i] = df * a.d[i];
    return r;
  }
};

template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v + b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v - b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a) {
  Dual<T, N> r;
  r.v = -a.v;
  for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r;
  r.v = a.v * b.v;
  for (int i = 0; i < N; ++i) r.d[i] = a.v * b.d[i] + a.d[i] * b.v;
  return r;
}
template <class T, int N>
Dual<T, N> operator*(double s, const Dual<T, N>& a) {
  Dual<T, N> r;
  r.v = s * a.v;
  for (int i = 0; i < N; ++i) r.d[i] = s * a.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b) {
  const T inv = T(1.0) / b.v;
  Dual<T, N> r;
  r.v = a.v * inv;
  for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - r.v * b.d[i]) * inv;
  return r;
}
template <class T, int N>
Dual<T, N>& operator+=(Dual<T, N>& a, const Dual<T, N>& b) {
  a = a + b;
  return a;
}

template <class T, int N>
Dual<T, N> sqrt(const Dual<T, N>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  return Dual<T, N>::chain(a, s, T(0.5) / s);
}
template <class T, int N>
Dual<T, N> sin(const Dual<T, N>& a) {
  using std::cos;
  using std::sin;
  return Dual<T, N>::chain(a, sin(a.v), cos(a.v));
}
template <class T, int N>
Dual<T, N> cos(const Dual<T, N>& a) {
  using std::cos;
  using std::sin;
  return Dual<T, N>::chain(a, cos(a.v), -sin(a.v));
}
/// atan2(y, x) with d = (x dy - y dx) / (x^2 + y^2).
template <class T, int N>
Dual<T, N> atan2(const Dual<T, N>& y, const Dual<T, N>& x) {
  using std::atan2;
  Dual<T, N> r;
  r.v = atan2(y.v, x.v);
  const T inv = T(1.0) / (x.v * x.v + y.v * y.v);
  for (int i = 0; i < N; ++i) r.d[i] = (x.v * y.d[i] - y.v * x.d[i]) * inv;
  return r;
}

/// Plain value of a (possibly nested) dual number.
inline double value(double x) { return x; }
template <class T, int N>
double value(const Dual<T, N>& a) {
  return value(a.v);
}

}  // namespace dabs::elements
