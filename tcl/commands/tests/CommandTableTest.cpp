// SPDX-License-Identifier: MIT
// Error paths of the model, load and analysis commands: every bad input is a Tcl error naming the
// command and argument, and leaves the model unchanged.
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <vector>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl::testing {

namespace {
std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

using CommandTableTest = TclFixture;

TEST_F(CommandTableTest, NonNumberNamesCommandArgumentAndToken) {
  ok("model basic -ndm 2 -ndf 3");
  const std::string msg = error("node 1 0.0 abc");
  EXPECT_NE(msg.find("node 1: argument 3 (y) expected a number, got \"abc\""), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("usage: node tag"), std::string::npos) << msg;
  EXPECT_EQ(ok("getNodeTags"), "");
}

TEST_F(CommandTableTest, ValidationErrorPointsAtTheArgumentItIsAbout) {
  // The material's own validation names the field (n, subIncrement); the command layer finds
  // where that field was read and names its position and token.
  ok("model basic -ndm 3 -ndf 6");
  std::string msg = error("biaxialMaterial Yoshida 1 0.26 0.15 -1.0 4.3 3.5 0.06 0.002");
  EXPECT_NE(msg.find("argument 5: n must be positive, got \"-1.0\""), std::string::npos) << msg;
  msg = error("biaxialMaterial Yoshida 1 0.26 0.15 1.0 4.3 3.5 0.06 0.002 -subIncrement 0");
  EXPECT_NE(msg.find("argument 11: subIncrement must be positive, got \"0\""), std::string::npos)
      << msg;
}

TEST_F(CommandTableTest, WrongCountOfCoordinates) {
  ok("model basic -ndm 3 -ndf 6");
  EXPECT_NE(error("node 1 0.0 1.0").find("too few arguments"), std::string::npos);
  EXPECT_NE(error("node 1 0.0 1.0 2.0 3.0").find("unexpected argument \"3.0\""), std::string::npos);
  EXPECT_EQ(ok("getNodeTags"), "");
}

TEST_F(CommandTableTest, DuplicateTagsAreRejectedAndModelKept) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 1.0; uniaxialMaterial Elastic 1 100.0");
  EXPECT_NE(error("node 1 5.0").find("node 1 already exists"), std::string::npos);
  EXPECT_EQ(number("nodeCoord 1 1"), 0.0);
  EXPECT_NE(error("uniaxialMaterial Elastic 1 200.0").find("uniaxialMaterial 1 already exists"),
            std::string::npos);
  ok("element zeroLength 1 1 2 -mat 1 -dir 1");
  EXPECT_NE(error("element zeroLength 1 1 2 -mat 1 -dir 1").find("element 1 already exists"),
            std::string::npos);
  EXPECT_EQ(ok("getEleTags"), "1");
}

TEST_F(CommandTableTest, UnknownTagsAndTypes) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 1.0; uniaxialMaterial Elastic 1 100.0");
  EXPECT_NE(error("element zeroLength 1 1 3 -mat 1 -dir 1").find("node 3 does not exist"),
            std::string::npos);
  EXPECT_NE(
      error("element zeroLength 1 1 2 -mat 9 -dir 1").find("uniaxialMaterial 9 does not exist"),
      std::string::npos);
  const std::string msg = error("element noSuchElement 1 1 2");
  EXPECT_NE(msg.find("\"noSuchElement\" is not a known element"), std::string::npos) << msg;
  EXPECT_NE(msg.find("zeroLength"), std::string::npos) << msg;
  EXPECT_EQ(ok("getEleTags"), "");
}

TEST_F(CommandTableTest, ElementBetweenNodesOfWrongDofs) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 1 0 -ndf 2; uniaxialMaterial Elastic 1 100.0");
  const std::string msg = error("element truss 1 1 2 1.0 1");
  EXPECT_NE(msg.find("node 2 has 2 dofs but truss needs 3"), std::string::npos) << msg;
  EXPECT_EQ(ok("getEleTags"), "");
}

