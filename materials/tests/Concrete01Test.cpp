// SPDX-License-Identifier: MIT
// Concrete01: Kent-Scott-Park envelope, no tension, Karsan-Jirsa unloading, computed here.

#include "materials/Concrete01.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <vector>

#include "materials/tests/SameBits.h"

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

// computeTrials (four fibers at a time where the processor has AVX) must give computeTrial's
// stress and tangent to the bit, for every fiber whatever branch its neighbours in the same four
// take: states from a walk of unloading and reloading cycles, each with strains in every range,
// shuffled so that the four lanes mix branches, and a count not a multiple of four; and
// commitTrials each state as commitTrial leaves it.
TEST(Concrete01Test, ArraysOfFibersGiveEachFibersOwnUpdate) {
  const Concrete01 m(1, Concrete01::Params{kFpc, kEps0, kFpcu, kEpsU});
  std::vector<Concrete01::State> states{m.virginState()};
  const double peaks[] = {-0.001, -0.0002, -0.0025, 0.0005, -0.004, -0.001, -0.008, 0.001, -0.012};
  double strain = 0.0;
  for (const double peak : peaks) {
    for (int k = 1; k <= 6; ++k) {
      Concrete01::State trial;
      ASSERT_TRUE(ok(m.computeTrial(states.back(), trial, strain + (peak - strain) * k / 6.0)));
      states.push_back(trial);
    }
    strain = peak;
  }
  std::mt19937 random(13);
  std::uniform_real_distribution<double> anywhere(-0.014, 0.002);
  std::vector<std::pair<Concrete01::State, double>> fibers;
  for (const auto& s : states) {
    const double near[] = {s.strain,
                           s.strain + 0.25 * DBL_EPSILON,
                           DBL_EPSILON,  // moved by exactly DBL_EPSILON from the virgin state
                           -DBL_EPSILON,
                           s.strain - 1e-5,
                           s.strain + 1e-5,
                           s.minStrain - 1e-6,
                           s.minStrain - 1e-4,
                           0.5 * kEps0,
                           0.5 * (kEps0 + kEpsU),
                           1.5 * kEpsU,
                           s.endStrain - 1e-5,
                           0.5 * (s.strain + s.endStrain),
                           1e-4,
                           std::nan(""),
                           anywhere(random),
                           anywhere(random)};
    for (const double e : near) fibers.emplace_back(s, e);
  }
  const auto [committed, strains] = testing::shuffledArrays(fibers, random);
  const std::size_t n = testing::expectEveryGroupSize(m, committed, strains);
  {
    // commitTrials: the same fibers (among them new most compressive strains on every part of
    // the envelope and each of unload's three lines), and those that reach none (fours of fibers
    // that only take the trial's strain, stress and tangent).
    SCOPED_TRACE("commits");
    testing::expectEveryGroupSizeCommits(m, committed, strains);
    std::vector<std::pair<Concrete01::State, double>> noNewMinimum;
    for (const auto& [s, e] : fibers)
      if (!(!(e > 0.0) && e < s.strain && e <= s.minStrain)) noNewMinimum.emplace_back(s, e);
    const auto [keptCommitted, keptStrains] = testing::shuffledArrays(noNewMinimum, random);
    testing::expectEveryGroupSizeCommits(m, keptCommitted, keptStrains);
  }
  {
    // Fours whose strains are all tensile (open cracks; the four's shortcut): from every state,
    // most of them with a compressive stress the update must drop, and the tensile states at
    // their own strain (unchanged).
    std::vector<std::pair<Concrete01::State, double>> open;
    for (const auto& s : states) {
      open.emplace_back(s, 1e-4 + 1e-7 * static_cast<double>(open.size()));
      if (s.strain > 0.0) open.emplace_back(s, s.strain);
    }
    const auto [openCommitted, openStrains] = testing::shuffledArrays(open, random);
    SCOPED_TRACE("all tensile");
    testing::expectEveryGroupSize(m, openCommitted, openStrains);
  }
  // What the fibers exercise: unchanged, tension, a new minimum (on the envelope, or below the
  // committed line, which then takes the new unloading slope), reloading along the unloading line,
  // unloading along the committed line.
  int unchanged = 0, tension = 0, newMinimum = 0, lineAboveEnvelope = 0, reloading = 0,
      unloading = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = committed[i];
    const double e = strains[i];
    Concrete01::State trial;
    static_cast<void>(m.computeTrial(c, trial, e));
    const double linear = c.stress + c.unloadSlope * e - c.unloadSlope * c.strain;
    if (std::fabs(e - c.strain) < DBL_EPSILON) {
      ++unchanged;
    } else if (e > 0.0) {
      ++tension;
    } else if (e < c.strain && e <= c.minStrain) {
      linear > trial.stress || trial.stress == linear ? ++lineAboveEnvelope : ++newMinimum;
    } else if (e < c.strain) {
      ++reloading;
    } else {
      ++unloading;
    }
  }
  for (const int count : {unchanged, tension, newMinimum, lineAboveEnvelope, reloading, unloading})
    EXPECT_GT(count, 4);
}

}  // namespace
}  // namespace dabs::materials
