// SPDX-License-Identifier: MIT
// Steel02 against the Menegotto-Pinto equation evaluated here from the published formula
// (Menegotto & Pinto 1973; Filippou, Popov & Bertero 1983, EERC 83/19, eqs. 3-5).

#include "materials/Steel02.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "materials/tests/SameBits.h"

namespace dabs::materials {
namespace {

constexpr double kFy = 400.0, kE = 2.0e5, kB = 0.01, kEpsY = kFy / kE;
constexpr double kRelTol = 1e-12;

/// Normalised Menegotto-Pinto curve sig* = b*eps* + (1-b)*eps*/(1+|eps*|^R)^(1/R).
double menegottoPinto(double epsStar, double b, double R) {
  return b * epsStar +
         (1.0 - b) * epsStar / std::pow(1.0 + std::pow(std::fabs(epsStar), R), 1.0 / R);
}

TEST(Steel02Test, FirstLoadingFollowsMenegottoPintoWithR0) {
  Steel02 m(1, Steel02::Params{kFy, kE, kB});
  // first excursion: origin (0,0), asymptote intersection (epsy, Fy), xi = 0 so R = R0 = 15
  for (double ratio : {0.5, 1.0, 1.5, 3.0}) {
    ASSERT_TRUE(ok(m.setTrialStrain(ratio * kEpsY)));
    const double expected = kFy * menegottoPinto(ratio, kB, 15.0);
    EXPECT_NEAR(m.getStress(), expected, kRelTol * kFy) << "eps/epsy = " << ratio;
  }
}

TEST(Steel02Test, StressAndTangentAroundTheLinearLimitOfTheBranch) {
  // Near the start of a branch the update skips exp and log where |eps*|^R < e^-38 (R = 15 here:
  // |eps*| < e^(-38/15) = 0.0794). On both sides of that limit the stress and tangent must be the
  // published curve's: sig* from menegottoPinto, E* = b + (1-b)/(1+|eps*|^R)^(1+1/R).
  const double limit = std::exp(-38.0 / 15.0);
  for (double ratio : {0.5 * limit, 0.999 * limit, 1.001 * limit, 2.0 * limit, -0.999 * limit}) {
    Steel02 m(1, Steel02::Params{kFy, kE, kB});
    ASSERT_TRUE(ok(m.setTrialStrain(ratio * kEpsY)));
    EXPECT_NEAR(m.getStress(), kFy * menegottoPinto(ratio, kB, 15.0), 1e-15 * kFy) << ratio;
    const double t = std::pow(std::fabs(ratio), 15.0);
    const double eStar = kB + (1.0 - kB) / std::pow(1.0 + t, 1.0 + 1.0 / 15.0);
    EXPECT_NEAR(m.getTangent(), kE * eStar, 1e-15 * kE) << ratio;
  }
}

TEST(Steel02Test, StressAndTangentInEachRangeOfThePower) {
  // (1 + t)^(1/R), t = |eps*|^R, by the series in t (t < 1e-4), the power (up to 1e4) and |eps*|
  // times the series in 1/t (beyond): in each range, and on both sides of each bound, the stress
  // and tangent of the published curve evaluated in long double.
  const long double R = 15.0L;
  for (double ratio : {0.3, 0.5, 0.54, 0.55, 0.7, 1.0, 1.3, 1.84, 1.86, 2.0, 5.0, 40.0, -2.5}) {
    Steel02 m(1, Steel02::Params{kFy, kE, kB});
    ASSERT_TRUE(ok(m.setTrialStrain(ratio * kEpsY)));
    const long double x = ratio, t = std::pow(std::fabs(x), R);
    const long double root = std::pow(1.0L + t, 1.0L / R);
    const long double sigStar = kB * x + (1.0L - kB) * x / root;
    const long double eStar = kB + (1.0L - kB) / ((1.0L + t) * root);
    EXPECT_NEAR(m.getStress(), static_cast<double>(kFy * sigStar), 1e-14 * kFy) << ratio;
    EXPECT_NEAR(m.getTangent(), static_cast<double>(kE * eStar), 1e-14 * kE) << ratio;
  }
}

TEST(Steel02Test, ElasticStartAndHardeningAsymptote) {
  Steel02 m(1, Steel02::Params{kFy, kE, kB});
  ASSERT_TRUE(ok(m.setTrialStrain(0.01 * kEpsY)));
  EXPECT_NEAR(m.getTangent(), kE, 1e-12 * kE);  // |eps*|^R negligible: initial slope E
  ASSERT_TRUE(ok(m.setTrialStrain(20.0 * kEpsY)));
  // far beyond yield the curve approaches the asymptote Fy + b*E*(eps - epsy), slope b*E
  EXPECT_NEAR(m.getStress(), kFy + kB * kE * 19.0 * kEpsY, 1e-6 * kFy);
  EXPECT_NEAR(m.getTangent(), kB * kE, 1e-3 * kB * kE);
}

TEST(Steel02Test, ReversalUsesNewOriginAsymptoteAndDegradedR) {
  Steel02::Params p{kFy, kE, kB};
  Steel02 m(1, p);
  const double epsMax = 3.0 * kEpsY;
  ASSERT_TRUE(ok(m.setTrialStrain(epsMax)));
  m.commitState();
  const double sigR = m.getStress();
  // independent construction of the reversal branch:
  // elastic line sig = sigR + E*(eps - epsR) meets the compressive asymptote
  // sig = -Fy + b*E*(eps + epsy) at eps0
  const double eps0 = (-kFy + kB * kE * kEpsY - sigR + kE * epsMax) / (kE - kB * kE);
  const double sig0 = -kFy + kB * kE * (eps0 + kEpsY);
  // xi = |eps_pl - eps0|/epsy with eps_pl the previous extreme on the compression side (-epsy)
  const double xi = std::fabs(-kEpsY - eps0) / kEpsY;
  const double R = p.R0 * (1.0 - p.cR1 * xi / (p.cR2 + xi));
  for (double eps : {2.5 * kEpsY, 0.0, -2.0 * kEpsY}) {
    ASSERT_TRUE(ok(m.setTrialStrain(eps)));
    const double epsStar = (eps - epsMax) / (eps0 - epsMax);
    const double expected = sigR + (sig0 - sigR) * menegottoPinto(epsStar, kB, R);
    EXPECT_NEAR(m.getStress(), expected, kRelTol * kFy) << "eps = " << eps;
  }
  // unloading starts with the elastic slope
  ASSERT_TRUE(ok(m.setTrialStrain(epsMax - 1e-7)));
  EXPECT_NEAR(m.getTangent(), kE, 1e-6 * kE);
}

TEST(Steel02Test, IsotropicHardeningShiftsTheCompressiveAsymptote) {
  Steel02::Params p{kFy, kE, kB};
  p.a1 = 0.4;
  p.a2 = 2.0;
  Steel02 hard(1, p), plain(2, Steel02::Params{kFy, kE, kB});
  for (auto* m : {&hard, &plain}) {
    ASSERT_TRUE(ok(m->setTrialStrain(5.0 * kEpsY)));
    m->commitState();
    ASSERT_TRUE(ok(m->setTrialStrain(-30.0 * kEpsY)));
  }
  // shift = 1 + a1*((epsmax - epsmin)/(2*a2*epsy))^0.8 with epsmax = 5 epsy, epsmin = -epsy
  const double shift = 1.0 + 0.4 * std::pow(6.0 / 4.0, 0.8);
  const double epsR = 5.0 * kEpsY, sigR = kFy * menegottoPinto(5.0, kB, 15.0);
  // elastic line from the reversal meets the shifted asymptote -Fy*shift + bE(eps + epsy*shift)
  const double Esh = kB * kE;
  const double eps0 = (-kFy * shift + Esh * kEpsY * shift - sigR + kE * epsR) / (kE - Esh);
  const double sig0 = -kFy * shift + Esh * (eps0 + kEpsY * shift);
  const double xi = std::fabs(-kEpsY - eps0) / kEpsY;
  const double R = 15.0 * (1.0 - 0.925 * xi / (0.15 + xi));
  const double epsStar = (-30.0 * kEpsY - epsR) / (eps0 - epsR);
  EXPECT_NEAR(hard.getStress(), sigR + (sig0 - sigR) * menegottoPinto(epsStar, kB, R),
              kRelTol * kFy);
  EXPECT_LT(hard.getStress(), plain.getStress() - 0.3 * kFy);
}

TEST(Steel02Test, InitialStressShiftsTheVirginState) {
  Steel02::Params p{kFy, kE, kB};
  p.sigInit = 100.0;
  Steel02 m(1, p);
  EXPECT_DOUBLE_EQ(m.getStress(), 100.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.1 * kEpsY)));
  // internal strain 0.1 epsy + 100/E = 0.35 epsy on the first-loading curve
  EXPECT_NEAR(m.getStress(), kFy * menegottoPinto(0.35, kB, 15.0), kRelTol * kFy);
}

