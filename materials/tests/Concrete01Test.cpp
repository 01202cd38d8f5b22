// SPDX-License-Identifier: MIT
// Concrete01: Kent-Scott-Park envelope, no tension, Karsan-Jirsa unloading, computed here.

#include "materials/Concrete01.h"

#include <gtest/gtest.h>

#include <cmath>

namespace dabs::materials {
namespace {

constexpr double kFpc = -30.0, kEps0 = -0.002, kFpcu = -6.0, kEpsU = -0.006;
constexpr double kTol = 1e-10;

TEST(Concrete01Test, ParabolaUpToPeak) {
  Concrete01 m(1, Concrete01::Params{kFpc, kEps0, kFpcu, kEpsU});
  for (double eta : {0.25, 0.5, 0.9}) {
    ASSERT_TRUE(ok(m.setTrialStrain(eta * kEps0)));
    EXPECT_NEAR(m.getStress(), kFpc * (2.0 * eta - eta * eta), kTol * 30.0);
    EXPECT_NEAR(m.getTangent(), 2.0 * kFpc / kEps0 * (1.0 - eta), kTol * 3e4);
  }
}

TEST(Concrete01Test, LinearDescentThenResidual) {
  Concrete01 m(1, Concrete01::Params{kFpc, kEps0, kFpcu, kEpsU});
  const double slope = (kFpcu - kFpc) / (kEpsU - kEps0);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.004)));
  EXPECT_NEAR(m.getStress(), kFpc + slope * (-0.004 - kEps0), kTol * 30.0);
  EXPECT_NEAR(m.getTangent(), slope, kTol * 3e4);
  ASSERT_TRUE(ok(m.setTrialStrain(-0.008)));
  EXPECT_DOUBLE_EQ(m.getStress(), kFpcu);
  EXPECT_DOUBLE_EQ(m.getTangent(), 0.0);
}

TEST(Concrete01Test, NoTension) {
  Concrete01 m(1, Concrete01::Params{30.0, 0.002, 6.0, 0.006});  // positive inputs flipped
  ASSERT_TRUE(ok(m.setTrialStrain(0.001)));
  EXPECT_EQ(m.getStress(), 0.0);
  EXPECT_EQ(m.getTangent(), 0.0);
  EXPECT_DOUBLE_EQ(m.getInitialTangent(), 2.0 * 30.0 / 0.002);
}

TEST(Concrete01Test, UnloadsToKarsanJirsaStrainFromThePeak) {
  Concrete01 m(1, Concrete01::Params{kFpc, kEps0, kFpcu, kEpsU});
  ASSERT_TRUE(ok(m.setTrialStrain(kEps0)));
  m.commitState();
  // Karsan & Jirsa: eps_end/eps0 = 0.145*eta^2 + 0.13*eta with eta = 1
  const double epsEnd = (0.145 + 0.13) * kEps0;
  const double slope = kFpc / (kEps0 - epsEnd);
  ASSERT_TRUE(ok(m.setTrialStrain(0.5 * (kEps0 + epsEnd))));
  EXPECT_NEAR(m.getStress(), 0.5 * kFpc, kTol * 30.0);
  EXPECT_NEAR(m.getTangent(), slope, kTol * 3e4);
  ASSERT_TRUE(ok(m.setTrialStrain(0.9 * epsEnd)));  // beyond the end strain: open crack
  EXPECT_EQ(m.getStress(), 0.0);
}

}  // namespace
}  // namespace dabs::materials
