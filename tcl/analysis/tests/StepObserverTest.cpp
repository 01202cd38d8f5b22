// SPDX-License-Identifier: MIT
// Step observers (AnalysisBuilder::addStepObserver) on a cubic spring under load control: each
// is called once per committed step, in the committed state, never after a failed step, and a
// non-zero code it returns stops `analyze` with that code after the step. The step times follow
// from load control's increment.
#include "tcl/analysis/driver/StepObserver.h"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

constexpr double kK = 100.0, kC = 500.0, kP = 25.0, kDLambda = 0.25;

/// Notes the committed time of each call and the trial displacement then (equal to the committed
/// one after a commit); returns `code` from call `stopAt` on (never when 0).
struct CountingObserver final : StepObserver {
  int afterCommit(const domain::Domain& domain, StepContext& context) override {
    times.push_back(domain.committedTime());
    trialEqualsCommitted.push_back(domain.node(2).disp(0) == domain.node(2).committedDisp(0));
    stepsSeen.push_back(context.statistics.steps);
    if (context.log) context.log("observed");
    return stopAt > 0 && static_cast<int>(times.size()) >= stopAt ? code : 0;
  }
  std::vector<double> times;
  std::vector<char> trialEqualsCommitted;
  std::vector<long> stepsSeen;
  int stopAt = 0;
  int code = -7;
};

class StepObserverTest : public ::testing::Test {
 protected:
  StepObserverTest() : builder_(domain_) {
    testing::buildSpring(domain_, std::make_unique<testing::CubicSpring>(kK, kC), 0.0, kP);
    builder_.setTest(testing::dispTest(1e-12, 50));
    builder_.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
    builder_.setIntegrator(std::make_unique<LoadControl>(kDLambda, 1, kDLambda, kDLambda));
    builder_.setAnalysis(AnalysisBuilder::Kind::Static);
    builder_.log = [this](const std::string& line) { lines_.push_back(line); };
  }
  domain::Domain domain_;
  AnalysisBuilder builder_;
  std::vector<std::string> lines_;
};

TEST_F(StepObserverTest, CalledOncePerCommittedStepInTheCommittedState) {
  auto& o = static_cast<CountingObserver&>(
      builder_.addStepObserver(std::make_unique<CountingObserver>()));
  ASSERT_EQ(builder_.analyze(3, 0.0), 0);
  ASSERT_EQ(o.times.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(o.times[i], kDLambda * static_cast<double>(i + 1));
    EXPECT_TRUE(o.trialEqualsCommitted[i]);
    EXPECT_EQ(o.stepsSeen[i], static_cast<long>(i + 1));  // after the step was counted
  }
  EXPECT_EQ(lines_.size(), 3u);  // the analysis' log reaches the observer
}

TEST_F(StepObserverTest, NotCalledAfterAFailedStep) {
  auto& o = static_cast<CountingObserver&>(
      builder_.addStepObserver(std::make_unique<CountingObserver>()));
  ASSERT_EQ(builder_.analyze(1, 0.0), 0);
  builder_.setTest(testing::dispTest(1e-12, 1));  // one Newton iteration cannot reach 1e-12
  EXPECT_LT(builder_.analyze(2, 0.0), 0);
  EXPECT_EQ(builder_.statistics().failedSteps, 1);
  EXPECT_EQ(o.times.size(), 1u);
  builder_.setTest(testing::dispTest(1e-12, 50));
  ASSERT_EQ(builder_.analyze(1, 0.0), 0);
  ASSERT_EQ(o.times.size(), 2u);
  EXPECT_DOUBLE_EQ(o.times[1], 2.0 * kDLambda);
}

TEST_F(StepObserverTest, NonZeroCodeStopsAnalyzeAfterThatStepAndEveryObserverIsCalled) {
  auto& first = static_cast<CountingObserver&>(
      builder_.addStepObserver(std::make_unique<CountingObserver>()));
  auto& second = static_cast<CountingObserver&>(
      builder_.addStepObserver(std::make_unique<CountingObserver>()));
  first.stopAt = 2;
  second.stopAt = 2;
  second.code = -9;  // the first observer's code wins
  EXPECT_EQ(builder_.analyze(5, 0.0), -7);
  EXPECT_EQ(first.times.size(), 2u);
  EXPECT_EQ(second.times.size(), 2u);
  EXPECT_EQ(builder_.statistics().steps, 2);  // the step that stopped it is committed
  EXPECT_DOUBLE_EQ(domain_.committedTime(), 2.0 * kDLambda);
}

TEST_F(StepObserverTest, ObserversOutliveWipe) {
  auto& o = static_cast<CountingObserver&>(
      builder_.addStepObserver(std::make_unique<CountingObserver>()));
  builder_.wipe();
  builder_.setTest(testing::dispTest(1e-12, 50));
  builder_.setIntegrator(std::make_unique<LoadControl>(kDLambda, 1, kDLambda, kDLambda));
  builder_.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder_.analyze(1, 0.0), 0);
  EXPECT_EQ(o.times.size(), 1u);
}

}  // namespace
}  // namespace dabs::analysis
