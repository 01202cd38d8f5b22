// SPDX-License-Identifier: MIT
// Bad input to the pounding commands (uniaxialMaterial Restrainer|Bumper, element nodeToSurface,
// pounding, contactStepping): each error names the argument by its position on the command line
// (the command word is argument 0) and leaves the model unchanged.

#include <gtest/gtest.h>

#include <string>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl {
namespace {

class ContactParsersTest : public testing::TclFixture {
 protected:
  /// Two unit faces 0.01 apart, normal X: nodes 11-14 at x = 0, 21-24 at x = 0.01 (ndf 3), and
  /// node 30 of a 6-dof kind.
  void twoFaces() {
    ok("model basic -ndm 3 -ndf 3");
    ok("node 11 0 -1 -1; node 12 0 1 -1; node 13 0 1 1; node 14 0 -1 1");
    ok("node 21 0.01 -1 -1; node 22 0.01 1 -1; node 23 0.01 1 1; node 24 0.01 -1 1");
    ok("node 30 0.01 0 0 -ndf 6");
  }
  int elementCount() { return std::stoi(ok("llength [getEleTags]")); }
};

/// True when `message` contains `part`; prints the message otherwise.
::testing::AssertionResult has(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << part << "\" not in: " << message;
}

TEST_F(ContactParsersTest, GapSpringErrorsPointAtTheArgument) {
  ok("model basic -ndm 1 -ndf 1");
  std::string m = error("uniaxialMaterial Restrainer 7 -1.0 0.05");
  EXPECT_TRUE(has(m, "uniaxialMaterial Restrainer 7: argument 3: k must be positive"));
  m = error("uniaxialMaterial Bumper 7 1e4 -0.01");
  EXPECT_TRUE(has(m, "argument 4: gap must be zero or positive"));
  m = error("uniaxialMaterial Restrainer 7 1e4 0.05 -Fy -5");
  EXPECT_TRUE(has(m, "argument 6: Fy must be positive, got \"-5\""));
  m = error("uniaxialMaterial Restrainer 7 1e4 0.05 -Fy 100 -b 1.5");
  EXPECT_TRUE(has(m, "argument 8: b must be in [0, 1), got \"1.5\""));
  m = error("uniaxialMaterial Bumper 7 1e4 0.05 -b 0.1");
  EXPECT_TRUE(has(m, "argument 6 (-b) needs -Fy"));
  m = error("uniaxialMaterial Bumper 7 1e4 abc");
  EXPECT_TRUE(has(m, "argument 4 (gap) expected a number, got \"abc\""));
  EXPECT_EQ(ok("uniaxialMaterial Bumper 7 1e4 0.05"), "");  // the tag is still free
}

TEST_F(ContactParsersTest, NodeToSurfaceErrorsPointAtTheNodeOrOption) {
  twoFaces();
  // element nodeToSurface tag cNode a b c d: cNode is argument 3, a..d are 4..7.
  std::string m = error("element nodeToSurface 1 21 11 12 99 14 -K 1e6");
  EXPECT_TRUE(has(m, "argument 6: c node 99 does not exist"));
  m = error("element nodeToSurface 1 98 11 12 13 14 -K 1e6");
  EXPECT_TRUE(has(m, "argument 3: cNode node 98 does not exist"));
  m = error("element nodeToSurface 1 21 11 12 12 14 -K 1e6");
  EXPECT_TRUE(has(m, "argument 6: c node 12 appears twice"));
  m = error("element nodeToSurface 1 21 11 21 13 14 -K 1e6");
  EXPECT_TRUE(has(m, "argument 5: b node 21 is also the contactor node"));
  m = error("element nodeToSurface 1 30 11 12 13 14 -K 1e6");
  EXPECT_TRUE(has(m, "argument 4: a node 11 has 3 dofs but the contactor 30 has 6"));
  // Options: -K value is argument 9, -e value 11, -masses values 13 and 14 (after -e), -EAL values
  // 9-11.
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 1e6 -e 1.5");
  EXPECT_TRUE(has(m, "argument 11: e must be in [0, 1], got \"1.5\""));
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 0");
  EXPECT_TRUE(has(m, "argument 9: K must be positive and finite, got \"0\""));
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 1e6 -e 0.5 -masses 2.0 0.0");
  EXPECT_TRUE(has(m, "argument 14 (-masses) M2 must be positive when e < 1"));
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 1e6 -e 0.5");
  EXPECT_TRUE(has(m, "M1 must be positive when e < 1 (-masses M1 M2)"));
  m = error("element nodeToSurface 1 21 11 12 13 14 -EAL 2e8 0.5 0.0");
  EXPECT_TRUE(has(m, "argument 11 (-EAL) the length L must be positive, got \"0.0\""));
  m = error("element nodeToSurface 1 21 11 12 13 14 -EAL -2e8 0.5 40");
  EXPECT_TRUE(has(m, "argument 9 (-EAL) gives K = E A / L, which must be positive"));
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 1e6 -mu_s 0.2 -mu_k 0.3");
  EXPECT_TRUE(has(m, "argument 13: mu_k must not exceed mu_s, got \"0.3\""));
  m = error("element nodeToSurface 1 21 11 12 13 14 -K 1e6 -search 0");
  EXPECT_TRUE(has(m, "argument 11: search must be positive"));
  EXPECT_EQ(elementCount(), 0);
  ok("element nodeToSurface 1 21 11 12 13 14 -K 1e6");
  EXPECT_EQ(elementCount(), 1);
}

TEST_F(ContactParsersTest, PoundingErrorsPointAtTheListAndLeaveNothingBehind) {
  twoFaces();
  const std::string sides = " -side1 {11 12} {11 12 13 14} -side2 {21} {21 24 23 22} -K 1e6";
  ok("element nodeToSurface 102 21 11 12 13 14 -K 1e6");
  // pounding tag -side1 {nodes} {face} -side2 {nodes} {face}: tag 1, lists 3, 4, 6, 7.
  std::string m = error("pounding 100" + sides);
  EXPECT_TRUE(has(m, "argument 1 (tag) numbers the 3 elements 100 to 102, but element 102"));
  m = error("pounding 200 -side1 {11 x} {11 12 13 14} -side2 {21} {21 24 23 22} -K 1e6");
  EXPECT_TRUE(has(m, "argument 3 (-side1) must list node tags, got \"11 x\""));
  m = error("pounding 200 -side1 {11} {11 12 13} -side2 {21} {21 24 23 22} -K 1e6");
  EXPECT_TRUE(has(m, "argument 4 (face1) must list exactly 4 nodes"));
  m = error("pounding 200 -side1 {11} {11 12 13 14} -side2 {} {21 24 23 22} -K 1e6");
  EXPECT_TRUE(has(m, "argument 6 (-side2) must list at least one node"));
  m = error("pounding 200 -side1 {11} {11 12 13 14} -side2 {21} {21 24 23 99} -K 1e6");
  EXPECT_TRUE(has(m, "argument 7: face2"));
  EXPECT_TRUE(has(m, "node 99 does not exist"));
  m = error("pounding 200 -side1 {11 12} {11 12 13 14} -side2 {97} {21 24 23 22} -K 1e6");
  EXPECT_TRUE(has(m, "argument 6: -side2"));
  EXPECT_TRUE(has(m, "node 97 does not exist"));
  m = error("pounding 200" + sides + " -e 2");
  EXPECT_TRUE(has(m, "argument 11: e must be in [0, 1]"));
  m = error("pounding 200 -side1 {11} {11 12 13 14} -K 1e6");
  EXPECT_TRUE(has(m, "both -side1 and -side2 are required"));
  EXPECT_EQ(elementCount(), 1);
}

TEST_F(ContactParsersTest, ContactSteppingErrorsPointAtTheOption) {
  ok("model basic -ndm 3 -ndf 3");
  std::string m = error("contactStepping -maxStep -0.1");
  EXPECT_TRUE(has(m, "argument 2: maxStep must be a positive step length, got \"-0.1\""));
  m = error("contactStepping -maxStep 0.01 -overshoot 0.5");
  EXPECT_TRUE(has(m, "argument 4: overshoot must be >= 1"));
  m = error("contactStepping -lookAhead -1");
  EXPECT_TRUE(has(m, "argument 2: lookAhead must be >= 0"));
  EXPECT_TRUE(has(ok("contactStepping"), "on 0"));
}

TEST_F(ContactParsersTest, ImpactLawErrorsPointAtTheArgument) {
  twoFaces();
  const std::string cmd = "element nodeToSurface 1 21 11 12 13 14 -K 1e9";
  // -law value is argument 11, the next option's value 13, the one after 15.
  std::string m = error(cmd + " -law hunt");
  EXPECT_TRUE(
      has(m, "argument 11 (-law) expected kelvin, hertz, hertzdamp or jankowski, got \"hunt\""));
  EXPECT_TRUE(has(m, "usage: element nodeToSurface"));
  m = error(cmd + " -law hertz -n -1.5");
  EXPECT_TRUE(has(m, "argument 13: n must be positive and finite, got \"-1.5\""));
  m = error(cmd + " -law hertz -e 0.6");
  EXPECT_TRUE(has(
      m,
      "argument 13: e must be 1: the hertz law has no damping (use -law hertzdamp), got \"0.6\""));
  m = error(cmd + " -law hertzdamp -e 0.6");
  EXPECT_TRUE(has(m, "-law hertzdamp needs -v0 v0"));
  m = error(cmd + " -law hertzdamp -v0 0 -e 0.6");
  EXPECT_TRUE(has(m, "argument 13: v0 must be positive and finite"));
  m = error(cmd + " -law hertzdamp -v0 1 -e 0");
  EXPECT_TRUE(has(m, "argument 15: e must be in (0, 1] for hertzdamp;"));
  m = error(cmd + " -law jankowski -e 0.6");
  EXPECT_TRUE(has(m, "M1 must be positive for the jankowski law (-masses M1 M2)"));
  m = error(cmd + " -law jankowski -e 1.2 -masses 1 2");
  EXPECT_TRUE(has(m, "argument 13: e must be in (0, 1] for jankowski, got \"1.2\""));
  m = error(cmd + " -law kelvin -n 1.5");
  EXPECT_TRUE(has(m, "argument 13 (-n) is the exponent of -law hertz or hertzdamp only"));
  m = error(cmd + " -law jankowski -v0 1 -masses 1 2");
  EXPECT_TRUE(has(m, "argument 13 (-v0) is the approach speed of -law hertzdamp only"));
  m = error("element nodeToSurface 1 21 11 12 13 14 -EAL 2e8 0.5 40 -law hertz");
  EXPECT_TRUE(has(m, "(-EAL) gives a linear stiffness; -law hertz needs -K in force/length^n"));
  m = error(cmd + " -law hertz -Kt -1");
  EXPECT_TRUE(has(m, "argument 13: Kt must be positive and finite"));
  EXPECT_EQ(elementCount(), 0);
  ok(cmd + " -law hertz -n 1.5 -Kt 1e6 -mu_s 0.3");
  ok("element nodeToSurface 2 21 11 12 13 14 -K 1e9 -law hertzdamp -v0 0.5 -e 0.7");
  ok("element nodeToSurface 3 21 11 12 13 14 -K 1e9 -law jankowski -e 0.65 -masses 1e3 2e3");
  ok("element nodeToSurface 4 21 11 12 13 14 -K 1e6 -law kelvin -e 0.65 -masses 1e3 2e3");
  EXPECT_EQ(elementCount(), 4);
  // pounding shares the options.
  const std::string sides = " -side1 {11} {11 12 13 14} -side2 {21} {21 24 23 22}";
  m = error("pounding 100" + sides + " -K 1e9 -law jankowski -e 0.6");
  EXPECT_TRUE(has(m, "M1 must be positive for the jankowski law"));
  EXPECT_EQ(elementCount(), 4);
  EXPECT_EQ(ok("pounding 100 -K 1e9 -law hertzdamp -v0 0.5 -e 0.7" + sides), "100 101");
}

}  // namespace
}  // namespace dabs::tcl
