// SPDX-License-Identifier: MIT
#include "materials/Fatigue.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/InputError.h"
#include "materials/Steel02.h"
#include "materials/tests/MaterialContract.h"

namespace dabs::materials {
namespace {

/// Relative tolerance of damage sums (a few additions of round-off).
constexpr double kDamageTol = 1e-12;
constexpr double kE = 2.0e5;

Fatigue::Params paramsFor(const UniaxialMaterial& m, double E0, double slope) {
  Fatigue::Params p;
  p.material = &m;
  p.E0 = E0;
  p.m = slope;
  return p;
}

}  // namespace

// --- the material contract ------------------------------------------------------------------
// (in the contract's namespace: the typed-suite macros name its registration objects)
namespace testing {
namespace {

/// Steel02 that fails by fatigue half way along the contract's cyclic path (E0 small).
struct FatigueSteel02Case {
  static std::unique_ptr<UniaxialMaterial> make() {
    const Steel02 steel(1, Steel02::Params{400.0, kE, 0.01});
    return std::make_unique<Fatigue>(10, paramsFor(steel, 0.012, -0.5));
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return testing::cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

/// ElasticPP that fails at the strain limit -max (between path points) late in the path.
struct FatigueStrainLimitCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    const ElasticPP epp(2, ElasticPP::Params{kE, 0.002, std::nullopt, 0.0});
    Fatigue::Params p;
    p.material = &epp;
    p.maxStrain = 3.3 * strainScale();
    return std::make_unique<Fatigue>(11, p);
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return testing::cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

/// OpenSees' default parameters: no failure along the path, only damage.
struct FatigueDefaultCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    const Steel02 steel(1, Steel02::Params{400.0, kE, 0.01});
    Fatigue::Params p;
    p.material = &steel;
    return std::make_unique<Fatigue>(12, p);
  }
  static double strainScale() { return 0.002; }
  static std::vector<double> path() { return testing::cyclicPath(strainScale()); }
  static constexpr bool kRateDependent = false;
};

using FatigueCases =
    ::testing::Types<FatigueSteel02Case, FatigueStrainLimitCase, FatigueDefaultCase>;
INSTANTIATE_TYPED_TEST_SUITE_P(Fatigue, MaterialContract, FatigueCases);

}  // namespace
}  // namespace testing

namespace {
using testing::FatigueDefaultCase;
using testing::FatigueSteel02Case;
using testing::FatigueStrainLimitCase;

/// Index of the first committed point of `path` at which `m` has failed, or path.size().
std::size_t failurePoint(UniaxialMaterial& m, const std::vector<double>& path) {
  for (std::size_t k = 0; k < path.size(); ++k) {
    EXPECT_TRUE(ok(m.setTrialStrain(path[k])));
    m.commitState();
    if (*m.response("failure") == 1.0) return k;
  }
  return path.size();
}

TEST(FatigueTest, ContractPathsCoverFailureAndLife) {
  // The contract cases above are meant to cross failure inside their paths, so that the contract
  // also holds the failed material.
  const auto path = FatigueSteel02Case::path();
  auto a = FatigueSteel02Case::make();
  const std::size_t ka = failurePoint(*a, path);
  EXPECT_GT(ka, path.size() / 4) << ka;
  EXPECT_LT(ka, path.size() - 32) << "at least two segments after failure";
  auto b = FatigueStrainLimitCase::make();
  EXPECT_LT(failurePoint(*b, path), path.size());
  auto c = FatigueDefaultCase::make();
  EXPECT_EQ(failurePoint(*c, path), path.size());
  EXPECT_GT(*c->response("damage"), 0.0);
}

// --- Miner's rule against the closed form ---------------------------------------------------

/// Cycles to failure at strain range r: N = (r / E0)^(1/m) (Coffin-Manson, range = E0 N^m).
double cyclesToFailure(double range, double E0, double m) { return std::pow(range / E0, 1.0 / m); }

/// Strains 0, then cycles between +a and -a in `perHalf` steps per half cycle.
std::vector<double> constantAmplitude(double a, int halves, int perHalf) {
  std::vector<double> out{0.0};
  for (int i = 1; i <= perHalf / 2; ++i) out.push_back(a * i / (perHalf / 2));
  double from = a;
  for (int h = 0; h < halves; ++h) {
    const double to = -from;
    for (int i = 1; i <= perHalf; ++i) out.push_back(from + (to - from) * i / perHalf);
    from = to;
  }
  return out;
}

TEST(FatigueTest, ConstantAmplitudeDamageIsMinersSum) {
  // The first peak (+a) only opens the count; the second closes the half cycle 0 to +a (range a);
  // every later reversal closes a half cycle of range 2a. After n >= 2 counted reversals:
  // D = 1/(2 N(a)) + (n - 2)/(2 N(2a)).
  const double a = 0.01, E0 = 0.191, m = -0.458;
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  Fatigue f(2, paramsFor(elastic, E0, m));
  const int perHalf = 20;
  const auto path = constantAmplitude(a, 12, perHalf);
  int reversals = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    ASSERT_TRUE(ok(f.setTrialStrain(path[k])));
    f.commitState();
    // A peak is counted one step after it (the step that shows the reversal).
    if (k > 1 && (path[k - 1] - path[k - 2]) * (path[k] - path[k - 1]) < 0.0) ++reversals;
    const double expected = reversals < 2
                                ? 0.0
                                : 0.5 / cyclesToFailure(a, E0, m) +
                                      (reversals - 2) * 0.5 / cyclesToFailure(2 * a, E0, m);
    ASSERT_NEAR(*f.response("damage"), expected, kDamageTol * std::max(expected, 1.0))
        << "point " << k;
  }
  EXPECT_EQ(reversals, 12);
  EXPECT_EQ(*f.response("failure"), 0.0);
}

TEST(FatigueTest, ConstantAmplitudeFailsInTheCycleOfTheClosedForm) {
  // Range 2a = 0.02 with E0 = 0.1, m = -0.5: N_f = (0.2)^-2 = 25 full cycles. Failure comes at
  // a pseudo peak (counted damage plus the open half cycle), in tension, inside cycle 25.
  const double a = 0.01, E0 = 0.1, m = -0.5;
  const double nf = cyclesToFailure(2 * a, E0, m);
  ASSERT_NEAR(nf, 25.0, 1e-9);
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  Fatigue f(2, paramsFor(elastic, E0, m));
  const int perHalf = 40;
  const auto path = constantAmplitude(a, 60, perHalf);
  std::size_t failedAt = path.size();
  for (std::size_t k = 0; k < path.size(); ++k) {
    ASSERT_TRUE(ok(f.setTrialStrain(path[k])));
    f.commitState();
    if (*f.response("failure") == 1.0) {
      failedAt = k;
      break;
    }
  }
  ASSERT_LT(failedAt, path.size());
  EXPECT_GT(path[failedAt], 0.0) << "fails only under tensile stress";
  // Full cycles completed before the failing step (the path starts with a quarter cycle).
  const double cycles = (static_cast<double>(failedAt) - perHalf / 2) / (2.0 * perHalf);
  EXPECT_GT(cycles, nf - 1.0);
  EXPECT_LE(cycles, nf);
  // The damage at failure just exceeds 1, by less than one step's worth of damage.
  const double d = *f.response("damage");
  EXPECT_GT(d, 1.0);
  EXPECT_LT(d, 1.0 + 1.0 / nf);
  // Failed: 1e-8 of the wrapped stress and initial tangent.
  EXPECT_DOUBLE_EQ(f.getStress(), 1e-8 * (kE * path[failedAt]));
  EXPECT_DOUBLE_EQ(f.getTangent(), 1e-8 * kE);
}

TEST(FatigueTest, DmaxBringsFailureForward) {
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  auto p = paramsFor(elastic, 0.1, -0.5);
  const auto path = constantAmplitude(0.01, 60, 40);
  Fatigue full(2, p);
  p.Dmax = 0.5;
  Fatigue half(3, p);
  const std::size_t kFull = failurePoint(full, path);
  const std::size_t kHalf = failurePoint(half, path);
  EXPECT_LT(kHalf, kFull);
  EXPECT_GT(*half.response("damage"), 0.5);
  EXPECT_LT(*half.response("damage"), 0.6);
}

// --- strain limits, commit and revert around failure -----------------------------------------

TEST(FatigueTest, StrainLimitsFailTheMaterial) {
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  Fatigue::Params p;
  p.material = &elastic;
  p.minStrain = -0.02;
  p.maxStrain = 0.01;
  Fatigue f(2, p);
  ASSERT_TRUE(ok(f.setTrialStrain(0.0099)));
  EXPECT_DOUBLE_EQ(f.getStress(), kE * 0.0099);
  EXPECT_EQ(*f.response("failure"), 0.0);
  ASSERT_TRUE(ok(f.setTrialStrain(0.01)));  // the limit itself fails (>= max)
  EXPECT_EQ(*f.response("failure"), 1.0);
  EXPECT_DOUBLE_EQ(*f.response("damage"), 1.0);  // Dmax, as OpenSees sets it
  EXPECT_DOUBLE_EQ(f.getStress(), 1e-8 * (kE * 0.01));
  EXPECT_DOUBLE_EQ(f.getTangent(), 1e-8 * kE);

  Fatigue g(3, p);
  ASSERT_TRUE(ok(g.setTrialStrain(-0.0199)));
  EXPECT_EQ(*g.response("failure"), 0.0);
  ASSERT_TRUE(ok(g.setTrialStrain(-0.02)));
  EXPECT_EQ(*g.response("failure"), 1.0);
}

TEST(FatigueTest, RevertUndoesATrialFailureAndCommitKeepsIt) {
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  Fatigue::Params p;
  p.material = &elastic;
  p.maxStrain = 0.01;
  Fatigue f(2, p);
  ASSERT_TRUE(ok(f.setTrialStrain(0.005)));
  f.commitState();
  ASSERT_TRUE(ok(f.setTrialStrain(0.02)));
  EXPECT_EQ(*f.response("failure"), 1.0);
  f.revertToLastCommit();
  EXPECT_EQ(*f.response("failure"), 0.0);
  EXPECT_DOUBLE_EQ(f.getStress(), kE * 0.005);
  // A trial back inside the limits after a failed trial: no trace of it.
  ASSERT_TRUE(ok(f.setTrialStrain(0.02)));
  ASSERT_TRUE(ok(f.setTrialStrain(0.006)));
  EXPECT_EQ(*f.response("failure"), 0.0);
  EXPECT_DOUBLE_EQ(f.getStress(), kE * 0.006);
  // Committed failure is for good, also back inside the limits ...
  ASSERT_TRUE(ok(f.setTrialStrain(0.02)));
  f.commitState();
  ASSERT_TRUE(ok(f.setTrialStrain(0.0)));
  EXPECT_EQ(*f.response("failure"), 1.0);
  f.revertToLastCommit();
  EXPECT_EQ(*f.response("failure"), 1.0);
  EXPECT_DOUBLE_EQ(f.getStrain(), 0.02);
  EXPECT_DOUBLE_EQ(f.getStress(), 1e-8 * (kE * 0.02));
  // ... until revertToStart.
  f.revertToStart();
  EXPECT_EQ(*f.response("failure"), 0.0);
  EXPECT_EQ(*f.response("damage"), 0.0);
  ASSERT_TRUE(ok(f.setTrialStrain(0.005)));
  EXPECT_DOUBLE_EQ(f.getStress(), kE * 0.005);
}

TEST(FatigueTest, FailedMaterialFollowsTheWrappedStateBeforeFailure) {
  // After failure the wrapped material is no longer committed (OpenSees): its trials start from
  // the last state committed before the failing step.
  const Steel02 steel(1, Steel02::Params{400.0, kE, 0.01});
  Fatigue::Params p;
  p.material = &steel;
  p.maxStrain = 0.012;
  Fatigue f(2, p);
  Steel02 reference(3, Steel02::Params{400.0, kE, 0.01});
  for (double e : {0.004, 0.008, -0.002, 0.011}) {
    ASSERT_TRUE(ok(f.setTrialStrain(e)));
    f.commitState();
    ASSERT_TRUE(ok(reference.setTrialStrain(e)));
    reference.commitState();
  }
  ASSERT_TRUE(ok(f.setTrialStrain(0.013)));  // fails: the step is not committed in the steel
  f.commitState();
  ASSERT_EQ(*f.response("failure"), 1.0);
  for (double e : {0.013, 0.0, -0.01}) {
    ASSERT_TRUE(ok(f.setTrialStrain(e)));
    f.commitState();
    ASSERT_TRUE(ok(reference.setTrialStrain(e)));  // never committed
    EXPECT_DOUBLE_EQ(f.getStress(), 1e-8 * reference.getStress()) << "strain " << e;
    EXPECT_DOUBLE_EQ(f.getTangent(), 1e-8 * kE);
  }
}

// --- parameters -------------------------------------------------------------------------------

TEST(FatigueTest, ParamsValidateNamesTheField) {
  const Elastic elastic(1, Elastic::Params{kE, 0.0, std::nullopt});
  auto fieldOf = [](const Fatigue::Params& p) {
    try {
      p.validate();
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string();
  };
  Fatigue::Params p;
  EXPECT_EQ(fieldOf(p), "matTag");
  p.material = &elastic;
  EXPECT_EQ(fieldOf(p), "");
  auto with = [&](auto edit) {
    Fatigue::Params q = p;
    edit(q);
    return fieldOf(q);
  };
  EXPECT_EQ(with([](auto& q) { q.E0 = 0.0; }), "E0");
  EXPECT_EQ(with([](auto& q) { q.E0 = NAN; }), "E0");
  EXPECT_EQ(with([](auto& q) { q.m = 0.0; }), "m");
  EXPECT_EQ(with([](auto& q) { q.m = 0.5; }), "m");
  EXPECT_EQ(with([](auto& q) { q.Dmax = 0.0; }), "Dmax");
  EXPECT_EQ(with([](auto& q) { q.Dmax = 1.5; }), "Dmax");
  EXPECT_EQ(with([](auto& q) { q.maxStrain = q.minStrain; }), "max");
  EXPECT_EQ(with([](auto& q) { q.minStrain = NAN; }), "min");
}

}  // namespace
}  // namespace dabs::materials
