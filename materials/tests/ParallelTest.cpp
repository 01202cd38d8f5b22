// SPDX-License-Identifier: MIT
#include "materials/Parallel.h"

#include <gtest/gtest.h>

#include "materials/Elastic.h"
#include "materials/ElasticPP.h"

namespace dabs::materials {
namespace {

TEST(ParallelTest, WeightedSumOfComponents) {
  const ElasticPP epp(1, ElasticPP::Params{1000.0, 0.001, std::nullopt, 0.0});
  const Elastic spring(2, Elastic::Params{100.0, 3.0, std::nullopt});
  Parallel m(3, Parallel::Params{{&epp, &spring}, {2.0, 1.5}});
  EXPECT_DOUBLE_EQ(m.getInitialTangent(), 2.0 * 1000.0 + 1.5 * 100.0);
  ASSERT_TRUE(ok(m.setTrialStrain(0.004, 0.5)));
  EXPECT_DOUBLE_EQ(m.getStress(), 2.0 * 1.0 + 1.5 * (100.0 * 0.004 + 3.0 * 0.5));
  EXPECT_DOUBLE_EQ(m.getTangent(), 1.5 * 100.0);  // the EPP branch has yielded
  EXPECT_DOUBLE_EQ(m.getDampTangent(), 1.5 * 3.0);
}

}  // namespace
}  // namespace dabs::materials