// A fiber section keeps only a bar's trial stress and tangent and commits with commitTrial: the
// committed branch data must be the ones computeTrial forms, field for field, through the virgin
// point (with an initial stress), first yield, reversals with isotropic hardening (a1..a4, whose
// shift uses pow) and steps that do not move, with several trials before each commit.
TEST(Steel02Test, CommitFromTrialResponseEqualsTheTrialState) {
  Steel02::Params params{kFy, kE, kB};
  params.a1 = 0.02;
  params.a3 = 0.02;
  params.sigInit = 40.0;
  const Steel02 m(1, params);
  Steel02::State committed = m.virginState();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
  const double peaks[] = {0.0, 0.5, -1.0, 3.0, -4.0, 8.0, -2.0, 12.0, -12.0};
  double strain = 0.0;
  int reversals = 0;
  for (const double peak : peaks) {
    for (int k = 1; k <= 10; ++k) {
      const double target = (strain + (peak - strain) * k / 10.0) * kEpsY;
      Steel02::State trial;
      for (int iteration = 0; iteration < 3; ++iteration)
        ASSERT_TRUE(ok(m.computeTrial(committed, trial, target + jitter(random) * kEpsY)));
      const double last = k % 5 == 0 ? committed.strain : target;  // some steps do not move
      ASSERT_TRUE(ok(m.computeTrial(committed, trial, last)));
      Steel02::State viaResponse = committed;
      m.commitTrial(viaResponse, last, trial.stress, trial.tangent);
      EXPECT_EQ(viaResponse.strain, trial.strain);
      EXPECT_EQ(viaResponse.stress, trial.stress);
      EXPECT_EQ(viaResponse.tangent, trial.tangent);
      EXPECT_EQ(viaResponse.epsMin, trial.epsMin);
      EXPECT_EQ(viaResponse.epsMax, trial.epsMax);
      EXPECT_EQ(viaResponse.epsPl, trial.epsPl);
      EXPECT_EQ(viaResponse.eps0, trial.eps0);
      EXPECT_EQ(viaResponse.sig0, trial.sig0);
      EXPECT_EQ(viaResponse.epsR, trial.epsR);
      EXPECT_EQ(viaResponse.sigR, trial.sigR);
      EXPECT_EQ(viaResponse.kon, trial.kon);
      EXPECT_EQ(viaResponse.R, trial.R);
      EXPECT_EQ(viaResponse.linearLimit, trial.linearLimit);
      EXPECT_EQ(viaResponse.invSpan, trial.invSpan);
      if (trial.kon != committed.kon) ++reversals;
      committed = trial;
    }
    strain = peak;
  }
  EXPECT_GE(reversals, 8);  // the virgin point, first yield and every peak's reversal were passed
}

