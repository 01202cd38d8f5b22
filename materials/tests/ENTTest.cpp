// SPDX-License-Identifier: MIT
#include "materials/ENT.h"

#include <gtest/gtest.h>

namespace dabs::materials {
namespace {

TEST(ENTTest, NoTension) {
  ENT m(1, ENT::Params{500.0});
  ASSERT_TRUE(ok(m.setTrialStrain(-0.01)));
  EXPECT_DOUBLE_EQ(m.getStress(), -5.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), 500.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.01)));
  EXPECT_EQ(m.getStress(), 0.0);
  EXPECT_EQ(m.getTangent(), 0.0);
}

}  // namespace
}  // namespace dabs::materials
