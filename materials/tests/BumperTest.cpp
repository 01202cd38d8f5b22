// SPDX-License-Identifier: MIT
// Bumper (compression-only gap spring with crushing): closed-form force-displacement through the
// clearance in both directions, yielding, FD tangent, trial/commit/revert.
#include "materials/GapSpring.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/InputError.h"
#include "materials/tests/MaterialContract.h"

namespace dabs::materials {
namespace {

constexpr double kTol = 1e-12;
constexpr double kFdRelTol = 1e-5;
constexpr double kK = 250.0, kGap = 0.02, kFy = 5.0, kB = 0.05;

double stressAt(UniaxialMaterial& m, double eps) {
  EXPECT_TRUE(ok(m.setTrialStrain(eps)));
  return m.getStress();
}

TEST(BumperTest, NoForceUntilClosingExceedsGapThenCompression) {
  auto b = GapSpring::bumper(2, {kK, kGap});
  EXPECT_EQ(stressAt(b, -0.01), 0.0);                          // inside the clearance
  EXPECT_EQ(stressAt(b, 0.5), 0.0);                            // opening: never tension
  EXPECT_NEAR(stressAt(b, -0.05), -kK * (0.05 - kGap), kTol);  // F = -k (closing - gap)
  EXPECT_EQ(b.getTangent(), kK);
  EXPECT_EQ(b.getInitialTangent(), 0.0);
}

TEST(BumperTest, CrushesOnBilinearEnvelopeAndClearanceGrows) {
  auto b = GapSpring::bumper(2, {kK, kGap, kFy, kB});
  const double ey = kFy / kK;
  EXPECT_NEAR(stressAt(b, -(kGap + ey)), -kFy, kTol);
  const double e1 = 0.1;
  const double f1 = kFy + kB * kK * (e1 - ey);
  EXPECT_NEAR(stressAt(b, -(kGap + e1)), -f1, kTol);
  EXPECT_NEAR(b.getTangent(), kB * kK, kTol);
  b.commitState();
  const double ep = e1 - f1 / kK;
  EXPECT_NEAR(*b.response("plasticCrush"), ep, kTol);
  EXPECT_NEAR(stressAt(b, -(kGap + 0.09)), -kK * (0.09 - ep), kTol);  // elastic unloading
  EXPECT_EQ(stressAt(b, -(kGap + 0.5 * ep)), 0.0);                    // clearance is now gap + ep
  b.revertToLastCommit();
  EXPECT_NEAR(b.getStress(), -f1, kTol);
}

TEST(BumperTest, TangentMatchesCentralDifferenceOnCyclicPath) {
  auto b = GapSpring::bumper(2, {kK, kGap, kFy, kB});
  const std::vector<double> path{-0.01, -0.03, -0.05, -0.08, -0.07, -0.04, 0.1, -0.06, -0.12};
  const double ey = kFy / kK;
  int checked = 0;
  for (double eps : path) {
    const double h = 1e-6 * std::max(std::abs(eps), ey);
    const double fp = stressAt(b, eps + h), fm = stressAt(b, eps - h);
    const double f0 = stressAt(b, eps);
    const double kt = b.getTangent();
    const double right = (fp - f0) / h, left = (f0 - fm) / h;
    if (std::abs(right - left) <= 1e-3 * kK) {
      EXPECT_NEAR(kt, (fp - fm) / (2 * h), kFdRelTol * kK) << "strain " << eps;
      ++checked;
    }
    b.commitState();
  }
  EXPECT_GE(checked, 7);
}

TEST(BumperTest, TrialIsIdempotentAndRevertToStartClearsCrush) {
  auto b = GapSpring::bumper(2, {kK, kGap, kFy, kB});
  const double f = stressAt(b, -0.04);
  (void)stressAt(b, -0.5);
  EXPECT_NEAR(stressAt(b, -0.04), f, kTol);
  (void)stressAt(b, -0.5);
  b.commitState();
  EXPECT_GT(b.committedState().plastic, 0.0);
  b.revertToStart();
  EXPECT_EQ(b.committedState().plastic, 0.0);
  EXPECT_EQ(b.getStress(), 0.0);
}

TEST(BumperTest, BadInputThrows) {
  EXPECT_THROW((GapSpringParams{0.0, 0.1}.validate()), InputError);
  EXPECT_THROW((GapSpringParams{1.0, -0.1}.validate()), InputError);
  EXPECT_THROW((GapSpringParams{1.0, 0.1, -1.0, 0.0}.validate()), InputError);
  EXPECT_THROW((GapSpringParams{1.0, 0.1, 1.0, 1.5}.validate()), InputError);
  EXPECT_NO_THROW((GapSpringParams{1.0, 0.0}.validate()));
}

}  // namespace

namespace testing {

// The shared material contract (MaterialContract.h) on a cyclic path through the clearance in
// both directions and well past yield.
struct BumperContractCase {
  static std::unique_ptr<UniaxialMaterial> make() {
    return std::make_unique<GapSpring>(
        GapSpring::bumper(1, GapSpringParams{250.0, 0.02, 5.0, 0.05}));
  }
  static std::vector<double> path() { return testing::cyclicPath(strainScale()); }
  static double strainScale() { return 0.02 + 5.0 / 250.0; }
  static constexpr bool kRateDependent = false;
};
using BumperContractCases = ::testing::Types<BumperContractCase>;
INSTANTIATE_TYPED_TEST_SUITE_P(Bumper, MaterialContract, BumperContractCases);

}  // namespace testing

}  // namespace dabs::materials
