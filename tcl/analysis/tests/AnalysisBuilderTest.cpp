// SPDX-License-Identifier: MIT
// The step loop of the analysis builder on a cubic spring f(u) = k u + c u^3 under load control:
// converged steps reach the root of f(u) = lambda P found here by scalar Newton; a step that
// fails (a test allowing one iteration) returns a negative code, is counted, and leaves the model
// at the last converged step; components replaced between analyze calls take effect.
#include "tcl/analysis/driver/AnalysisBuilder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "elements/link/ZeroLength.h"
#include "materials/Elastic.h"
#include "tcl/analysis/driver/ThreadChoice.h"
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

// The automatic thread choice is measured on the model's first steps and again after
// kRevisitAfter steps on its choice: the builder times every step, not only the first trial's.
// Whatever the two threads measure on two springs (a clear answer or a second trial), 500 steps
// hold the first decision (by step 42) and the revisit's (by step 482).
TEST(AnalysisBuilderTest, AutomaticThreadsAreMeasuredAgainDuringARun) {
  if (AnalysisModel::availableThreads() < 2) GTEST_SKIP() << "one thread available";
  domain::Domain domain;
  testing::buildSpring(domain, std::make_unique<testing::CubicSpring>(kK, kC), 0.0, kP);
  elements::ZeroLength::Params p;  // a second spring beside the first: two elements to share
  p.nodes = {1, 2};
  p.ndm = 1;
  p.ndf = 1;
  p.dirs = {1};
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  materials::Elastic::Params elastic;
  elastic.E = kK;
  mats.push_back(std::make_unique<materials::Elastic>(2, elastic));
  p.validate(mats.size());
  domain.addElement(std::make_unique<elements::ZeroLength>(2, p, std::move(mats)));
  AnalysisBuilder builder(domain);
  builder.setThreads(0);  // auto
  builder.setTest(testing::dispTest(1e-12, 50));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  constexpr double kStep = 1e-3;
  builder.setIntegrator(std::make_unique<LoadControl>(kStep, 1, kStep, kStep));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  constexpr int kSteps = 500;
  static_assert(kSteps >= ThreadChoice::kWarmUp + 4 * ThreadChoice::kPairs +
                              ThreadChoice::kRevisitAfter + 4 * ThreadChoice::kPairs);
  ASSERT_EQ(builder.analyze(kSteps, 0.0), 0);
  EXPECT_EQ(builder.threadChoice().decisions(), 2);
  const double load = kSteps * kStep * kP;  // two springs in parallel: 2 k u + c u^3 = load
  double u = 0.0;
  for (int i = 0; i < 100; ++i)
    u -= (2.0 * kK * u + kC * u * u * u - load) / (2.0 * kK + 3.0 * kC * u * u);
  EXPECT_NEAR(domain.node(2).disp(0), u, 1e-12);
}

}  // namespace
}  // namespace dabs::analysis