// computeTrials (four fibers at a time where the processor has AVX) must give each fiber's own
// update to the bit (computeTrialWith<LanePowers> in groups of four or more, computeTrial in
// smaller ones), whatever its neighbours in the same four do:
// states from walks of growing cycles (materials below), each with strains that stay on the
// branch (the initial line, either side of its limit, the binomial series, the power), that
// reverse it, or that start the first branch, shuffled so that the four lanes mix them, and a
// count not a multiple of four. commitTrials (the fold of a commit; four at a time where every
// fiber of the four stays on its branch) must leave each state as commitTrial does, on the same
// fibers.
TEST(Steel02Test, ArraysOfFibersGiveEachFibersOwnUpdate) {
  // The usual curvature with an initial stress; the same with isotropic hardening (whose
  // reversals shift the asymptotes: those fibers go one by one), both ways and each way alone; a
  // curvature that falls below 1.
  Steel02::Params usual{kFy, kE, kB, 18.0, 0.925, 0.15};
  usual.sigInit = 40.0;
  Steel02::Params hardening = usual;
  hardening.a1 = 0.02;
  hardening.a3 = 0.02;
  // Hardening one way only: reversals the other way go through the lanes.
  Steel02::Params compressiveHardening = usual;
  compressiveHardening.a1 = 0.02;
  Steel02::Params tensileHardening = usual;
  tensileHardening.a3 = 0.02;
  const Steel02::Params flat{kFy, kE, kB, 1.5, 0.925, 0.15};
  int virgin = 0, reversal = 0, shiftedReversal = 0, line = 0, series = 0, power = 0, belowOne = 0;
  for (const auto& params : {usual, hardening, compressiveHardening, tensileHardening, flat}) {
    const Steel02 m(1, params);
    const double epsIni = params.sigInit / params.E;
    std::vector<Steel02::State> states{m.virginState()};
    const double peaks[] = {0.5, -1.0, 3.0, -4.0, 8.0, -2.0, 12.0, -12.0, 20.0};
    double strain = 0.0;
    for (const double peak : peaks) {
      // Two short steps first, so that some states lie at the start of a branch, where the
      // strains ahead of them are on its initial line.
      for (const double step : {1e-4, 1e-3, 0.2, 0.4, 0.6, 0.8, 1.0}) {
        Steel02::State trial;
        ASSERT_TRUE(
            ok(m.computeTrial(states.back(), trial, (strain + (peak - strain) * step) * kEpsY)));
        states.push_back(trial);
      }
      strain = peak;
    }
    std::mt19937 random(17);
    std::uniform_real_distribution<double> anywhere(-15.0 * kEpsY, 15.0 * kEpsY);
    std::vector<std::pair<Steel02::State, double>> fibers;
    for (const auto& s : states) {
      // The strain at a normalised strain eps* of the committed branch.
      const double span = s.invSpan != 0.0 ? 1.0 / s.invSpan : kEpsY;
      auto at = [&](double ratio) { return s.epsR + ratio * span - epsIni; };
      const double limit = s.linearLimit;
      const double near[] = {s.strain,
                             s.strain + 1e-7 * kEpsY,
                             s.strain - 1e-7 * kEpsY,
                             s.strain + 0.05 * kEpsY,
                             s.strain - 0.05 * kEpsY,
                             s.strain + 0.5 * kEpsY,  // reversals past their linear start
                             s.strain - 0.5 * kEpsY,
                             s.strain + 3.0 * kEpsY,
                             s.strain - 3.0 * kEpsY,
                             at(0.5 * limit),
                             at(0.999 * limit),
                             at(1.001 * limit),
                             at(3.0 * limit),
                             at(0.4),
                             at(0.7),
                             at(1.5),
                             at(6.0),
                             std::nan(""),
                             anywhere(random),
                             anywhere(random)};
      for (const double e : near) fibers.emplace_back(s, e);
    }
    const auto [committed, strains] = testing::shuffledArrays(fibers, random);
    // Four or more fibers take the powers of steel02::LanePowers where the processor runs the
    // fours, fewer the C library's (every size below is four or more).
    const auto inFours = [&m](const Steel02::State& c, Steel02::State& trial, double e) {
      return Steel02::updatesFourAtOnce() ? m.computeTrialWith<steel02::LanePowers>(c, trial, e)
                                          : m.computeTrial(c, trial, e);
    };
    const std::size_t n = testing::expectEveryGroupSize(m, committed, strains, inFours);
    for (const std::size_t few : {std::size_t{1}, std::size_t{2}, std::size_t{3}})
      testing::expectEachFibersOwnUpdate(m, committed, strains, few);
    {
      SCOPED_TRACE("commits");
      testing::expectEveryGroupSizeCommits(m, committed, strains);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const auto& c = committed[i];
      const double e = strains[i];
      // What the fiber exercised, from computeTrial's own tests.
      const double deps = (e + epsIni) - (c.strain + epsIni);
      const double absRat = std::fabs((e + epsIni - c.epsR) * c.invSpan);
      if (c.kon == 0 || c.kon == 3) {
        ++virgin;
      } else if ((c.kon == 1 && deps < 0.0) || (c.kon == 2 && deps > 0.0)) {
        const bool shifted = c.kon == 1 ? params.a1 != 0.0 : params.a3 != 0.0;
        ++(shifted ? shiftedReversal : reversal);
      } else if (absRat < c.linearLimit) {
        ++line;
      } else if (std::exp(c.R * std::log(absRat)) < steel02::kSeriesLimit && c.R >= 1.0) {
        ++series;
      } else {
        ++power;
        if (c.R < 1.0) ++belowOne;
      }
    }
  }
  for (const int count : {virgin, reversal, shiftedReversal, line, series, power, belowOne})
    EXPECT_GT(count, 4);
}

}  // namespace
}  // namespace dabs::materials

