// SPDX-License-Identifier: MIT
// The step loop of the analysis builder on a cubic spring f(u) = k u + c u^3 under load control:
// converged steps reach the root of f(u) = lambda P found here by scalar Newton; a step that
// fails (a test allowing one iteration) returns a negative code, is counted, and leaves the model
// at the last converged step; components replaced between analyze calls take effect.
#include "tcl/analysis/driver/AnalysisBuilder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

constexpr double kK = 100.0, kC = 500.0, kP = 25.0, kDLambda = 0.25;

/// Root of k u + c u^3 = p (scalar Newton, converged to round-off).
double root(double p) {
  double u = 0.0;
  for (int i = 0; i < 100; ++i) u -= (kK * u + kC * u * u * u - p) / (kK + 3.0 * kC * u * u);
  return u;
}

TEST(AnalysisBuilderTest, FailedStepIsReportedAndLeavesTheLastConvergedStep) {
  domain::Domain domain;
  testing::buildSpring(domain, std::make_unique<testing::CubicSpring>(kK, kC), 0.0, kP);
  AnalysisBuilder builder(domain);
  builder.setTest(testing::dispTest(1e-12, 50));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  builder.setIntegrator(std::make_unique<LoadControl>(kDLambda, 1, kDLambda, kDLambda));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder.analyze(2, 0.0), 0);
  const double u2 = root(2.0 * kDLambda * kP);
  EXPECT_NEAR(domain.node(2).disp(0), u2, 1e-14);
  EXPECT_EQ(builder.statistics().steps, 2);

  builder.setTest(testing::dispTest(1e-12, 1));  // one Newton iteration cannot reach 1e-12
  EXPECT_LT(builder.analyze(1, 0.0), 0);
  EXPECT_EQ(builder.statistics().failedSteps, 1);
  EXPECT_NEAR(domain.committedTime(), 2.0 * kDLambda, 1e-14);
  EXPECT_NEAR(domain.node(2).disp(0), u2, 1e-14);
  EXPECT_NEAR(domain.node(2).committedDisp(0), u2, 1e-14);

  builder.setTest(testing::dispTest(1e-12, 50));  // the next analyze continues from there
  ASSERT_EQ(builder.analyze(2, 0.0), 0);
  EXPECT_NEAR(domain.node(2).disp(0), root(4.0 * kDLambda * kP), 1e-14);
  EXPECT_EQ(builder.statistics().steps, 4);
}

}  // namespace
}  // namespace dabs::analysis
