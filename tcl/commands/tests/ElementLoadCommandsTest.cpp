// SPDX-License-Identifier: MIT
// The element-side commands that follow OpenSees' syntax: eleLoad, section Uniaxial, truss on a
// section, corotTruss, the integration rule in the beam commands, and imposedSupportMotion on a
// fixed dof. Each bad input is a Tcl error naming the command and what was expected, and leaves
// the model as it was.
#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl::testing {

using ElementLoadCommandsTest = TclFixture;

namespace {
constexpr const char* kBeam2d =
    "model basic -ndm 2 -ndf 3; node 1 0 0; node 2 4 0; node 3 8 0; fix 1 1 1 1;"
    "geomTransf Linear 1; element elasticBeamColumn 1 1 2 0.01 2.0e8 1.0e-4 1;"
    "element elasticBeamColumn 2 2 3 0.01 2.0e8 1.0e-4 1; timeSeries Linear 1;";
}  // namespace

TEST_F(ElementLoadCommandsTest, EleLoadNeedsAPatternElementsAndAType) {
  ok(kBeam2d);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamUniform -1.0").find("no load pattern"),
            std::string::npos);
  ok("pattern Plain 1 1 {}");
  EXPECT_NE(error("eleLoad -type -beamUniform -1.0").find("-ele tags"), std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -beamUniform -1.0").find("-type"), std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamThermal 1.0").find("-beamUniform or -beamPoint"),
            std::string::npos);
  EXPECT_NE(error("eleLoad -ele 7 -type -beamUniform -1.0").find("element 7 does not exist"),
            std::string::npos);
  EXPECT_NE(error("eleLoad -range 3 1 -type -beamUniform -1.0").find("last tag"),
            std::string::npos);
}

TEST_F(ElementLoadCommandsTest, EleLoadChecksItsValues) {
  ok(kBeam2d);
  ok("pattern Plain 1 1 {}");
  EXPECT_NE(error("eleLoad -ele 1 -type -beamPoint -1.0 1.5").find("0 <= xL <= 1"),
            std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamPoint -1.0").find("Py xL"), std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamUniform -1.0 0 0.6 0.4").find("aOverL < bOverL"),
            std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamUniform -1.0 0 0 1 -2.0 0 7").find("at most 6 values"),
            std::string::npos);
  EXPECT_NE(error("eleLoad -ele 1 -type -beamUniform abc").find("expected a number"),
            std::string::npos);
  // Good loads on both elements, with -ele and -range.
  ok("eleLoad -ele 1 2 -type -beamUniform -1.0; eleLoad -range 1 2 -type -beamPoint 2.0 0.5 1.0");
}

TEST_F(ElementLoadCommandsTest, EleLoadRefusesElementsWithoutMemberLoads) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 4 0; uniaxialMaterial Elastic 1 100.0;"
     "element truss 1 1 2 1.0 1; timeSeries Linear 1; pattern Plain 1 1 {}");
  EXPECT_NE(error("eleLoad -ele 1 -type -beamUniform -1.0").find("takes no member loads"),
            std::string::npos);
}

TEST_F(ElementLoadCommandsTest, LoadedElementStaysUntilItsPatternGoes) {
  ok(kBeam2d);
  ok("pattern Plain 1 1 { eleLoad -ele 2 -type -beamUniform -1.0 }");
  EXPECT_NE(error("remove element 2").find("loaded by pattern 1"), std::string::npos);
  ok("remove loadPattern 1; remove element 2");
}

