// SPDX-License-Identifier: MIT
// Arc-length control on a bilinear hardening spring: every converged step lies on the spring's
// force-displacement polyline at arc distance s from the last one, measured with the weights of
// the constraint wU du^2 + wF dlambda^2 = s^2, which fixes each point in closed form.
#include "tcl/analysis/integrators/ArcLength.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/Steel01.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

constexpr double kK = 100.0, kFy = 10.0, kB = 0.1, kP0 = 2.0;
constexpr double kUy = kFy / kK;

// Load factor on the spring's monotonic curve at displacement u (force / P0).
double lambdaAt(double u) { return (u <= kUy ? kK * u : kFy + kB * kK * (u - kUy)) / kP0; }

// The next point along the curve at weighted distance s from (u0, lambda0): bisection on
// g(u) = wU (u-u0)^2 + wF (lambda(u)-lambda0)^2 - s^2, increasing in u beyond u0.
double nextU(double u0, double wU, double wF, double s) {
  auto g = [&](double u) {
    const double dl = lambdaAt(u) - lambdaAt(u0);
    return wU * (u - u0) * (u - u0) + wF * dl * dl - s * s;
  };
  double lo = u0, hi = u0 + s / std::sqrt(wU);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

void traceSpring(double wU, double wF, bool loadScaled, double s) {
  domain::Domain domain;
  materials::Steel01::Params p{kFy, kK, kB};
  testing::buildSpring(domain, std::make_unique<materials::Steel01>(1, p), 0.0, kP0);
  AnalysisBuilder builder(domain);
  builder.setConstraints(ConstraintKind::Plain);
  builder.setTest(
      std::make_unique<ConvergenceTest>(ConvergenceTest::Kind::NormDispIncr, 1e-13, 50));
  builder.setIntegrator(std::make_unique<ArcLength>(s, wU, wF, loadScaled));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  const double wFe = loadScaled ? wF * kP0 * kP0 : wF;
  double u = 0.0;
  bool crossedYield = false;
  for (int step = 1; step <= 12; ++step) {
    ASSERT_EQ(builder.analyze(1, 0.0), 0) << "step " << step;
    const double expected = nextU(u, wU, wFe, s);
    crossedYield = crossedYield || (u < kUy && expected > kUy);
    u = expected;
    EXPECT_NEAR(domain.node(2).disp(0), u, 1e-9 * u) << "step " << step;
    EXPECT_NEAR(domain.committedTime(), lambdaAt(u), 1e-9 * lambdaAt(u)) << "step " << step;
  }
  EXPECT_TRUE(crossedYield);  // the path turned the corner within the steps checked
}

// `integrator ArcLength s alpha`: dU.dU + alpha^2 dlambda^2 = s^2.
TEST(ArcLengthTest, ArcLengthFollowsTheSpringAcrossYield) {
  traceSpring(1.0, 0.04 * 0.04, false, 0.03);
}

// `integrator HSConstraint s psiU psiF uRef`: psiU^2/uRef^2 dU.dU + psiF^2 phat.phat dlambda^2 =
// s^2.
TEST(ArcLengthTest, HSConstraintWeightsDisplacementAndLoad) {
  const double psiU = 2.0, uRef = 0.5, psiF = 0.01;
  traceSpring(psiU * psiU / (uRef * uRef), psiF * psiF, true, 0.08);
}

}  // namespace
}  // namespace dabs::analysis
