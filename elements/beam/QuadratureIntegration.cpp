// SPDX-License-Identifier: MIT
#include "elements/beam/QuadratureIntegration.h"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::elements {

namespace {

/// Legendre polynomial P_n(x) and its derivative (three-term recurrence, A&S 22.7.10).
void legendre(int n, double x, double& p, double& dp) {
  double p0 = 1.0, p1 = x;
  if (n == 0) {
    p = 1.0;
    dp = 0.0;
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = pk;
  }
  p = p1;
  dp = n * (x * p1 - p0) / (x * x - 1.0);
}

/// Newton iteration for a root of f from x0 (f given with its derivative).
template <class F>
double newton(F f, double x) {
  for (int it = 0; it < 100; ++it) {
    double v, d;
    f(x, v, d);
    const double dx = v / d;
    x -= dx;
    if (std::abs(dx) < 1e-15) break;
  }
  return x;
}

}  // namespace

QuadratureIntegration::QuadratureIntegration(int tag, Rule rule, int sectionTag, int n)
    : BeamIntegration(tag), rule_(rule), sectionTag_(sectionTag) {
  const int minPoints = (rule == Rule::Lobatto || rule == Rule::NewtonCotes) ? 2 : 1;
  if (n < minPoints || n > 20)
    throw InputError("N", "must be between " + std::to_string(minPoints) + " and 20");
  std::vector<double> x(n), w(n);
  const double pi = std::numbers::pi;
  switch (rule) {
    case Rule::Legendre:  // roots of P_n; w = 2 / ((1 - x^2) P_n'(x)^2) (A&S 25.4.29)
      for (int i = 0; i < n; ++i) {
        const double xi = newton([n](double t, double& v, double& d) { legendre(n, t, v, d); },
                                 -std::cos(pi * (i + 0.75) / (n + 0.5)));
        double p, dp;
        legendre(n, xi, p, dp);
        x[i] = xi;
        w[i] = 2.0 / ((1.0 - xi * xi) * dp * dp);
      }
      break;
    case Rule::Lobatto:  // ends and roots of P'_{n-1}; w = 2 / (n (n-1) P_{n-1}(x)^2) (25.4.32)
      x[0] = -1.0;
      x[n - 1] = 1.0;
      for (int i = 1; i < n - 1; ++i) {
        const int m = n - 1;
        // P'_m root: Newton on g = (1 - t^2) P'_m, g' = -m(m+1) P_m.
        x[i] = newton(
            [m](double t, double& v, double& d) {
              double p, dp;
              legendre(m, t, p, dp);
              v = (1.0 - t * t) * dp;
              d = -m * (m + 1.0) * p;
            },
            -std::cos(pi * i / (n - 1.0)));
      }
      for (int i = 0; i < n; ++i) {
        double p, dp;
        legendre(n - 1, x[i], p, dp);
        w[i] = 2.0 / (n * (n - 1.0) * p * p);
      }
      break;
    case Rule::Radau:  // x0 = -1 and roots of (P_{n-1} + P_n)/(1 + x) (A&S 25.4.31)
      x[0] = -1.0;
      w[0] = 2.0 / (double(n) * n);
      for (int i = 1; i < n; ++i) {
        x[i] = newton(
            [n](double t, double& v, double& d) {
              double a, da, b, db;
              legendre(n - 1, t, a, da);
              legendre(n, t, b, db);
              v = a + b;
              d = da + db;
            },
            -std::cos(pi * (2.0 * i) / (2.0 * n - 1.0)));
        double p, dp;
        legendre(n - 1, x[i], p, dp);
        w[i] = (1.0 - x[i]) / (double(n) * n * p * p);
      }
      break;
    case Rule::NewtonCotes: {  // equally spaced; weights integrate 1, t, ..., t^(n-1) exactly
      Eigen::MatrixXd v(n, n);
      Eigen::VectorXd moments(n);
      for (int i = 0; i < n; ++i) x[i] = -1.0 + 2.0 * i / (n - 1.0);
      for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) v(k, i) = std::pow(x[i], k);
        moments(k) = (k % 2 == 0) ? 2.0 / (k + 1.0) : 0.0;
      }
      const Eigen::VectorXd sol = v.fullPivLu().solve(moments);
      for (int i = 0; i < n; ++i) w[i] = sol(i);
      break;
    }
  }
  xi_.resize(n);
  w_.resize(n);
  for (int i = 0; i < n; ++i) {
    xi_[i] = 0.5 * (x[i] + 1.0);
    w_[i] = 0.5 * w[i];
  }
  // Sort by location (Newton from the Chebyshev guesses already gives ascending order).
}

std::string_view QuadratureIntegration::typeName() const {
  switch (rule_) {
    case Rule::Lobatto: return "Lobatto";
    case Rule::Legendre: return "Legendre";
    case Rule::Radau: return "Radau";
    case Rule::NewtonCotes: return "NewtonCotes";
  }
  return "";
}

HingeRadauIntegration::HingeRadauIntegration(int tag, int secI, double lpI, int secJ, double lpJ,
                                             int secE)
    : BeamIntegration(tag), secI_(secI), secJ_(secJ), secE_(secE), lpI_(lpI), lpJ_(lpJ) {
  // A zero plastic-hinge length gives its end section no weight (the hinge's two points
  // collapse onto the end): the element would carry no plastic rotation there.
  if (!(lpI > 0.0) || !std::isfinite(lpI))
    throw InputError("lpI", "must be a positive plastic-hinge length");
  if (!(lpJ > 0.0) || !std::isfinite(lpJ))
    throw InputError("lpJ", "must be a positive plastic-hinge length");
}

std::vector<double> HingeRadauIntegration::locations(double length) const {
  const double a = 4.0 * lpI_ / length, b = 1.0 - 4.0 * lpJ_ / length;
  const double g = 0.5 / std::sqrt(3.0);
  return {0.0,
          8.0 / 3.0 * lpI_ / length,
          a + (b - a) * (0.5 - g),
          a + (b - a) * (0.5 + g),
          1.0 - 8.0 / 3.0 * lpJ_ / length,
          1.0};
}

std::vector<double> HingeRadauIntegration::weights(double length) const {
  const double a = 4.0 * lpI_ / length, b = 1.0 - 4.0 * lpJ_ / length;
  return {lpI_ / length, 3.0 * lpI_ / length, 0.5 * (b - a),
          0.5 * (b - a), 3.0 * lpJ_ / length, lpJ_ / length};
}

}  // namespace dabs::elements