namespace dabs::materials {
namespace {

// The four-lane powers (libmvec where the build has it) against the C library's, over the bases
// and curvatures a branch takes: within a few ulps of t = x^R for each of log's and exp's own
// errors, which R |log x| multiplies (the error of log x is relative to log x), and of the root.
TEST(Steel02Test, LanePowersAgreeWithTheCLibrarysToRoundOff) {
#if defined(__x86_64__) && defined(__GLIBC__)
  // The build this project supports (Debian, libc6-dev) has libmvec: the lanes must take it.
  EXPECT_TRUE(steel02::LanePowers::fromLibmvec());
#endif
  const bool distinct = steel02::LanePowers::fromLibmvec() && Steel02::updatesFourAtOnce();
  const double ulp = DBL_EPSILON;
  int compared = 0, differing = 0;
  for (double R = 1.0; R <= 25.0; R += 0.37) {
    for (double x = 1e-3; x < 40.0; x *= 1.07) {
      const double lane = steel02::LanePowers::power(x, R);
      const double libm = steel02::LibmPowers::power(x, R);
      differing += lane != libm ? 1 : 0;
      EXPECT_LE(std::fabs(lane - libm), (4.0 + 4.0 * R * std::fabs(std::log(x))) * ulp * libm)
          << "x " << x << " R " << R;
      const double base = 1.0 + libm;
      const double rootLane = steel02::LanePowers::root(base, 1.0 / R);
      const double rootLibm = steel02::LibmPowers::root(base, 1.0 / R);
      EXPECT_LE(std::fabs(rootLane - rootLibm), 4.0 * ulp * rootLibm) << "base " << base;
      ++compared;
    }
  }
  EXPECT_GT(compared, 5000);
  // Where libmvec serves the lanes its functions are not the C library's (about half the powers
  // differ in the last bits here), so this compares two implementations, not one with itself.
  if (distinct) {
    EXPECT_GT(differing, compared / 10);
  }
}

// The linear limit against e^(-38/R) from the C library: never above it beyond round-off (so
// |eps*|^R stays below half an ulp of 1 under it, which needs e^(-36.74/R)), never below it by
// more than 2^(1/4); zero for R < 1.
TEST(Steel02Test, LinearLimitIsWithinAQuarterPowerOfTwoBelowExpOfMinus38OverR) {
  EXPECT_EQ(steel02::linearLimit(0.999), 0.0);
  EXPECT_EQ(steel02::linearLimit(0.0), 0.0);
  EXPECT_EQ(steel02::linearLimit(std::nan("")), 0.0);
  for (double R = 1.0; R < 200.0; R *= 1.0007) {
    const double exact = std::exp(-38.0 / R);
    const double limit = steel02::linearLimit(R);
    ASSERT_LE(limit, exact * (1.0 + 1e-12)) << "R " << R;
    ASSERT_GE(limit, exact / 1.1892071150027211 * (1.0 - 1e-12)) << "R " << R;
    ASSERT_LT(std::pow(limit, R), 0.5 * DBL_EPSILON) << "R " << R;
  }
}

}  // namespace
}  // namespace dabs::materials
