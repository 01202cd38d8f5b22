// SPDX-License-Identifier: MIT
// validate() of the parameters of integrators, convergence tests and algorithms: each field's
// bad value throws InputError naming that field, the defaults and the Tcl commands' usual values
// pass, and the constructors refuse what validate() refuses, so a C++ caller cannot build an
// unstable or meaningless component. The bounds are those stated in the Params comments (Chung
// and Hulbert 1993, eq. 25, for the generalized-alpha family).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "materials/InputError.h"
#include "tcl/analysis/integrators/ArcLength.h"
#include "tcl/analysis/algorithms/ConvergenceTest.h"
#include "tcl/analysis/integrators/DisplacementControl.h"
#include "tcl/analysis/integrators/GeneralizedAlpha.h"
#include "tcl/analysis/algorithms/KrylovNewton.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonLineSearch.h"

namespace dabs::analysis {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The field of the InputError validate() throws ("" when it throws none).
template <class P>
std::string failingField(const P& p) {
  try {
    p.validate();
  } catch (const InputError& e) {
    return e.field().empty() ? std::string("<none>") : e.field();
  }
  return "";
}

GeneralizedAlpha::Params alpha(double alphaM, double alphaF, double gamma, double beta) {
  return GeneralizedAlpha::Params{alphaM, alphaF, gamma, beta};
}

TEST(StrategyParamsTest, GeneralizedAlphaAcceptsNewmarkHhtAndStableGeneralizedAlpha) {
  EXPECT_EQ(failingField(GeneralizedAlpha::Params{}), "");
  EXPECT_EQ(failingField(alpha(1.0, 1.0, 0.5, 0.25)), "");       // average acceleration
  EXPECT_EQ(failingField(alpha(1.0, 1.0, 0.5, 1.0 / 6.0)), "");  // linear acceleration
  EXPECT_EQ(failingField(alpha(1.0, 0.7, 0.8, 0.4225)), "");     // HHT 0.7, its defaults
  // Generalized alpha with rho_inf = 0.5: alphaM = (2 - rho)/(1 + rho), alphaF = 1/(1 + rho).
  const double aM = 1.5 / 1.5, aF = 1.0 / 1.5;
  EXPECT_EQ(failingField(alpha(aM, aF, 0.5 + aM - aF, 0.25 * (1 + aM - aF) * (1 + aM - aF))), "");
}

TEST(StrategyParamsTest, GeneralizedAlphaRefusesUnstableParameters) {
  EXPECT_EQ(failingField(alpha(1.0, 1.0, 0.0, 0.25)), "gamma");
  EXPECT_EQ(failingField(alpha(1.0, 1.0, 0.5, 0.0)), "beta");
  EXPECT_EQ(failingField(alpha(1.0, 1.0, 0.4, 0.25)), "gamma");    // Newmark below 1/2 grows
  EXPECT_EQ(failingField(alpha(1.0, 0.4, 1.1, 0.6)), "alphaF");    // alphaF < 1/2
  EXPECT_EQ(failingField(alpha(0.8, 0.9, 0.5, 0.25)), "alphaF");   // alphaM < alphaF
  EXPECT_EQ(failingField(alpha(1.0, 0.7, 0.7, 0.4225)), "gamma");  // < 1/2 + 0.3
  EXPECT_EQ(failingField(alpha(1.0, 0.7, 0.8, 0.3)), "beta");      // < 1/4 + 0.15
  EXPECT_EQ(failingField(alpha(kNaN, 1.0, 0.5, 0.25)), "alphaM");
  EXPECT_EQ(failingField(alpha(1.0, 1.0, kInf, 0.25)), "gamma");
  EXPECT_THROW(GeneralizedAlpha(1.0, 0.7, 0.7, 0.4225), InputError);
  EXPECT_NO_THROW(GeneralizedAlpha(1.0, 1.0, 0.5, 0.25));
}

TEST(StrategyParamsTest, ConvergenceTestRefusesNonPositiveToleranceAndIterations) {
  using K = ConvergenceTest::Kind;
  EXPECT_EQ(failingField(ConvergenceTest::Params{}), "");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::NormDispIncr, 1e-8, 10, 0, 0}), "");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::NormDispIncr, -1e-8, 10}), "tol");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::NormDispIncr, 0.0, 10}), "tol");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::NormDispIncr, kNaN, 10}), "tol");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::EnergyIncr, 1e-8, 0}), "maxIter");
  EXPECT_EQ(failingField(ConvergenceTest::Params{K::NormUnbalance, 1e-8, 10, 0, -1}), "nType");
  EXPECT_THROW(ConvergenceTest(K::NormDispIncr, -1e-8, 10), InputError);
}