TEST_F(ElementLoadCommandsTest, SectionUniaxialAndTrussOnASection) {
  ok("model basic -ndm 2 -ndf 2; node 1 0 0; node 2 2 0; uniaxialMaterial Elastic 1 100.0");
  EXPECT_NE(error("section Uniaxial 1 1 Q").find("unknown resultant \"Q\""), std::string::npos);
  EXPECT_NE(error("section Uniaxial 1 1 T").find("not available in a 2D model"), std::string::npos);
  EXPECT_NE(error("section Uniaxial 1 9 P").find("uniaxialMaterial 9 does not exist"),
            std::string::npos);
  ok("section Uniaxial 1 1 P; section Uniaxial 2 1 Mz");
  EXPECT_NE(error("element truss 1 1 2 2").find("no axial resultant"), std::string::npos);
  EXPECT_NE(error("element truss 1 1 2 7").find("section 7 does not exist"), std::string::npos);
  ok("element truss 1 1 2 1 -rho 2.0 -cMass 1; element corotTruss 2 1 2 1.0 1 -doRayleigh 1");
  EXPECT_EQ(ok("getEleTags"), "1 2");
}

TEST_F(ElementLoadCommandsTest, IntegrationRuleInTheBeamCommand) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 4 0; geomTransf Linear 1;"
     "section Elastic 1 2.0e8 0.01 1.0e-4");
  EXPECT_NE(error("element forceBeamColumn 1 1 2 1 {Simpson 1 5}").find("expected Lobatto"),
            std::string::npos);
  EXPECT_NE(error("element forceBeamColumn 1 1 2 1 Lobatto 1").find("Lobatto needs secTag N"),
            std::string::npos);
  EXPECT_NE(error("element dispBeamColumn 1 1 2 1 {Legendre x 3}").find("expected an integer"),
            std::string::npos);
  EXPECT_NE(error("element dispBeamColumn 1 1 2 1 {Legendre 4 3}").find("section 4 does not exist"),
            std::string::npos);
  EXPECT_NE(error("element forceBeamColumn 1 1 2 3 1 1 -cMass -lMass").find("not both"),
            std::string::npos);
  // A blank integration word (a list of no words) crashed the parser once.
  EXPECT_NE(error("element forceBeamColumn 50 1 2 1 {  } 1").find("got a blank word"),
            std::string::npos);
  EXPECT_NE(error("element dispBeamColumn 50 1 2 1 \"\t\"").find("got a blank word"),
            std::string::npos);
  EXPECT_NE(error("element forceBeamColumn 50 1 2 1 {}").find("integration"), std::string::npos);
  EXPECT_EQ(ok("getEleTags"), "");
  ok("element forceBeamColumn 1 1 2 1 {Lobatto 1 5} -lMass;"
     "element dispBeamColumn 2 1 2 1 Legendre 1 3 -mass 1.0 -cMass;"
     "element forceBeamColumn 3 1 2 1 HingeRadau 1 0.2 1 0.2 1");
  EXPECT_EQ(ok("getEleTags"), "1 2 3");
}

TEST_F(ElementLoadCommandsTest, ImposedMotionOnAFixedDofReplacesTheFixUntilThePatternGoes) {
  ok("model basic -ndm 1 -ndf 1; node 1 0; node 2 0; fix 1 1; timeSeries Linear 1;"
     "pattern MultiSupport 1 { groundMotion 1 Plain -disp 1; imposedSupportMotion 1 1 1 }");
  // The fix is gone while the pattern exists, so fixing again is accepted; it comes back with
  // the pattern's removal (a second fix is then a duplicate).
  ok("remove loadPattern 1");
  EXPECT_NE(error("fix 1 1").find("already fixed"), std::string::npos);
}

TEST_F(ElementLoadCommandsTest, RemoveSpOfADofAnImposedMotionTookOverIsForGood) {
  // OpenSees scripts remove the fix after imposing a motion on it (RCFrameMulti.tcl): accepted,
  // the motion goes on, and the pattern's removal no longer fixes the dof again.
  ok("model basic -ndm 1 -ndf 1; node 1 0; node 2 0; fix 1 1; timeSeries Linear 1;"
     "pattern MultiSupport 1 { groundMotion 1 Plain -disp 1; imposedSupportMotion 1 1 1 }");
  ok("remove sp 1 1");
  EXPECT_NE(error("remove sp 1 1").find("is not fixed"), std::string::npos);
  ok("remove loadPattern 1; fix 1 1");
}

}  // namespace dabs::tcl::testing
