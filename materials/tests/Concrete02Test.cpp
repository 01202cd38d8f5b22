// SPDX-License-Identifier: MIT
// Concrete02: compression envelope (Kent-Scott-Park) and linear tension softening, computed here.

#include "materials/Concrete02.h"

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
constexpr double kFt = 3.0, kEts = 1500.0, kEc = 2.0 * kFpc / kEps0;
constexpr double kTol = 1e-10;

Concrete02 make() {
  return Concrete02(1, Concrete02::Params{kFpc, kEps0, kFpcu, kEpsU, 0.1, kFt, kEts});
}

TEST(Concrete02Test, CompressionEnvelope) {
  auto m = make();
  ASSERT_TRUE(ok(m.setTrialStrain(0.5 * kEps0)));
  EXPECT_NEAR(m.getStress(), kFpc * (2.0 * 0.5 - 0.25), kTol * 30.0);
  m.revertToLastCommit();
  ASSERT_TRUE(ok(m.setTrialStrain(-0.005)));
  EXPECT_NEAR(m.getStress(), kFpc + (kFpcu - kFpc) * (-0.005 - kEps0) / (kEpsU - kEps0),
              kTol * 30.0);
  EXPECT_NEAR(m.getTangent(), (kFpcu - kFpc) / (kEpsU - kEps0), kTol * kEc);
}

TEST(Concrete02Test, TensionBranchAndLinearSoftening) {
  auto m = make();
  const double epsCrack = kFt / kEc;
  ASSERT_TRUE(ok(m.setTrialStrain(0.5 * epsCrack)));
  EXPECT_NEAR(m.getStress(), 0.5 * kFt, kTol * 30.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), kEc);
  ASSERT_TRUE(ok(m.setTrialStrain(epsCrack + 0.001)));
  EXPECT_NEAR(m.getStress(), kFt - kEts * 0.001, kTol * 30.0);
  EXPECT_DOUBLE_EQ(m.getTangent(), -kEts);
  m.commitState();
  // unloading from the softening branch goes back towards the origin (secant slope)
  const double sigMax = m.getStress();
  ASSERT_TRUE(ok(m.setTrialStrain(0.5 * (epsCrack + 0.001))));
  EXPECT_NEAR(m.getStress(), 0.5 * sigMax, kTol * 30.0);
  // beyond ft/Ec0 + ft/Ets the tensile stress is zero
  m.revertToLastCommit();
  ASSERT_TRUE(ok(m.setTrialStrain(epsCrack + kFt / kEts + 1e-4)));
  EXPECT_EQ(m.getStress(), 0.0);
}

TEST(Concrete02Test, DefaultsFollowOpenSees) {
  const auto p = Concrete02::Params::withDefaults(kFpc, kEps0, kFpcu, kEpsU);
  EXPECT_DOUBLE_EQ(p.lambda, 0.1);
  EXPECT_DOUBLE_EQ(p.ft, 3.0);
  EXPECT_DOUBLE_EQ(p.Ets, 0.1 * kFpc / kEps0);
}

// A fiber section keeps only a fiber's trial stress and tangent and commits with commitTrial: the
// committed history must be the one computeTrial forms, field for field, on a walk through every
// branch (envelope, unloading, reloading, cracking, tension softening, crushing), with several
// trials before each commit as in Newton iterations, and with repeated strains.
TEST(Concrete02Test, CommitFromTrialResponseEqualsTheTrialState) {
  const Concrete02 m = make();
  Concrete02::State committed = m.virginState();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-2e-4, 2e-4);
  const double peaks[] = {-0.001, 0.0004, -0.0025, 0.001, -0.004, 0.002, -0.008, 0.003, -0.012};
  double strain = 0.0;
  int commits = 0;
  for (const double peak : peaks) {
    for (int k = 1; k <= 12; ++k) {
      const double target = strain + (peak - strain) * k / 12.0;
      Concrete02::State trial;
      for (int iteration = 0; iteration < 3; ++iteration)
        ASSERT_TRUE(
            ok(m.computeTrial(committed, trial, target + jitter(random) / (1 << (2 * iteration)))));
      const double last = k % 4 == 0 ? committed.strain : target;  // some steps do not move
      ASSERT_TRUE(ok(m.computeTrial(committed, trial, last)));
      Concrete02::State viaResponse = committed;
      m.commitTrial(viaResponse, last, trial.stress, trial.tangent);
      EXPECT_EQ(viaResponse.strain, trial.strain);
      EXPECT_EQ(viaResponse.stress, trial.stress);
      EXPECT_EQ(viaResponse.tangent, trial.tangent);
      EXPECT_EQ(viaResponse.ecmin, trial.ecmin);
      EXPECT_EQ(viaResponse.dept, trial.dept);
      EXPECT_EQ(viaResponse.sigMin, trial.sigMin);
      EXPECT_EQ(viaResponse.Er, trial.Er);
      EXPECT_EQ(viaResponse.ept, trial.ept);
      committed = trial;
      ++commits;
    }
    strain = peak;
  }
  // The walk reached crushing and tension softening (otherwise branches went untested).
  EXPECT_LT(committed.ecmin, kEpsU);
  EXPECT_GT(committed.dept, kFt / kEc);
  EXPECT_EQ(commits, 9 * 12);
}

