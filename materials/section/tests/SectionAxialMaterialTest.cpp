// SPDX-License-Identifier: MIT
// The axial resultant of a section as a uniaxial material (trusses on sections): it reproduces
// the material carrying P in a one-material section, with its state protocol, and refuses a
// section without an axial resultant.
#include "materials/section/SectionAxialMaterial.h"

#include <gtest/gtest.h>

#include "materials/InputError.h"
#include "materials/Steel01.h"
#include "materials/section/SectionAggregator.h"

namespace dabs::materials::section {
namespace {

Steel01 steel() {
  Steel01::Params p;
  p.Fy = 350.0;
  p.E0 = 2.0e5;
  p.b = 0.01;
  p.validate();
  return Steel01(1, p);
}

TEST(SectionAxialMaterialTest, FollowsTheMaterialCarryingP) {
  const Steel01 proto = steel();
  Steel01 alone = steel();
  SectionAxialMaterial axial(std::make_unique<SectionAggregator>(
      3, std::vector<SectionAggregator::Part>{{&proto, SectionCode::Mz}, {&proto, SectionCode::P}},
      nullptr));
  for (double e : {0.001, 0.004, 0.002, -0.003}) {
    ASSERT_TRUE(ok(axial.setTrialStrain(e)));
    ASSERT_TRUE(ok(alone.setTrialStrain(e)));
    EXPECT_EQ(axial.getStress(), alone.getStress()) << e;
    EXPECT_EQ(axial.getTangent(), alone.getTangent()) << e;
    EXPECT_EQ(axial.getStrain(), e);
    axial.commitState();
    alone.commitState();
  }
  EXPECT_EQ(axial.getInitialTangent(), 2.0e5);
  const auto copy = axial.clone();
  ASSERT_TRUE(ok(axial.setTrialStrain(0.01)));
  axial.revertToLastCommit();
  EXPECT_EQ(axial.getStress(), alone.getStress());
  EXPECT_EQ(copy->getStress(), alone.getStress());
  axial.revertToStart();
  EXPECT_EQ(axial.getStress(), 0.0);
}

TEST(SectionAxialMaterialTest, RefusesASectionWithoutAxialResultant) {
  const Steel01 proto = steel();
  EXPECT_THROW(SectionAxialMaterial(std::make_unique<SectionAggregator>(
                   3, std::vector<SectionAggregator::Part>{{&proto, SectionCode::Mz}}, nullptr)),
               InputError);
}

}  // namespace
}  // namespace dabs::materials::section
