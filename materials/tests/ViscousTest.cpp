// SPDX-License-Identifier: MIT
#include "materials/Viscous.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dabs::materials {
namespace {

TEST(ViscousTest, PowerLawDashpot) {
  Viscous m(1, Viscous::Params{50.0, 0.3, 1e-11});
  ASSERT_TRUE(ok(m.setTrialStrain(0.0, -4.0)));
  EXPECT_NEAR(m.getStress(), -50.0 * std::pow(4.0, 0.3), 1e-12);
  EXPECT_NEAR(m.getDampTangent(), 0.3 * 50.0 * std::pow(4.0, -0.7), 1e-12);
  EXPECT_EQ(m.getTangent(), 0.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.0, 0.0)));  // tangent floored by minVel, stays finite
  EXPECT_NEAR(m.getDampTangent(), 0.3 * 50.0 * std::pow(1e-11, -0.7), 1e-3);
}

}  // namespace
}  // namespace dabs::materials