TEST(StrategyParamsTest, LoadAndDisplacementControlRefuseBadIncrementsAndJd) {
  EXPECT_EQ(failingField(LoadControl::Params{}), "");
  EXPECT_EQ(failingField(LoadControl::Params{0.1, 0, 0.1, 0.1}), "Jd");
  EXPECT_EQ(failingField(LoadControl::Params{kInf, 1, 0.1, 0.1}), "dLambda");
  EXPECT_EQ(failingField(LoadControl::Params{0.1, 3, kNaN, 0.1}), "minLambda");
  EXPECT_EQ(failingField(LoadControl::Params{0.1, 3, 0.01, kNaN}), "maxLambda");
  EXPECT_THROW(LoadControl(0.1, 0, 0.1, 0.1), InputError);

  using DC = DisplacementControl::Params;
  EXPECT_EQ(failingField(DC{3, 0, 0.01, 1, 0.01, 0.01, false}), "");
  EXPECT_EQ(failingField(DC{3, -1, 0.01, 1, 0.01, 0.01, false}), "dof");
  EXPECT_EQ(failingField(DC{3, 0, kNaN, 1, 0.01, 0.01, false}), "incr");
  EXPECT_EQ(failingField(DC{3, 0, 0.01, 0, 0.01, 0.01, false}), "Jd");
  EXPECT_EQ(failingField(DC{3, 0, 0.01, 2, kInf, 0.01, false}), "dUmin");
  EXPECT_EQ(failingField(DC{3, 0, 0.01, 2, 0.001, kInf, false}), "dUmax");
  EXPECT_THROW(DisplacementControl(3, 0, 0.01, 0, 0.01, 0.01, false), InputError);
}

TEST(StrategyParamsTest, ArcLengthRefusesNonPositiveLengthAndWeights) {
  EXPECT_EQ(failingField(ArcLength::Params{}), "");
  EXPECT_EQ(failingField(ArcLength::Params{0.1, 1.0, 0.0, false}), "");  // alpha 0
  EXPECT_EQ(failingField(ArcLength::Params{0.0, 1.0, 1.0, false}), "arcLength");
  EXPECT_EQ(failingField(ArcLength::Params{-0.1, 1.0, 1.0, false}), "arcLength");
  EXPECT_EQ(failingField(ArcLength::Params{0.1, kInf, 1.0, true}), "wU");  // uRef = 0
  EXPECT_EQ(failingField(ArcLength::Params{0.1, 1.0, -1.0, true}), "wF");
  EXPECT_EQ(failingField(ArcLength::Params{0.1, 0.0, 0.0, true}), "<none>");
  EXPECT_THROW(ArcLength(0.0, 1.0, 1.0, false), InputError);
}

TEST(StrategyParamsTest, AlgorithmsRefuseMeaninglessSearchAndKrylovSettings) {
  using S = NewtonLineSearch::Search;
  EXPECT_EQ(failingField(NewtonLineSearch::Params{}), "");
  EXPECT_EQ(failingField(NewtonLineSearch::Params{S::Bisection, 0.0, 10, 0.1, 10.0}), "-tol");
  EXPECT_EQ(failingField(NewtonLineSearch::Params{S::Secant, 0.8, 0, 0.1, 10.0}), "-maxIter");
  EXPECT_EQ(failingField(NewtonLineSearch::Params{S::Secant, 0.8, 10, 0.0, 10.0}), "-minEta");
  EXPECT_EQ(failingField(NewtonLineSearch::Params{S::Secant, 0.8, 10, 1.5, 10.0}), "-minEta");
  EXPECT_EQ(failingField(NewtonLineSearch::Params{S::Secant, 0.8, 10, 0.1, 0.5}), "-maxEta");
  EXPECT_THROW(NewtonLineSearch(S::RegulaFalsi, -1.0, 10, 0.1, 10.0), InputError);

  EXPECT_EQ(failingField(KrylovNewton::Params{}), "");
  EXPECT_EQ(failingField(KrylovNewton::Params{false, 0}), "-maxDim");
  EXPECT_THROW(KrylovNewton(true, 0), InputError);
}

}  // namespace
}  // namespace dabs::analysis
