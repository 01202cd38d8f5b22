// SPDX-License-Identifier: MIT
#include "materials/ElasticPP.h"

#include <gtest/gtest.h>

namespace dabs::materials {
namespace {

constexpr double kTol = 1e-12;

TEST(ElasticPPTest, YieldsAtEpsyPAndUnloadsElastically) {
  ElasticPP m(1, ElasticPP::Params{1000.0, 0.002, -0.001, 0.0});
  ASSERT_TRUE(ok(m.setTrialStrain(0.001)));
  EXPECT_NEAR(m.getStress(), 1.0, kTol);
  EXPECT_DOUBLE_EQ(m.getTangent(), 1000.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.005)));
  m.commitState();
  EXPECT_DOUBLE_EQ(m.getStress(), 2.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), 0.0);
  // plastic strain 0.003: elastic unloading to zero stress at 0.003, yield in compression at
  // 0.003 - 0.001 = 0.002
  ASSERT_TRUE(ok(m.setTrialStrain(0.004)));
  EXPECT_NEAR(m.getStress(), 1.0, kTol);
  ASSERT_TRUE(ok(m.setTrialStrain(0.0)));
  EXPECT_DOUBLE_EQ(m.getStress(), -1.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), 0.0);
}

TEST(ElasticPPTest, InitialStrainShiftsTheElasticBranch) {
  ElasticPP m(1, ElasticPP::Params{1000.0, 0.002, std::nullopt, 0.0005});
  ASSERT_TRUE(ok(m.setTrialStrain(0.0)));
  EXPECT_NEAR(m.getStress(), -0.5, kTol);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.003)));
  EXPECT_DOUBLE_EQ(m.getStress(), -2.0);  // epsyN defaults to -epsyP
}

}  // namespace
}  // namespace dabs::materials
