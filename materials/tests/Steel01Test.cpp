// SPDX-License-Identifier: MIT
// Steel01 closed forms: bilinear kinematic hardening (yield point, post-yield slope b*E0,
// elastic unloading over 2*Fy) and the Filippou isotropic shift.

#include "materials/Steel01.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dabs::materials {
namespace {

constexpr double kFy = 300.0, kE = 2.0e5, kB = 0.05, kEpsY = kFy / kE;
constexpr double kTol = 1e-9;

TEST(Steel01Test, YieldPointAndPostYieldSlope) {
  Steel01 m(1, Steel01::Params{kFy, kE, kB});
  ASSERT_TRUE(ok(m.setTrialStrain(0.5 * kEpsY)));
  EXPECT_NEAR(m.getStress(), 0.5 * kFy, kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kE);
  ASSERT_TRUE(ok(m.setTrialStrain(4.0 * kEpsY)));
  EXPECT_NEAR(m.getStress(), kFy + kB * kE * 3.0 * kEpsY, kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kB * kE);
}

TEST(Steel01Test, UnloadsElasticallyOverTwiceFy) {
  Steel01 m(1, Steel01::Params{kFy, kE, kB});
  ASSERT_TRUE(ok(m.setTrialStrain(4.0 * kEpsY)));
  m.commitState();
  const double sigMax = m.getStress();
  ASSERT_TRUE(ok(m.setTrialStrain(4.0 * kEpsY - 1.5 * kEpsY)));
  EXPECT_NEAR(m.getStress(), sigMax - 1.5 * kFy, kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kE);
  // reverse yielding on the compressive asymptote b*E0*eps - Fy*(1-b)
  ASSERT_TRUE(ok(m.setTrialStrain(-2.0 * kEpsY)));
  EXPECT_NEAR(m.getStress(), kB * kE * (-2.0 * kEpsY) - kFy * (1.0 - kB), kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kB * kE);
}

TEST(Steel01Test, IsotropicShiftAfterReversal) {
  Steel01 m(1, Steel01::Params{kFy, kE, kB, 0.5, 2.0, 0.0, 55.0});
  ASSERT_TRUE(ok(m.setTrialStrain(5.0 * kEpsY)));
  m.commitState();
  ASSERT_TRUE(ok(m.setTrialStrain(4.0 * kEpsY)));  // reversal: shiftN computed for later trials
  m.commitState();
  ASSERT_TRUE(ok(m.setTrialStrain(-10.0 * kEpsY)));
  const double shiftN = 1.0 + 0.5 * std::pow(5.0 * kEpsY / (2.0 * 2.0 * kEpsY), 0.8);
  EXPECT_NEAR(m.getStress(), kB * kE * (-10.0 * kEpsY) - shiftN * kFy * (1.0 - kB), kTol * kFy);
}

// A negative b softens after yield: the stress falls along Fy + b*E0*(eps - epsy) and unloading
// is elastic from the softened stress.
TEST(Steel01Test, NegativeHardeningRatioSoftens) {
  constexpr double kSoft = -0.02;
  Steel01 m(1, Steel01::Params{kFy, kE, kSoft});
  ASSERT_TRUE(ok(m.setTrialStrain(5.0 * kEpsY)));
  EXPECT_NEAR(m.getStress(), kFy + kSoft * kE * 4.0 * kEpsY, kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kSoft * kE);
  m.commitState();
  const double sigma = m.getStress();
  ASSERT_TRUE(ok(m.setTrialStrain(4.0 * kEpsY)));
  EXPECT_NEAR(m.getStress(), sigma - kFy, kTol * kFy);
  EXPECT_DOUBLE_EQ(m.getTangent(), kE);
}

}  // namespace
}  // namespace dabs::materials
