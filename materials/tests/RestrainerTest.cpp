// SPDX-License-Identifier: MIT
// Restrainer (tension-only gap spring with yielding): closed-form force-displacement through the
// clearance in both directions, yielding, slack after yielding, FD tangent, trial/commit/revert.
#include "materials/GapSpring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/InputError.h"
#include "materials/tests/MaterialContract.h"

namespace dabs::materials {
namespace {

constexpr double kTol = 1e-12;      // closed forms evaluated in double precision
constexpr double kFdRelTol = 1e-5;  // style.md section 7
constexpr double kK = 100.0, kGap = 0.05, kFy = 2.0, kB = 0.1;

GapSpringParams yielding() { return {kK, kGap, kFy, kB}; }

double stressAt(UniaxialMaterial& m, double eps) {
  EXPECT_TRUE(ok(m.setTrialStrain(eps)));
  return m.getStress();
}

TEST(RestrainerTest, NoForceUntilOpeningExceedsGapThenLinear) {
  auto r = GapSpring::restrainer(1, {kK, kGap});
  EXPECT_EQ(stressAt(r, 0.03), 0.0);  // inside the clearance
  EXPECT_EQ(r.getTangent(), 0.0);
  EXPECT_EQ(stressAt(r, -0.5), 0.0);                         // closing: never compression
  EXPECT_NEAR(stressAt(r, 0.08), kK * (0.08 - kGap), kTol);  // F = k (u - gap)
  EXPECT_EQ(r.getTangent(), kK);
  EXPECT_EQ(r.getInitialTangent(), 0.0);
}

TEST(RestrainerTest, YieldsOnBilinearEnvelopeAndKeepsPermanentSlack) {
  auto r = GapSpring::restrainer(1, yielding());
  const double ey = kFy / kK;
  // Elastic up to Fy at opening gap + Fy/k.
  EXPECT_NEAR(stressAt(r, kGap + ey), kFy, kTol);
  // Post-yield slope b k: F = Fy + b k (e - ey).
  const double e1 = 0.05;
  const double f1 = kFy + kB * kK * (e1 - ey);
  EXPECT_NEAR(stressAt(r, kGap + e1), f1, kTol);
  EXPECT_NEAR(r.getTangent(), kB * kK, kTol);
  r.commitState();
  const double ep = e1 - f1 / kK;  // permanent elongation
  EXPECT_NEAR(*r.response("plasticElongation"), ep, kTol);
  // Unloading with slope k from (e1, f1).
  EXPECT_NEAR(stressAt(r, kGap + 0.03), kK * (0.03 - ep), kTol);
  EXPECT_EQ(r.getTangent(), kK);
  // Slack below gap + ep (the clearance grew by ep), though still beyond the original gap.
  EXPECT_EQ(stressAt(r, kGap + 0.5 * ep), 0.0);
  EXPECT_EQ(r.getTangent(), 0.0);
  // Reloading past the old peak continues on the envelope.
  const double e2 = 0.06;
  EXPECT_NEAR(stressAt(r, kGap + e2), kFy + kB * kK * (e2 - ey), kTol);
}

TEST(RestrainerTest, TrialIsIdempotentAndRevertRestoresCommitted) {
  auto r = GapSpring::restrainer(1, yielding());
  const double f = stressAt(r, kGap + 0.04);
  (void)stressAt(r, kGap + 0.2);  // a yielding trial that is not committed
  EXPECT_NEAR(stressAt(r, kGap + 0.04), f, kTol);
  r.commitState();
  (void)stressAt(r, kGap + 0.3);
  r.revertToLastCommit();
  EXPECT_EQ(r.getStrain(), kGap + 0.04);
  EXPECT_EQ(r.getStress(), f);
  r.revertToStart();
  EXPECT_EQ(r.getStrain(), 0.0);
  EXPECT_EQ(r.committedState().plastic, 0.0);
}

TEST(RestrainerTest, CloneIsIndependent) {
  auto r = GapSpring::restrainer(1, yielding());
  (void)stressAt(r, kGap + 0.1);
  r.commitState();
  auto c = r.clone();
  EXPECT_EQ(c->getStress(), r.getStress());
  EXPECT_TRUE(ok(c->setTrialStrain(0.0)));
  EXPECT_NE(c->getStress(), r.getStress());
}

TEST(RestrainerTest, TangentMatchesCentralDifferenceOnCyclicPath) {
  auto r = GapSpring::restrainer(1, yielding());
  const std::vector<double> path{0.02, 0.06, 0.08, 0.1, 0.09, 0.07, 0.0, -0.05, 0.06, 0.12, 0.13};
  const double ey = kFy / kK;
  int checked = 0;
  for (double eps : path) {
    const double h = 1e-6 * std::max(std::abs(eps), ey);
    const double fp = stressAt(r, eps + h), fm = stressAt(r, eps - h);
    const double f0 = stressAt(r, eps);
    const double kt = r.getTangent();
    // Skip points within 2h of a branch switch: the one-sided slopes disagree there.
    const double right = (fp - f0) / h, left = (f0 - fm) / h;
    if (std::abs(right - left) <= 1e-3 * kK) {
      EXPECT_NEAR(kt, (fp - fm) / (2 * h), kFdRelTol * kK) << "strain " << eps;
      ++checked;
    }
    r.commitState();
  }
  EXPECT_GE(checked, 8);
}

TEST(RestrainerTest, BadInputThrowsNamingTheField) {
  auto field = [](GapSpringParams p) {
    try {
      p.validate();
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("none");
  };
  EXPECT_EQ(field({0.0, 0.1}), "k");
  EXPECT_EQ(field({-5.0, 0.1}), "k");
  EXPECT_EQ(field({10.0, -0.1}), "gap");
  EXPECT_EQ(field({10.0, 0.1, 0.0, 0.0}), "Fy");
  EXPECT_EQ(field({10.0, 0.1, 1.0, 1.0}), "b");
  EXPECT_EQ(field({10.0, 0.1, 1.0, -0.1}), "b");
  EXPECT_EQ(field({10.0, 0.0, 1.0, 0.5}), "none");
}

TEST(RestrainerTest, ZeroGapEngagesAtFirstOpening) {
  auto r = GapSpring::restrainer(1, {kK, 0.0});
  EXPECT_EQ(r.getInitialTangent(), kK);
  EXPECT_NEAR(stressAt(r, 1e-3), kK * 1e-3, kTol);
  EXPECT_EQ(stressAt(r, -1e-3), 0.0);
}

}  // namespace

namespace testing {

// The shared material contract (MaterialContract.h) on a cyclic path through the clearance in
// both directions and well past yield.
struct RestrainerContractCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<GapSpring>(
        GapSpring::restrainer(1, GapSpringParams{100.0, 0.05, 2.0, 0.1}));
  }
  static std::vector<double> path() { return testing::cyclicPath(strainScale()); }
  static double strainScale() { return 0.05 + 2.0 / 100.0; }
  static constexpr bool kRateDependent = false;
};
using RestrainerContractCases = ::testing::Types<RestrainerContractCase>;
INSTANTIATE_TYPED_TEST_SUITE_P(Restrainer, MaterialContract, RestrainerContractCases);

}  // namespace testing

}  // namespace dabs::materials