TEST_F(CommandTableTest, CommandsBeforeModelAndAnalysisBeforeDefinition) {
  EXPECT_NE(error("node 1 0.0").find("needs a model first"), std::string::npos);
  ok("model basic -ndm 1 -ndf 1; node 1 0.0");
  EXPECT_NE(error("analyze 1").find("analysis is not defined"), std::string::npos);
}

TEST_F(CommandTableTest, FixIsAllOrNothing) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; fix 1 0 1 0");
  // dof 2 is fixed already: the whole command fails and dof 1 is not fixed either.
  EXPECT_NE(error("fix 1 1 1 0").find("already fixed"), std::string::npos);
  ok("fix 1 1 0 0");
  EXPECT_NE(error("fix 1 1 0 2").find("expected 0 or 1"), std::string::npos);
}

TEST_F(CommandTableTest, ConstraintListsAreCheckedBeforeAnythingIsFormed) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 1 0; node 3 2 0; fix 3 0 1 0");
  // A dof outside the nodes' dofs is refused before the constraint's matrix (list size squared)
  // is formed; a repeated dof at its second place.
  EXPECT_NE(error("equalDOF 1 2 1 4").find("argument 4 (dof) must be a dof of both nodes, 1 to 3"),
            std::string::npos);
  EXPECT_NE(error("equalDOF 1 2 1 2 1").find("argument 5 (dof) is given twice"), std::string::npos);
  EXPECT_NE(error("rigidDiaphragm 3 1 2 2").find("node 2 is listed twice"), std::string::npos);
  EXPECT_NE(error("rigidDiaphragm 3 1 3").find("dof 2 of node 3 is fixed"), std::string::npos);
  ok("equalDOF 1 2 1 2");
  EXPECT_NE(error("equalDOF 1 2 1").find("already constrained"), std::string::npos);
  EXPECT_NE(error("fix 2 1 0 0").find("already constrained by a multi-point constraint"),
            std::string::npos);
  // remove sp gives the dof back: it can be constrained again.
  ok("remove sp 3 2; equalDOF 1 3 2");
  EXPECT_NE(error("fixX 0.0 1 1 1 -tol -1e-3").find("-tol"), std::string::npos);
  EXPECT_NE(error("fixX 0.0 1 1 1 -tol -1e-3").find("must be a distance, zero or positive"),
            std::string::npos);
}

TEST_F(CommandTableTest, HingeRadauNeedsPositiveHingeLengths) {
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 4 0; geomTransf Linear 1;"
     "section Elastic 1 2.0e8 0.01 1.0e-4");
  EXPECT_NE(error("beamIntegration HingeRadau 1 1 0.0 1 0.2 1").find("lpI"), std::string::npos);
  EXPECT_NE(error("beamIntegration HingeRadau 1 1 0.2 1 0.0 1").find("positive plastic-hinge"),
            std::string::npos);
  EXPECT_NE(error("element forceBeamColumn 1 1 2 1 HingeRadau 1 0.0 1 0.2 1").find("lpI"),
            std::string::npos);
  ok("beamIntegration HingeRadau 1 1 0.2 1 0.2 1");
}

TEST_F(CommandTableTest, PatternBodyErrorRemovesThePattern) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; timeSeries Linear 1");
  const std::string msg = error("pattern Plain 1 1 { load 1 1.0; load 7 1.0 }");
  EXPECT_NE(msg.find("node 7 does not exist"), std::string::npos) << msg;
  ok("pattern Plain 1 1 { load 1 2.0 }");  // the tag is free again
}

TEST_F(CommandTableTest, SingularSystemIsAStatusNotAnError) {
  // A free node with no stiffness: the factorisation fails, analyze returns a negative code and
  // the model stays at its last converged state.
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 1.0; fix 1 1; node 3 2.0");
  ok("uniaxialMaterial Elastic 1 100.0; element zeroLength 1 1 2 -mat 1 -dir 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { load 2 1.0; load 3 1.0 }");
  ok("system BandGeneral; test NormDispIncr 1e-10 10; algorithm Newton; integrator LoadControl "
     "1.0; analysis Static");
  EXPECT_LT(number("analyze 1"), 0.0);
  EXPECT_EQ(number("nodeDisp 2 1"), 0.0);
  EXPECT_EQ(number("getTime"), 0.0);
}

