// SPDX-License-Identifier: MIT
#include "contact/CoulombFriction.h"

#include <gtest/gtest.h>

#include "materials/InputError.h"

namespace dabs::contact {
namespace {

constexpr double kTol = 1e-12;
constexpr double kKt = 1000.0;

TEST(CoulombFrictionTest, StickGivesKtTimesElasticSlip) {
  const CoulombFriction f({kKt, 1.0, 0.5, 0.3});
  const auto r = f.returnMap<double>({0.001, -0.002}, 10.0, {0.0, 0.0}, false);
  EXPECT_FALSE(r.sliding);
  EXPECT_NEAR(r.force[0], -kKt * 0.001, kTol);
  EXPECT_NEAR(r.force[1], kKt * 0.002, kTol);
  EXPECT_EQ(r.plasticSlip, 0.0);
}

TEST(CoulombFrictionTest, SlideReturnsToKineticConeAndDissipates) {
  const CoulombFriction f({kKt, 1.0, 0.5, 0.3});
  const double N = 10.0;
  const std::array<double, 2> d{0.03, 0.04};  // |Kt d| = 50 > mu_s N = 5
  const auto r = f.returnMap<double>(d, N, {0.0, 0.0}, false);
  EXPECT_TRUE(r.sliding);
  EXPECT_NEAR(std::hypot(r.force[0], r.force[1]), 0.3 * N, kTol);  // |t| = mu_k N
  EXPECT_NEAR(r.force[0] / r.force[1], 0.75, kTol);                // along the trial force
  EXPECT_NEAR(r.elasticAfter.norm(), 0.3 * N / kKt, kTol);         // spring stays on the limit
  EXPECT_NEAR(r.plasticSlip, 0.05 - 0.3 * N / kKt, kTol);
  // Work of the friction force on the plastic slip is positive.
  const Eigen::Vector2d slip = Eigen::Vector2d(d[0], d[1]) - r.elasticAfter;
  EXPECT_GT(-(r.force[0] * slip(0) + r.force[1] * slip(1)), 0.0);
}

TEST(CoulombFrictionTest, KineticThresholdOnceSliding) {
  const CoulombFriction f({kKt, 1.0, 0.5, 0.3});
  const double N = 10.0;
  const std::array<double, 2> d{0.004, 0.0};  // |Kt d| = 4: under mu_s N = 5, over mu_k N = 3
  EXPECT_FALSE((f.returnMap<double>(d, N, {0.0, 0.0}, false).sliding));
  EXPECT_TRUE((f.returnMap<double>(d, N, {0.0, 0.0}, true).sliding));
}

TEST(CoulombFrictionTest, StickDashpotAndFrictionless) {
  const CoulombFriction damped({kKt, 0.5, 0.5, 0.5, 1.0, 1.0});
  EXPECT_GT(damped.damping(), 0.0);
  const auto r = damped.returnMap<double>({0.0, 0.0}, 10.0, {0.2, 0.0}, false);
  EXPECT_NEAR(r.force[0], -damped.damping() * 0.2, kTol);
  const CoulombFriction none({kKt, 1.0, 0.0, 0.0});
  EXPECT_FALSE(none.active());
  EXPECT_EQ((none.returnMap<double>({1.0, 1.0}, 10.0, {0.0, 0.0}, false).force[0]), 0.0);
}

TEST(CoulombFrictionTest, BadInputThrows) {
  EXPECT_THROW((CoulombFriction::Params{0.0}.validate()), InputError);
  EXPECT_THROW((CoulombFriction::Params{1.0, 1.0, 0.2, 0.3}.validate()),
               InputError);  // mu_k > mu_s
  EXPECT_THROW((CoulombFriction::Params{1.0, 1.0, -0.2, 0.0}.validate()), InputError);
  EXPECT_THROW((CoulombFriction::Params{1.0, 0.5, 0.2, 0.1}.validate()), InputError);  // masses
}

}  // namespace
}  // namespace dabs::contact
