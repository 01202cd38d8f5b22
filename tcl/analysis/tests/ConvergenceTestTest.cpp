// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/ConvergenceTest.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dabs::analysis {
namespace {

TEST(ConvergenceTestTest, NormsAreTheOnesOpenSeesUses) {
  Eigen::VectorXd x(2), b(2);
  x << 3.0, 4.0;
  b << 1.0, -2.0;
  ConvergenceTest disp(ConvergenceTest::Kind::NormDispIncr, 1e-12, 5);
  disp.start();
  (void)disp.test(x, b);
  EXPECT_DOUBLE_EQ(disp.lastNorm(), 5.0);  // 2-norm of the increment
  ConvergenceTest unbalance(ConvergenceTest::Kind::NormUnbalance, 1e-12, 5);
  unbalance.start();
  (void)unbalance.test(x, b);
  EXPECT_DOUBLE_EQ(unbalance.lastNorm(), std::sqrt(5.0));
  ConvergenceTest energy(ConvergenceTest::Kind::EnergyIncr, 1e-12, 5);
  energy.start();
  (void)energy.test(x, b);
  EXPECT_DOUBLE_EQ(energy.lastNorm(), 0.5 * std::abs(3.0 - 8.0));
  ConvergenceTest maxNorm(ConvergenceTest::Kind::NormDispIncr, 1e-12, 5, 0, 0);
  maxNorm.start();
  (void)maxNorm.test(x, b);
  EXPECT_DOUBLE_EQ(maxNorm.lastNorm(), 4.0);
}

TEST(ConvergenceTestTest, FailsAfterMaxIterationsUnlessPrintFlagAccepts) {
  Eigen::VectorXd x = Eigen::VectorXd::Ones(1), b = Eigen::VectorXd::Ones(1);
  ConvergenceTest t(ConvergenceTest::Kind::NormDispIncr, 1e-6, 2);
  t.start();
  EXPECT_EQ(t.test(x, b), ConvergenceTest::Result::Continue);
  EXPECT_EQ(t.test(x, b), ConvergenceTest::Result::Failed);
  ConvergenceTest accept(ConvergenceTest::Kind::NormDispIncr, 1e-6, 1, 5);
  accept.start();
  EXPECT_EQ(accept.test(x, b), ConvergenceTest::Result::Converged);
  Eigen::VectorXd nan = Eigen::VectorXd::Constant(1, NAN);
  t.start();
  EXPECT_EQ(t.test(nan, b), ConvergenceTest::Result::Failed);
}

}  // namespace
}  // namespace dabs::analysis