TEST_F(CommandTableTest, StaticSpringGivesHookesLaw) {
  // k u = P for a linear spring: u = 3 / 100.
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 0.0; fix 1 1");
  ok("uniaxialMaterial Elastic 1 100.0; element zeroLength 1 1 2 -mat 1 -dir 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { load 2 3.0 }");
  ok("system BandSPD; test NormUnbalance 1e-12 5; algorithm Newton; integrator LoadControl 1.0; "
     "analysis Static");
  EXPECT_EQ(number("analyze 1"), 0.0);
  EXPECT_NEAR(number("nodeDisp 2 1"), 0.03, 1e-14);
  ok("reactions");
  EXPECT_NEAR(number("nodeReaction 1 1"), -3.0, 1e-12);
}

TEST_F(CommandTableTest, NodeRecorderWritesOpenSeesLayout) {
  const std::string file = ::testing::TempDir() + "dabs-node-recorder.out";
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 0.0; fix 1 1");
  ok("uniaxialMaterial Elastic 1 100.0; element zeroLength 1 1 2 -mat 1 -dir 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { load 2 1.0 }");
  ok("recorder Node -file " + file + " -time -precision 4 -node 2 -dof 1 disp");
  ok("integrator LoadControl 0.5; analysis Static");
  ok("analyze 2");
  // u = lambda / 100 at lambda = 0.5, 1.0; 4 significant digits, one space, newline.
  EXPECT_EQ(readFile(file), "0.5 0.005\n1 0.01\n");
}

TEST_F(CommandTableTest, EnvelopeRecorderWritesMinMaxAbsMax) {
  const std::string file = ::testing::TempDir() + "dabs-envelope.out";
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 0.0; fix 1 1");
  ok("uniaxialMaterial Elastic 1 100.0; element zeroLength 1 1 2 -mat 1 -dir 1");
  ok("timeSeries Path 1 -time {0 1 2 3} -values {0 1 -2 0.5}; pattern Plain 1 1 { load 2 100.0 }");
  ok("recorder EnvelopeNode -file " + file + " -node 2 -dof 1 disp");
  ok("integrator LoadControl 1.0; analysis Static");
  ok("analyze 2");  // u = 1, -2
  ok("remove recorders");
  EXPECT_EQ(readFile(file), "-2\n1\n2\n");
}

TEST_F(CommandTableTest, RecorderKeepsRowsWhenALaterStepFails) {
  const std::string file = ::testing::TempDir() + "dabs-keep.out";
  // An elastic-perfectly-plastic spring cannot carry more than Fy = 1: the third load step fails.
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 0.0; fix 1 1");
  ok("uniaxialMaterial ElasticPP 1 100.0 0.01; element zeroLength 1 1 2 -mat 1 -dir 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { load 2 0.45 }");
  ok("recorder Node -file " + file + " -node 2 -dof 1 disp");
  ok("test NormUnbalance 1e-10 10; algorithm Newton; integrator LoadControl 1.0; analysis Static");
  EXPECT_LT(number("analyze 5"), 0.0);  // the tangent vanishes after yield: singular
  EXPECT_EQ(readFile(file), "0.0045\n0.009\n");
  EXPECT_NEAR(number("getTime"), 2.0, 1e-15);
  EXPECT_NEAR(number("nodeDisp 2 1"), 0.009, 1e-15);
}

TEST_F(CommandTableTest, WipeClearsEverything) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0");
  ok("wipe");
  EXPECT_NE(error("node 2 0.0").find("needs a model first"), std::string::npos);
  ok("model basic -ndm 1 -ndf 1");
  EXPECT_EQ(ok("getNodeTags"), "");
}

}  // namespace dabs::tcl::testing

