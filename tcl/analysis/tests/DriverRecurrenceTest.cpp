// SPDX-License-Identifier: MIT
// Generalized-alpha (with HHT and Newmark as its cases), displacement control, the line search,
// Krylov-Newton and the builder's wipe, on one-dof springs, each against a closed form or the
// scheme's recurrence worked out here independently of the driver's code.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "materials/Elastic.h"
#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/integrators/DisplacementControl.h"
#include "tcl/analysis/integrators/GeneralizedAlpha.h"
#include "tcl/analysis/algorithms/KrylovNewton.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonLineSearch.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

using testing::CubicSpring;
using testing::dispTest;

std::unique_ptr<materials::Elastic> elastic(double k, double eta) {
  materials::Elastic::Params p;
  p.E = k;
  p.eta = eta;
  return std::make_unique<materials::Elastic>(1, p);
}

// Generalized-alpha in OpenSees' convention (x_{n+a} = (1 - a) x_n + a x_{n+1}; 1 and 1 is
// Newmark), Chung & Hulbert (1993) eqs. 2-4: Newmark's update of u and v from a_{n+1}, and
// m a_{n+alphaM} + c v_{n+alphaF} + k u_{n+alphaF} = P(t_{n+alphaF}), here P = P0 t.
struct State {
  double u = 0.0, v = 0.0, a = 0.0;
};
State alphaStep(const State& s, double t, double dt, double m, double c, double k, double P0,
                double alphaM, double alphaF, double gamma, double beta) {
  const double uPred = s.u + dt * s.v + dt * dt * (0.5 - beta) * s.a;
  const double vPred = s.v + dt * (1.0 - gamma) * s.a;
  const double load = P0 * (t + alphaF * dt);
  const double rhs = load - m * (1.0 - alphaM) * s.a - c * ((1.0 - alphaF) * s.v + alphaF * vPred) -
                     k * ((1.0 - alphaF) * s.u + alphaF * uPred);
  const double a1 = rhs / (m * alphaM + c * alphaF * gamma * dt + k * alphaF * beta * dt * dt);
  return {uPred + beta * dt * dt * a1, vPred + gamma * dt * a1, a1};
}

void checkAlpha(double alphaM, double alphaF, double gamma, double beta) {
  constexpr double kM = 2.0, kK = 800.0, kC = 3.0, kP0 = 50.0, kDt = 0.02;
  domain::Domain domain;
  testing::buildSpring(domain, elastic(kK, kC), kM, kP0);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 20));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  builder.setIntegrator(std::make_unique<GeneralizedAlpha>(alphaM, alphaF, gamma, beta));
  builder.setAnalysis(AnalysisBuilder::Kind::Transient);
  State s;
  for (int n = 0; n < 40; ++n) {
    s = alphaStep(s, n * kDt, kDt, kM, kC, kK, kP0, alphaM, alphaF, gamma, beta);
    ASSERT_EQ(builder.analyze(1, kDt), 0);
    const domain::Node& node = domain.node(2);
    EXPECT_NEAR(node.disp(0), s.u, 1e-10 * std::abs(s.u) + 1e-15) << "step " << n + 1;
    EXPECT_NEAR(node.vel(0), s.v, 1e-9 * std::abs(s.v) + 1e-13) << "step " << n + 1;
    EXPECT_NEAR(node.accel(0), s.a, 1e-9 * std::abs(s.a) + 1e-11) << "step " << n + 1;
  }
}

TEST(GeneralizedAlphaTest, NewmarkFollowsItsRecurrence) { checkAlpha(1.0, 1.0, 0.5, 0.25); }

// `integrator HHT 0.8`: gamma = 1.5 - alpha, beta = (2 - alpha)^2 / 4.
TEST(GeneralizedAlphaTest, HHTFollowsItsRecurrence) { checkAlpha(1.0, 0.8, 0.7, 0.36); }

// alphaM != 1: the inertia force at n + alphaM.
TEST(GeneralizedAlphaTest, GeneralizedAlphaFollowsItsRecurrence) {
  checkAlpha(1.2, 0.8, 0.9, 0.49);
}

// Displacement control on a linear spring: after n steps the controlled displacement is n incr
// and the load factor the one that holds it, lambda = k u / P0.
TEST(DisplacementControlTest, ReachesTheDisplacementAndTheLoadThatHoldsIt) {
  constexpr double kK = 250.0, kP0 = 5.0, kIncr = 0.004;
  domain::Domain domain;
  testing::buildSpring(domain, elastic(kK, 0.0), 0.0, kP0);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 10));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  builder.setIntegrator(std::make_unique<DisplacementControl>(2, 0, kIncr, 1, kIncr, kIncr, false));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder.analyze(5, 0.0), 0);
  EXPECT_NEAR(domain.node(2).disp(0), 5 * kIncr, 1e-15);
  EXPECT_NEAR(domain.committedTime(), kK * 5 * kIncr / kP0, 1e-12);
}

// Cubic spring loaded in one step far into its stiff range: the full Newton step from u = 0
// (u = P/k = 0.3) overshoots the root (about 0.082) by far; the line search scales it back.
constexpr double kCubicK = 100.0, kCubicC = 4.0e4, kCubicP = 30.0;

struct Outcome {
  int status = 0;
  int iterations = 0;
  double u = 0.0;
};

Outcome solveCubic(std::unique_ptr<SolutionAlgorithm> algorithm) {
  domain::Domain domain;
  testing::buildSpring(domain, std::make_unique<CubicSpring>(kCubicK, kCubicC), 0.0, kCubicP);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 100));
  builder.setAlgorithm(std::move(algorithm));
  builder.setIntegrator(std::make_unique<LoadControl>(1.0, 1, 1.0, 1.0));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  Outcome o;
  o.status = builder.analyze(1, 0.0);
  o.iterations = builder.test()->iterations();
  o.u = domain.node(2).disp(0);
  return o;
}

