// SPDX-License-Identifier: MIT
#include "materials/Elastic.h"

#include <gtest/gtest.h>

namespace dabs::materials {
namespace {

TEST(ElasticTest, BimodularWithDashpot) {
  Elastic m(1, Elastic::Params{200.0, 5.0, 50.0});
  ASSERT_TRUE(ok(m.setTrialStrain(0.01, 2.0)));
  EXPECT_DOUBLE_EQ(m.getStress(), 200.0 * 0.01 + 5.0 * 2.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), 200.0);
  EXPECT_DOUBLE_EQ(m.getDampTangent(), 5.0);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.01, -1.0)));
  EXPECT_DOUBLE_EQ(m.getStress(), 50.0 * -0.01 - 5.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), 50.0);
  EXPECT_DOUBLE_EQ(m.getInitialTangent(), 200.0);
}

TEST(ElasticTest, EnegDefaultsToE) {
  Elastic m(1, Elastic::Params{300.0, 0.0, std::nullopt});
  ASSERT_TRUE(ok(m.setTrialStrain(-0.02)));
  EXPECT_DOUBLE_EQ(m.getStress(), -6.0);
}

}  // namespace
}  // namespace dabs::materials