// computeTrials (four fibers at a time where the processor has AVX) must give computeTrial's
// stress and tangent to the bit, for every fiber whatever branch its neighbours in the same four
// take. States from a walk through every branch, each paired with strains in every range
// (unchanged, a new minimum on each part of the envelope, the reloading band and its two bounds,
// tension reloading and the tension envelope, a NaN), shuffled so that the four lanes mix branches,
// and a count not a multiple of four. commitTrials (the fold of a commit, four at a time too) must
// leave each state as commitTrial does, on the same fibers.
TEST(Concrete02Test, ArraysOfFibersGiveEachFibersOwnUpdate) {
  const Concrete02 m = make();
  std::vector<Concrete02::State> states{m.virginState()};
  const double peaks[] = {-0.001, 0.0004, -0.0025, 0.001, -0.004, 0.002, -0.008, 0.003, -0.012};
  double strain = 0.0;
  for (const double peak : peaks) {
    for (int k = 1; k <= 6; ++k) {
      Concrete02::State trial;
      ASSERT_TRUE(ok(m.computeTrial(states.back(), trial, strain + (peak - strain) * k / 6.0)));
      states.push_back(trial);
    }
    strain = peak;
  }
  std::mt19937 random(11);
  std::uniform_real_distribution<double> anywhere(-0.014, 0.004);
  std::vector<std::pair<Concrete02::State, double>> fibers;
  for (const auto& s : states) {
    const double near[] = {s.strain,
                           s.strain + 0.25 * DBL_EPSILON,
                           DBL_EPSILON,  // moved by exactly DBL_EPSILON from the virgin state
                           s.strain - 1e-5,
                           s.strain + 1e-5,
                           s.ecmin - 1e-4,
                           0.5 * kEps0,
                           0.5 * (kEps0 + kEpsU),
                           1.5 * kEpsU,
                           s.ept,
                           s.ept - 1e-4,
                           s.ept + 0.5 * s.dept,
                           s.ept + s.dept + 1e-4,
                           s.ept + 0.5 * kFt / kEc,
                           std::nan(""),
                           anywhere(random),
                           anywhere(random)};
    for (const double e : near) fibers.emplace_back(s, e);
  }
  const auto [shuffledStates, shuffledStrains] = testing::shuffledArrays(fibers, random);
  const std::size_t n = testing::expectEveryGroupSize(m, shuffledStates, shuffledStrains);
  {
    SCOPED_TRACE("commits");
    testing::expectEveryGroupSizeCommits(m, shuffledStates, shuffledStrains);
  }
  // What the fibers exercise: unchanged, new minimum (parabola, descending, residual), the
  // reloading band (initial slope, the reloading line, half its slope), tension reloading, the
  // tension envelope (uncracked, softening, no stress), a NaN strain.
  int unchanged = 0, parabola = 0, descending = 0, residual = 0, bandInitial = 0, bandLower = 0,
      bandUpper = 0, reloading = 0, uncracked = 0, softening = 0, open = 0, nan = 0;
  const double epsCrack = kFt / kEc, epsZero = kFt * (1.0 / kEts + 1.0 / kEc);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = shuffledStates[i];
    const double e = shuffledStrains[i];
    Concrete02::State trial;
    static_cast<void>(m.computeTrial(c, trial, e));
    if (std::isnan(e)) {
      ++nan;
    } else if (std::fabs(e - c.strain) < DBL_EPSILON) {
      ++unchanged;
    } else if (e < c.ecmin) {
      e >= kEps0 ? ++parabola : e > kEpsU ? ++descending : ++residual;
    } else if (e <= c.ept) {
      trial.tangent == kEc ? ++bandInitial : trial.tangent == c.Er ? ++bandLower : ++bandUpper;
    } else if (e <= c.ept + c.dept) {
      ++reloading;
    } else {
      const double x = e - c.ept;
      x <= epsCrack ? ++uncracked : x <= epsZero ? ++softening : ++open;
    }
  }
  for (const int count : {unchanged, parabola, descending, residual, bandInitial, bandLower,
                          bandUpper, reloading, uncracked, softening, open, nan})
    EXPECT_GT(count, 4);
}

}  // namespace
}  // namespace dabs::materials
