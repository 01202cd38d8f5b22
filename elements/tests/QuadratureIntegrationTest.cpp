// SPDX-License-Identifier: MIT
// Beam integration rules: weights sum to 1 and polynomials up to the rule's degree are exact.
#include <gtest/gtest.h>

#include <cmath>

#include "elements/beam/QuadratureIntegration.h"
#include "materials/InputError.h"

namespace dabs::elements {
namespace {

constexpr double kTol = 1e-13;

/// Quadrature of xi^k over [0, 1] versus the exact 1/(k+1).
double error(const BeamIntegration& r, int k) {
  const auto x = r.locations(1.0), w = r.weights(1.0);
  double s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) s += w[i] * std::pow(x[i], k);
  return std::abs(s - 1.0 / (k + 1));
}

TEST(QuadratureIntegrationTest, ExactToTheRuleDegree) {
  using R = QuadratureIntegration::Rule;
  for (int n = 2; n <= 10; ++n) {
    const QuadratureIntegration lob(1, R::Lobatto, 1, n), leg(1, R::Legendre, 1, n),
        rad(1, R::Radau, 1, n), nc(1, R::NewtonCotes, 1, n);
    for (int k = 0; k <= 2 * n - 3; ++k) EXPECT_LT(error(lob, k), kTol) << n << " " << k;
    for (int k = 0; k <= 2 * n - 1; ++k) EXPECT_LT(error(leg, k), kTol) << n << " " << k;
    for (int k = 0; k <= 2 * n - 2; ++k) EXPECT_LT(error(rad, k), kTol) << n << " " << k;
    for (int k = 0; k <= n - 1; ++k) EXPECT_LT(error(nc, k), 1e-11) << n << " " << k;
    // One degree more is not exact (the rules are what they claim, not better).
    if (n <= 4) {
      EXPECT_GT(error(leg, 2 * n), 1e-10) << n;
    }
    EXPECT_DOUBLE_EQ(lob.locations(1.0).front(), 0.0);
    EXPECT_DOUBLE_EQ(lob.locations(1.0).back(), 1.0);
    EXPECT_DOUBLE_EQ(rad.locations(1.0).front(), 0.0);
  }
  // Lobatto 3 points is Simpson's rule.
  const QuadratureIntegration s(1, R::Lobatto, 1, 3);
  EXPECT_NEAR(s.weights(1.0)[1], 4.0 / 6.0, kTol);
  EXPECT_THROW(QuadratureIntegration(1, R::Lobatto, 1, 1), InputError);
}

TEST(QuadratureIntegrationTest, HingeRadauWeightsAndLocations) {
  // Scott & Fenves (2006): hinge points at 0 and 8/3 lp with weights lp and 3 lp; interior
  // two-point Gauss on [4 lpI, L - 4 lpJ]; weights sum to L.
  const double length = 10.0, lpI = 0.5, lpJ = 0.75;
  const HingeRadauIntegration h(1, 1, lpI, 2, lpJ, 3);
  const auto x = h.locations(length), w = h.weights(length);
  ASSERT_EQ(x.size(), 6u);
  double sum = 0.0;
  for (double v : w) sum += v;
  EXPECT_NEAR(sum, 1.0, kTol);
  EXPECT_NEAR(w[0] * length, lpI, kTol);
  EXPECT_NEAR(w[5] * length, lpJ, kTol);
  EXPECT_NEAR(x[1] * length, 8.0 / 3.0 * lpI, kTol);
  EXPECT_NEAR(x[4] * length, length - 8.0 / 3.0 * lpJ, kTol);
  // Linear functions are integrated exactly over the whole element.
  double lin = 0.0;
  for (int i = 0; i < 6; ++i) lin += w[i] * x[i];
  EXPECT_NEAR(lin, 0.5, kTol);
  // Hinge sections only at the ends; the points at 8/3 lp are elastic (Scott & Fenves 2006).
  EXPECT_EQ(h.sectionTags(), (std::vector<int>{1, 3, 3, 3, 3, 2}));
}

}  // namespace
}  // namespace dabs::elements
