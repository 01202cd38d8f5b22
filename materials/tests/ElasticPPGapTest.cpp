// SPDX-License-Identifier: MIT
#include "materials/ElasticPPGap.h"

#include <gtest/gtest.h>

namespace dabs::materials {
namespace {

constexpr double kTol = 1e-12;

TEST(ElasticPPGapTest, OpenGapThenElasticThenYield) {
  ElasticPPGap m(1, ElasticPPGap::Params{1000.0, 5.0, 0.002, 0.1, false});
  EXPECT_DOUBLE_EQ(m.getInitialTangent(), 0.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.001)));
  EXPECT_EQ(m.getStress(), 0.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.004)));
  EXPECT_NEAR(m.getStress(), 2.0, kTol);
  EXPECT_DOUBLE_EQ(m.getTangent(), 1000.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.017)));  // yield at 0.007, hardening 0.1*E
  EXPECT_NEAR(m.getStress(), 5.0 + 100.0 * 0.010, kTol);
  EXPECT_DOUBLE_EQ(m.getTangent(), 100.0);
}

TEST(ElasticPPGapTest, PlasticStrainWidensTheGap) {
  ElasticPPGap m(1, ElasticPPGap::Params{1000.0, 5.0, 0.002, 0.0, true});
  ASSERT_TRUE(ok(m.setTrialStrain(0.010)));
  m.commitState();
  // the gap now closes at 0.010 - 5/1000 = 0.005
  ASSERT_TRUE(ok(m.setTrialStrain(0.006)));
  EXPECT_NEAR(m.getStress(), 1.0, kTol);
  ASSERT_TRUE(ok(m.setTrialStrain(0.004)));
  EXPECT_EQ(m.getStress(), 0.0);
}

TEST(ElasticPPGapTest, CompressionGapMirrorsTension) {
  ElasticPPGap m(1, ElasticPPGap::Params{1000.0, -5.0, -0.002, 0.0, false});
  ASSERT_TRUE(ok(m.setTrialStrain(-0.001)));
  EXPECT_EQ(m.getStress(), 0.0);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.004)));
  EXPECT_NEAR(m.getStress(), -2.0, kTol);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.010)));
  EXPECT_DOUBLE_EQ(m.getStress(), -5.0);
}

}  // namespace
}  // namespace dabs::materials
