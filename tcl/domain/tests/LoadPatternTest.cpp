// SPDX-License-Identifier: MIT
// What each load pattern says it applies, through the base class alone: nodal and member loads,
// support dofs and their motion (scaled, constant, or from ground motions), the uniform ground
// acceleration, the fixes a pattern gives back, and whether it has one load factor.
#include "tcl/domain/LoadPattern.h"

#include <gtest/gtest.h>

#include <array>
#include <memory>

#include "tcl/domain/ConstantSeries.h"
#include "tcl/domain/LinearSeries.h"

namespace dabs::domain {
namespace {

TEST(LoadPatternTest, PlainScalesItsSupportsUnlessConstantAndReportsItsNodes) {
  PlainPattern p(1, std::make_shared<LinearSeries>(1, 2.0), 3.0);  // factor 6 t
  p.loads.push_back({4, Eigen::VectorXd::Ones(2)});
  p.prescribed.push_back({5, 1, 0.5, false});
  p.prescribed.push_back({6, 0, 0.25, true});
  const LoadPattern& base = p;
  EXPECT_EQ(base.nodalLoads().size(), 1u);
  EXPECT_TRUE(base.elementLoads().empty());
  ASSERT_EQ(base.supportCount(), 2u);
  const auto dofs = base.supportDofs();
  EXPECT_EQ(dofs[0].node, 5);
  EXPECT_EQ(dofs[0].dof, 1);
  EXPECT_FALSE(dofs[1].imposedMotion);
  std::array<SupportMotion, 2> motion;
  base.supportMotion(0.5, motion);
  EXPECT_DOUBLE_EQ(motion[0].disp, 0.5 * 6.0 * 0.5);
  EXPECT_DOUBLE_EQ(motion[1].disp, 0.25);
  EXPECT_DOUBLE_EQ(motion[0].vel, 0.0);
  EXPECT_TRUE(base.usesNode(4));
  EXPECT_TRUE(base.usesNode(6));
  EXPECT_FALSE(base.usesNode(7));
  EXPECT_FALSE(base.groundAcceleration(0.5).has_value());
  EXPECT_TRUE(base.hasFactor());
  EXPECT_EQ(p.asPlain(), &p);
  EXPECT_EQ(p.asMultipleSupport(), nullptr);
}

TEST(LoadPatternTest, UniformExcitationIsAGroundAccelerationInItsDirection) {
  UniformExcitation p(2, 1, std::make_shared<LinearSeries>(1, 1.0), 9.81, 0.0);
  const auto a = static_cast<const LoadPattern&>(p).groundAcceleration(0.2);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->dof, 1);
  EXPECT_DOUBLE_EQ(a->value, 9.81 * 0.2);
  EXPECT_EQ(p.supportCount(), 0u);
  EXPECT_EQ(p.asPlain(), nullptr);
}

TEST(LoadPatternTest, MultipleSupportMovesItsSupportsAndGivesBackReplacedFixes) {
  MultipleSupportPattern p(3);
  auto series = [](double v) { return std::make_shared<ConstantSeries>(1, v); };
  p.groundMotions[1] = std::make_unique<GroundMotion>(series(3.0), series(2.0), series(1.0), 0.5);
  p.imposed.push_back({8, 0, 1, true});
  p.imposed.push_back({9, 2, 1, false});
  const LoadPattern& base = p;
  EXPECT_FALSE(base.hasFactor());
  ASSERT_EQ(base.supportCount(), 2u);
  EXPECT_TRUE(base.supportDofs()[1].imposedMotion);
  std::array<SupportMotion, 2> motion;
  base.supportMotion(1.0, motion);
  EXPECT_DOUBLE_EQ(motion[1].disp, 0.5 * 1.0);
  EXPECT_DOUBLE_EQ(motion[1].vel, 0.5 * 2.0);
  EXPECT_DOUBLE_EQ(motion[1].accel, 0.5 * 3.0);
  const auto fixes = base.replacedFixes();
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_EQ(fixes[0].node, 8);
  EXPECT_TRUE(base.usesNode(9));
  EXPECT_EQ(p.asMultipleSupport(), &p);
}

}  // namespace
}  // namespace dabs::domain
