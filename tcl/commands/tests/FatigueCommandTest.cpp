// SPDX-License-Identifier: MIT
// `uniaxialMaterial Fatigue` through the interpreter: the material runs under the material tester,
// and bad input is a Tcl error naming the command, the argument and what was expected, with no
// material left behind.

#include <gtest/gtest.h>

#include <string>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl {
namespace {

class FatigueCommandTest : public testing::TclFixture {
 protected:
  void SetUp() override {
    TclFixture::SetUp();
    ok("model basic -ndm 1 -ndf 1; uniaxialMaterial Elastic 1 200000.0");
  }
  /// True when a material with this tag exists (testUniaxialMaterial accepts it).
  bool exists(int tag) {
    return Tcl_Eval(interp_, ("testUniaxialMaterial " + std::to_string(tag)).c_str()) == TCL_OK;
  }
};

::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

TEST_F(FatigueCommandTest, OptionsInAnyOrderAndStrainLimit) {
  ok("uniaxialMaterial Fatigue 2 1 -max 0.01 -m -0.5 -E0 0.1 -min -0.02 -Dmax 0.9");
  ok("testUniaxialMaterial 2; setStrain 0.005");
  EXPECT_DOUBLE_EQ(number("getStress"), 1000.0);
  ok("setStrain 0.01");
  EXPECT_DOUBLE_EQ(number("getStress"), 1e-8 * 2000.0);
  EXPECT_DOUBLE_EQ(number("getTangent"), 1e-8 * 200000.0);
}

TEST_F(FatigueCommandTest, ZeroLengthSpringFailsAtTheStrainLimitInAnAnalysis) {
  // The Fatigue spring (1-2) in series with an elastic one (2-3) whose end is pulled by 0.01 a
  // step: the second step crosses -max, the spring drops its force, the elastic one takes the
  // whole displacement. Damage and failure are recorded through zeroLength's material responses.
  ok("node 1 0; node 2 0; node 3 0; fix 1 1; uniaxialMaterial Fatigue 2 1 -max 0.01");
  ok("element zeroLength 1 1 2 -mat 2 -dir 1; element zeroLength 2 2 3 -mat 1 -dir 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { sp 3 1 0.04 }");
  ok("constraints Transformation; numberer Plain; system BandGeneral; test NormDispIncr 1e-12 20");
  ok("algorithm Newton; integrator LoadControl 0.25; analysis Static");
  EXPECT_EQ(ok("analyze 1"), "0");
  EXPECT_DOUBLE_EQ(number("nodeDisp 2 1"), 0.005);
  EXPECT_DOUBLE_EQ(number("eleResponse 1 material 1 damage"), 0.0);
  EXPECT_DOUBLE_EQ(number("eleResponse 1 material 1 failure"), 0.0);
  EXPECT_EQ(ok("analyze 1"), "0");
  EXPECT_DOUBLE_EQ(number("eleResponse 1 material 1 damage"), 1.0);
  EXPECT_DOUBLE_EQ(number("eleResponse 1 material 1 failure"), 1.0);
  EXPECT_NEAR(number("nodeDisp 2 1"), 0.02, 1e-8);
}

TEST_F(FatigueCommandTest, BadInputNamesTheArgumentAndLeavesNoMaterial) {
  struct Case {
    const char* script;
    const char* message;
  };
  const Case cases[] = {
      {"uniaxialMaterial Fatigue 2", "(matTag)"},
      {"uniaxialMaterial Fatigue 2 9", "argument 3 (matTag) uniaxialMaterial 9 does not exist"},
      {"uniaxialMaterial Fatigue 2 x", "argument 3 (matTag) expected an integer"},
      {"uniaxialMaterial Fatigue 2 1 -E0 abc",
       "argument 5 (-E0) expected a number after -E0, got \"abc\""},
      {"uniaxialMaterial Fatigue 2 1 -E0 -0.1", "E0 must be positive"},
      {"uniaxialMaterial Fatigue 2 1 -m 0.4", "m must be negative"},
      {"uniaxialMaterial Fatigue 2 1 -Dmax 2", "Dmax must be in (0, 1]"},
      {"uniaxialMaterial Fatigue 2 1 -min 0.1 -max 0.05", "max must be greater than min"},
      {"uniaxialMaterial Fatigue 2 1 -D_max 0.5", "-D_max"},
      {"uniaxialMaterial Fatigue 2 1 3", "3"},
  };
  for (const auto& c : cases) {
    const std::string message = error(c.script);
    EXPECT_TRUE(Contains(message, "uniaxialMaterial Fatigue")) << c.script;
    EXPECT_TRUE(Contains(message, c.message)) << c.script;
    EXPECT_FALSE(exists(2)) << c.script;
  }
}

}  // namespace
}  // namespace dabs::tcl