namespace dabs::tcl::testing {

TEST_F(CommandTableTest, ModelWithoutFreeDofsAnalysesTrivially) {
  // Every dof prescribed: nothing to solve, the step succeeds and the support moves as told.
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 1.0; fix 1 1");
  ok("uniaxialMaterial Elastic 1 100.0; element truss 1 1 2 1.0 1");
  ok("timeSeries Linear 1; pattern Plain 1 1 { sp 2 1 0.01 }");
  ok("integrator LoadControl 1.0; analysis Static");
  EXPECT_EQ(number("analyze 1"), 0.0);
  EXPECT_NEAR(number("nodeDisp 2 1"), 0.01, 1e-15);
  EXPECT_NEAR(number("eleResponse 1 axialForce"), 100.0 * 0.01, 1e-12);  // EA/L * u
}

TEST_F(CommandTableTest, PathSeriesWithTimesGivesLastValueAtLastTime) {
  // OpenSees PathTimeSeries interpolates up to and including the last time, and is zero after.
  ok("model basic -ndm 1 -ndf 1; timeSeries Path 1 -time {0 1 2} -values {0 1 3}");
  ok("node 1 0.0; node 2 0.0; fix 1 1; uniaxialMaterial Elastic 1 1.0; element zeroLength 1 1 2 "
     "-mat 1 -dir 1");
  ok("pattern Plain 1 1 { load 2 1.0 }; integrator LoadControl 1.0; analysis Static");
  ok("analyze 2");
  EXPECT_NEAR(number("nodeDisp 2 1"), 3.0, 1e-12);
  ok("analyze 1");
  EXPECT_NEAR(number("nodeDisp 2 1"), 0.0, 1e-12);
}

TEST_F(CommandTableTest, DampingForcesResponseIsTheElementRayleighForce) {
  // Axial bar (2D elastic beam, lumped mass m L / 2 per node) pushed along its axis: only the
  // axial velocity of node 2 is non-zero, so the Rayleigh force of the element is
  // (alphaM m L / 2 + betaK0 E A / L) v at node 2, dof 1, and -betaK0 E A / L v at node 1, dof 1.
  const double E = 200.0, A = 3.0, L = 2.0, m = 0.5, alphaM = 0.3, betaK0 = 0.01;
  ok("model basic -ndm 2 -ndf 3; node 1 0 0; node 2 2.0 0; fix 1 1 1 1; fix 2 0 1 1");
  ok("geomTransf Linear 1; element elasticBeamColumn 1 1 2 3.0 200.0 1.0 1 -mass 0.5");
  ok("uniaxialMaterial Elastic 9 50.0; element zeroLength 2 1 2 -mat 9 -dir 1");
  ok("rayleigh 0.3 0.0 0.01 0.0");
  ok("timeSeries Constant 1; pattern Plain 1 1 { load 2 10.0 0 0 }");
  ok("system FullGeneral; test NormDispIncr 1e-12 10; algorithm Newton; integrator Newmark 0.5 "
     "0.25");
  ok("analysis Transient");
  EXPECT_EQ(number("analyze 3 0.01"), 0.0);
  const double v = number("nodeVel 2 1");
  ASSERT_GT(std::abs(v), 1e-6);
  std::istringstream f(ok("eleResponse 1 dampingForces"));
  std::vector<double> values{std::istream_iterator<double>(f), std::istream_iterator<double>()};
  ASSERT_EQ(values.size(), 6u);
  EXPECT_NEAR(values[3], (alphaM * m * L / 2.0 + betaK0 * E * A / L) * v, 1e-12);
  EXPECT_NEAR(values[0], -betaK0 * E * A / L * v, 1e-12);
  for (int i : {1, 2, 4, 5}) EXPECT_NEAR(values[i], 0.0, 1e-12);
  EXPECT_EQ(ok("eleResponse 1 rayleighForces"), ok("eleResponse 1 dampingForces"));
  // A zeroLength declines Rayleigh damping (OpenSees' default): its damping force is zero.
  EXPECT_EQ(ok("eleResponse 2 dampingForces"), "0.0 0.0 0.0 0.0 0.0 0.0");
  EXPECT_NE(error("eleResponse 7 dampingForces").find("element 7 does not exist"),
            std::string::npos);
}

TEST_F(CommandTableTest, GetLoadFactorGivesSeriesTimesFactor) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0; node 2 0.0 -mass 1.0; fix 1 1");
  ok("timeSeries Path 1 -dt 0.1 -values {0 1 2} -factor 9.81; timeSeries Linear 2");
  ok("pattern UniformExcitation 1 1 -accel 1 -fact 2.0; pattern Plain 2 2 { load 2 1.0 }");
  ok("setTime 0.15");
  EXPECT_NEAR(number("getLoadFactor 1"), 2.0 * 9.81 * 1.5, 1e-12);  // linear interpolation
  EXPECT_NEAR(number("getLoadFactor 2"), 0.15, 1e-15);
  EXPECT_NE(error("getLoadFactor 3").find("load pattern 3 does not exist"), std::string::npos);
  EXPECT_NE(error("getLoadFactor").find("patternTag"), std::string::npos);
}

