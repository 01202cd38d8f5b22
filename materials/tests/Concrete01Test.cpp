// SPDX-License-Identifier: MIT
// Concrete01: Kent-Scott-Park envelope, no tension, Karsan-Jirsa unloading, computed here.

#include "materials/Concrete01.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

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

// A fiber section keeps only a fiber's trial stress and tangent and commits with commitTrial: the
// committed history must be the one computeTrial forms, field for field, on a walk through every
// branch (envelope, descent, crushing, unloading, reloading, open crack), with several trials
// before each commit as in Newton iterations, with steps that do not move, and with single steps
// from an open crack past the most compressive strain.
TEST(Concrete01Test, CommitFromTrialResponseEqualsTheTrialState) {
  const Concrete01 m(1, Concrete01::Params{kFpc, kEps0, kFpcu, kEpsU});
  Concrete01::State committed = m.virginState();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  struct Excursion {
    double peak;
    int steps;
  };
  const Excursion walk[] = {{-0.001, 12}, {0.0004, 12}, {-0.0025, 12}, {-0.0005, 12}, {-0.004, 12},
                            {0.001, 12},  {-0.0045, 1}, {0.0005, 4},   {-0.008, 12},  {-0.002, 12},
                            {-0.009, 1},  {0.001, 4},   {-0.012, 1}};
  double strain = 0.0;
  int newMinima = 0;
  for (const auto& [peak, steps] : walk) {
    for (int k = 1; k <= steps; ++k) {
      const double target = strain + (peak - strain) * k / steps;
      Concrete01::State trial;
      for (int iteration = 0; iteration < 3; ++iteration)
        ASSERT_TRUE(
            ok(m.computeTrial(committed, trial, target + jitter(random) / (1 << (2 * iteration)))));
      // some steps do not move, or by less than DBL_EPSILON (the committed state stands)
      const double last =
          k % 4 == 0 ? committed.strain + (k % 8 == 0 ? 0.25 * DBL_EPSILON : 0.0) : target;
      ASSERT_TRUE(ok(m.computeTrial(committed, trial, last)));
      Concrete01::State viaResponse = committed;
      m.commitTrial(viaResponse, last, trial.stress, trial.tangent);
      EXPECT_EQ(viaResponse.strain, trial.strain);
      EXPECT_EQ(viaResponse.stress, trial.stress);
      EXPECT_EQ(viaResponse.tangent, trial.tangent);
      EXPECT_EQ(viaResponse.minStrain, trial.minStrain);
      EXPECT_EQ(viaResponse.endStrain, trial.endStrain);
      EXPECT_EQ(viaResponse.unloadSlope, trial.unloadSlope);
      newMinima += trial.minStrain < committed.minStrain;
      committed = trial;
    }
    strain = peak;
  }
  // The walk reached the residual strength and moved the unloading line many times (otherwise
  // branches went untested).
  EXPECT_LT(committed.minStrain, kEpsU);
  EXPECT_GT(newMinima, 20);
}

}  // namespace
}  // namespace dabs::materials
