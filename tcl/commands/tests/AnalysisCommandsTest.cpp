// SPDX-License-Identifier: MIT
// The analysis commands through the interpreter: their type tables, the argument each validation
// error points at, and the OpenSees options that are refused or reported rather than ignored.

#include <string>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl {
namespace {

class AnalysisCommandsTest : public testing::TclFixture {
 protected:
  /// Passes when `text` contains `part`; prints the text otherwise.
  static ::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure()
           << "\"" << text << "\" does not contain \"" << part << "\"";
  }
};

TEST_F(AnalysisCommandsTest, UnknownTypesListTheKnownOnesAtTheTypeWord) {
  std::string msg = error("algorithm Broyden");
  EXPECT_TRUE(
      Contains(msg,
               "algorithm: argument 1 (type) expected one of Linear, Newton, ModifiedNewton, "
               "NewtonLineSearch, KrylovNewton, got \"Broyden\""));
  msg = error("integrator Explicit");
  EXPECT_TRUE(Contains(msg, "argument 1 (type) expected one of LoadControl,"));
  EXPECT_TRUE(Contains(msg, "CentralDifference, got \"Explicit\""));
  EXPECT_TRUE(
      Contains(error("test NormDispAndUnbalance 1e-8 10"),
               "argument 1 (type) expected one of NormDispIncr, NormUnbalance, EnergyIncr"));
  EXPECT_TRUE(
      Contains(error("constraints Lagrange"), "expected one of Plain, Transformation, Penalty"));
  EXPECT_TRUE(
      Contains(error("numberer Random"), "expected one of Plain, RCM, AMD, got \"Random\""));
  EXPECT_TRUE(
      Contains(error("analysis PFEM"), "expected one of Static, Transient, VariableTransient"));
  ok("model basic -ndm 1 -ndf 1");
  EXPECT_TRUE(
      Contains(error("recorder Remove 1"), "recorder: argument 1 (type) expected one of Node,"));
}

TEST_F(AnalysisCommandsTest, ValidationErrorsPointAtTheArgumentRead) {
  EXPECT_TRUE(Contains(error("test NormDispIncr -1e-8 10"),
                       "argument 2 (tol) must be positive, got \"-1e-8\""));
  EXPECT_TRUE(Contains(error("test NormDispIncr 1e-8 0"),
                       "argument 3 (maxIter) must be at least 1, got \"0\""));
  EXPECT_TRUE(Contains(error("test EnergyIncr 1e-8 5 0 -1"), "argument 5 (nType) must be 0"));
  EXPECT_TRUE(Contains(error("integrator LoadControl 0.1 0 0.1 0.1"),
                       "argument 3 (Jd) must be at least 1, got \"0\""));
  EXPECT_TRUE(Contains(error("integrator HHT 0.45"),
                       "integrator HHT: argument 2 (alpha) must be in [2/3, 1]"));
  EXPECT_TRUE(Contains(error("integrator Newmark 0.5 -0.25"),
                       "argument 3 (beta) must be positive, got \"-0.25\""));
  EXPECT_TRUE(
      Contains(error("integrator Newmark 0.5 0.25 -form X"), "argument 5 (-form) must be D or A"));
  EXPECT_TRUE(
      Contains(error("integrator HSConstraint 0.1 1 1 0"), "argument 5 (uRef) must not be zero"));
  EXPECT_TRUE(
      Contains(error("integrator ArcLength -1 0.5"), "argument 2 (arcLength) must be positive"));
  EXPECT_TRUE(Contains(error("constraints Penalty 1e12 0"),
                       "argument 3 (alphaMP) must be positive, got \"0\""));
  EXPECT_TRUE(Contains(error("algorithm NewtonLineSearch -maxIter 0"),
                       "argument 3 (-maxIter) must be at least 1"));
  EXPECT_TRUE(Contains(error("algorithm NewtonLineSearch -type Golden"),
                       "argument 3 (-type) expected one of InitialInterpolated, Bisection"));
  EXPECT_TRUE(
      Contains(error("algorithm NewtonLineSearch 0"), "argument 2 (ratio) must be positive"));
  EXPECT_TRUE(Contains(error("algorithm KrylovNewton -maxDim 0"),
                       "argument 3 (-maxDim) must be at least 1"));
  EXPECT_TRUE(Contains(error("analysis Static -numSubSteps 1"),
                       "argument 3 (-numSubSteps) must be at least 2"));
  EXPECT_TRUE(Contains(error("analyze -2"), "argument 1 (numIncr) must not be negative"));
  EXPECT_TRUE(Contains(error("threads 0"), "argument 1 (n) must be 1 to 256 or auto, got \"0\""));
  // The usage line is the chosen type's own.
  EXPECT_TRUE(Contains(error("integrator LoadControl x"),
                       "usage: integrator LoadControl dLambda ?Jd minLambda maxLambda?"));
  // A system type's error comes from the solver table's validation, at the type word.
  EXPECT_TRUE(Contains(error("system Pardiso"),
                       "system: argument 1: type \"Pardiso\" is not a known system"));
}

TEST_F(AnalysisCommandsTest, SecantAndLineSearchOutputAreRefusedNotIgnored) {
  for (const char* type : {"Linear", "Newton", "ModifiedNewton", "KrylovNewton"}) {
    const std::string msg = error(std::string("algorithm ") + type + " -secant");
    EXPECT_TRUE(Contains(msg, "-secant is not supported")) << type;
  }
  EXPECT_TRUE(
      Contains(error("algorithm NewtonLineSearch -pFlag 0"),
               "argument 3 (-pFlag) 0 (print each line-search iteration) is not supported"));
  ok("algorithm NewtonLineSearch -pFlag 1 -tol 0.5");  // OpenSees' default, quiet
  ok("algorithm Linear -initial -factorOnce");
  ok("algorithm Newton -initialThenCurrent");
}

TEST_F(AnalysisCommandsTest, ReactionsWithRayleighAloneAreRefused) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0");
  EXPECT_TRUE(Contains(error("reactions -rayleigh"),
                       "-rayleigh (damping forces without inertia) is not supported"));
  ok("reactions -dynamic");
}

TEST_F(AnalysisCommandsTest, PrintOptionsWithoutOutputAreRefused) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0");
  EXPECT_TRUE(Contains(error("print node flag 2"), "argument 3 (flag) is not supported"));
  EXPECT_TRUE(Contains(error("print -integrator"), "argument 1 (what) is not supported"));
  EXPECT_TRUE(Contains(error("print algorithm"), "is not supported: dabs does not describe"));
  const std::string file = ::testing::TempDir() + "dabs_print_flag0.txt";
  ok("print " + file + " node flag 0 1");
}

TEST_F(AnalysisCommandsTest, HugeInlineSeriesTagIsReportedAsATag) {
  ok("model basic -ndm 1 -ndf 1; node 1 0.0");
  const std::string msg = error("pattern Plain 1 99999999999 {}");
  EXPECT_TRUE(Contains(msg,
                       "expected an integer from -2147483648 to 2147483647 (a time series tag), "
                       "got \"99999999999\""));
  EXPECT_TRUE(Contains(error("pattern Plain 2 {} {}"), "expected a time series tag or spec"));
}

}  // namespace
}  // namespace dabs::tcl
