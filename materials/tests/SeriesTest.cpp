// SPDX-License-Identifier: MIT
#include "materials/Series.h"

#include <gtest/gtest.h>

#include "materials/ENT.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"

namespace dabs::materials {
namespace {

constexpr double kTol = 1e-9;

TEST(SeriesTest, SpringsInSeriesAddFlexibilities) {
  const Elastic a(1, Elastic::Params{100.0, 0.0, std::nullopt});
  const Elastic b(2, Elastic::Params{300.0, 0.0, std::nullopt});
  Series m(3, Series::Params{{&a, &b}});
  EXPECT_DOUBLE_EQ(m.getInitialTangent(), 75.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.04)));
  EXPECT_NEAR(m.getStress(), 3.0, kTol);
  EXPECT_NEAR(m.getTangent(), 75.0, kTol);
  EXPECT_NEAR(m.componentStrain(0), 0.03, kTol);
  EXPECT_NEAR(m.componentStrain(1), 0.01, kTol);
}

TEST(SeriesTest, YieldedComponentTakesTheStrain) {
  const ElasticPP epp(1, ElasticPP::Params{1000.0, 0.001, std::nullopt, 0.0});
  const Elastic spring(2, Elastic::Params{1000.0, 0.0, std::nullopt});
  Series m(3, Series::Params{{&epp, &spring}});
  ASSERT_TRUE(ok(m.setTrialStrain(0.01)));
  EXPECT_NEAR(m.getStress(), 1.0, kTol);  // capped by the EPP yield stress
  EXPECT_NEAR(m.componentStrain(1), 0.001, kTol);
  EXPECT_NEAR(m.componentStrain(0), 0.009, kTol);
}

TEST(SeriesTest, NoTensionComponentOpens) {
  const ENT ent(1, ENT::Params{1000.0});
  const Elastic spring(2, Elastic::Params{1000.0, 0.0, std::nullopt});
  Series m(3, Series::Params{{&ent, &spring}});
  ASSERT_TRUE(ok(m.setTrialStrain(-0.002)));
  EXPECT_NEAR(m.getStress(), -1.0, kTol);
  ASSERT_TRUE(ok(m.setTrialStrain(0.002)));
  EXPECT_NEAR(m.getStress(), 0.0, kTol);
}

TEST(SeriesTest, ReportsNotConvergedInsteadOfHanging) {
  const ElasticPP epp(1, ElasticPP::Params{1000.0, 0.001, std::nullopt, 0.0});
  const Elastic spring(2, Elastic::Params{1000.0, 0.0, std::nullopt});
  Series::Params p{{&epp, &spring}};
  p.maxIterations = 1;  // one Newton step cannot resolve the yield of the EPP component
  Series m(3, p);
  EXPECT_EQ(m.setTrialStrain(0.01), Status::NotConverged);
}

}  // namespace
}  // namespace dabs::materials