void expectRoot(const Outcome& o) {
  ASSERT_EQ(o.status, 0);
  EXPECT_NEAR(kCubicK * o.u + kCubicC * o.u * o.u * o.u, kCubicP, 1e-8);
}

TEST(NewtonLineSearchTest, EverySearchFindsTheRoot) {
  const Outcome newton =
      solveCubic(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  expectRoot(newton);
  using S = NewtonLineSearch::Search;
  for (S search : {S::InitialInterpolated, S::Bisection, S::Secant, S::RegulaFalsi}) {
    const Outcome o = solveCubic(std::make_unique<NewtonLineSearch>(search, 0.8, 10, 0.1, 10.0));
    expectRoot(o);
    // Within Newton's count (9 here): on this spring scaling the overshoots back costs nothing.
    EXPECT_LE(o.iterations, newton.iterations) << "search " << static_cast<int>(search);
  }
}

// The line search itself: along the first Newton direction dx = P/k from u = 0 the projected
// residual is s(eta) = dx (P - f(eta dx)); one InitialInterpolated step from eta = 1 lands at
// eta = s0 / (s0 - s1), the secant root through eta = 0 and eta = 1 (Crisfield 1991, sec. 9.3).
// With the search limited to one step and a test loose enough to accept the first iteration, the
// committed displacement is eta dx.
TEST(NewtonLineSearchTest, InitialInterpolatedStepIsTheSecantRootOfTheProjectedResidual) {
  const double dx = kCubicP / kCubicK;
  const double s0 = dx * kCubicP;
  const double s1 = dx * (kCubicP - kCubicK * dx - kCubicC * dx * dx * dx);
  const double eta = s0 / (s0 - s1);  // 0.027: far short of the full step
  ASSERT_GT(eta, 0.01);
  domain::Domain domain;
  testing::buildSpring(domain, std::make_unique<CubicSpring>(kCubicK, kCubicC), 0.0, kCubicP);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1.0, 1));
  builder.setAlgorithm(std::make_unique<NewtonLineSearch>(
      NewtonLineSearch::Search::InitialInterpolated, 0.8, 1, 0.01, 10.0));
  builder.setIntegrator(std::make_unique<LoadControl>(1.0, 1, 1.0, 1.0));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder.analyze(1, 0.0), 0);
  EXPECT_NEAR(domain.node(2).disp(0), eta * dx, 1e-15);
  // The projected residual there is far smaller than at the full step.
  const double u = eta * dx;
  EXPECT_LT(std::abs(dx * (kCubicP - kCubicK * u - kCubicC * u * u * u)), 0.1 * std::abs(s1));
}

// Krylov-Newton (Carlson & Miller 1998) accelerates the modified Newton iteration: on a cubic
// spring where the initial-tangent iteration contracts only by 3 c u^2 / k = 0.63 per step it
// reaches the root in far fewer iterations.
TEST(KrylovNewtonTest, AcceleratesTheInitialTangentIteration) {
  domain::Domain d1, d2;
  auto run = [](domain::Domain& domain, std::unique_ptr<SolutionAlgorithm> algorithm) {
    testing::buildSpring(domain, std::make_unique<CubicSpring>(100.0, 500.0), 0.0, 25.0);
    AnalysisBuilder builder(domain);
    builder.setTest(dispTest(1e-12, 200));
    builder.setAlgorithm(std::move(algorithm));
    builder.setIntegrator(std::make_unique<LoadControl>(1.0, 1, 1.0, 1.0));
    builder.setAnalysis(AnalysisBuilder::Kind::Static);
    EXPECT_EQ(builder.analyze(1, 0.0), 0);
    const double u = domain.node(2).disp(0);
    EXPECT_NEAR(100.0 * u + 500.0 * u * u * u, 25.0, 1e-9);
    return builder.test()->iterations();
  };
  const int modified =
      run(d1, std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Initial, true));
  const int krylov = run(d2, std::make_unique<KrylovNewton>(true, 3));
  EXPECT_GT(modified, 30);
  EXPECT_LT(krylov, modified / 3);
}

// wipe forgets every component: analyze is refused until an analysis is defined again, and the
// new one continues from the committed state of the domain, which wipe leaves alone.
TEST(AnalysisBuilderTest, WipeForgetsTheComponentsButNotTheCommittedState) {
  constexpr double kK = 250.0, kP0 = 5.0;
  domain::Domain domain;
  testing::buildSpring(domain, elastic(kK, 0.0), 0.0, kP0);
  AnalysisBuilder builder(domain);
  auto define = [&] {
    builder.setTest(dispTest(1e-12, 10));
    builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
    builder.setIntegrator(std::make_unique<LoadControl>(0.1, 1, 0.1, 0.1));
    builder.setAnalysis(AnalysisBuilder::Kind::Static);
  };
  define();
  ASSERT_EQ(builder.analyze(4, 0.0), 0);
  builder.wipe();
  EXPECT_EQ(builder.kind(), AnalysisBuilder::Kind::None);
  EXPECT_THROW((void)builder.analyze(1, 0.0), InputError);
  define();
  ASSERT_EQ(builder.analyze(6, 0.0), 0);
  EXPECT_NEAR(domain.committedTime(), 1.0, 1e-12);
  EXPECT_NEAR(domain.node(2).disp(0), kP0 / kK, 1e-14);
}

}  // namespace
}  // namespace dabs::analysis