TEST_F(CommandTableTest, YoshidaBearingTakesOneOrTwoRockingStiffnesses) {
  // Coincident nodes: local y = global X, local z = global Y, so a moment M about X turns node 2
  // by M / Kry and about Y by M / Krz.
  ok("model basic -ndm 3 -ndf 6; node 1 0 0 0; node 2 0 0 0; fix 1 1 1 1 1 1 1");
  ok("biaxialMaterial Yoshida 1 300.0 0.02 2.0 0.0 0.0 1.0 0.0");
  EXPECT_NE(error("element yoshidaBearing 1 1 2 1 -Tr 0.2 -Kv 1e6 -Kt 50.0 -Kr 1 2 3")
                .find("-Kr takes one value"),
            std::string::npos);
  EXPECT_NE(error("element yoshidaBearing 1 1 2 1 -Tr 0.2 -Kv 1e6 -Kt 50.0 -Kr -1").find("Kr"),
            std::string::npos);
  EXPECT_NE(error("biaxialMaterial Yoshida 2 300.0 0.02 2.0 0.0 0.0 1.0 0.0 -subIncrement 0")
                .find("subIncrement"),
            std::string::npos);
  ok("biaxialMaterial Yoshida 3 300.0 0.02 2.0 0.0 0.0 1.0 0.0 -subIncrement 0.005");
  ok("element yoshidaBearing 1 1 2 1 -Tr 0.2 -Kv 1e6 -Kt 50.0 -Kr 100.0 400.0");
  ok("timeSeries Linear 1; pattern Plain 1 1 { load 2 0 0 0 2.0 3.0 0 }");
  ok("system FullGeneral; test NormDispIncr 1e-12 10; algorithm Newton; integrator LoadControl "
     "1.0; analysis Static");
  EXPECT_EQ(number("analyze 1"), 0.0);
  EXPECT_NEAR(number("nodeDisp 2 4"), 2.0 / 100.0, 1e-12);
  EXPECT_NEAR(number("nodeDisp 2 5"), 3.0 / 400.0, 1e-12);
}

TEST_F(CommandTableTest, EntriesAreTheRegisteredCommands) {
  // Every row commandEntries gives (what the Python module exposes) is a command of the
  // interpreter, each once, with its usage line.
  const std::vector<const CommandEntry*> entries = commandEntries();
  ASSERT_GT(entries.size(), 50u);
  std::set<std::string_view> names;
  for (const CommandEntry* e : entries) {
    EXPECT_TRUE(names.insert(e->name).second) << e->name;
    EXPECT_FALSE(e->usage.empty()) << e->name;
    EXPECT_EQ(ok("info commands " + std::string(e->name)), std::string(e->name));
  }
  EXPECT_TRUE(names.count("nodeDisp") == 1 && names.count("section") == 1 &&
              names.count("pounding") == 1);
  // The program's commands (the parallel ones) are not the library's: it passes them in.
  EXPECT_EQ(names.count("ensemble"), 0u);
}

}  // namespace dabs::tcl::testing
