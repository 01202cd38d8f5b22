// SPDX-License-Identifier: MIT
// The driver's integrators, algorithms and builder on one-dof springs, each against a closed form
// or the scheme's own recurrence worked out here independently of the driver's code.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "materials/Elastic.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/integrators/CentralDifference.h"
#include "tcl/analysis/integrators/GeneralizedAlpha.h"
#include "tcl/analysis/algorithms/LinearAlgorithm.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/analysis/tests/SpringModel.h"
#include "tcl/domain/ConstantSeries.h"

namespace dabs::analysis {
namespace {

using testing::CubicSpring;
using testing::dispTest;

/// The spring of SpringModel.h with its load held constant (a step load P0 from t = 0).
void buildStepLoadedSpring(domain::Domain& domain, double k, double m, double P0) {
  materials::Elastic::Params p;
  p.E = k;
  testing::buildSpring(domain, std::make_unique<materials::Elastic>(1, p), m, 0.0);
  auto pattern = std::make_unique<domain::PlainPattern>(
      2, std::make_shared<domain::ConstantSeries>(2, 1.0), 1.0);
  pattern->loads.push_back({2, Eigen::VectorXd::Constant(1, P0)});
  domain.addPattern(std::move(pattern));
}

// Average acceleration (Newmark 1/2, 1/4) on an undamped linear SDOF: the amplification matrix is
// the Cayley transform of a skew matrix in the energy coordinates (omega x, v), x = u - P0/k, so
// every step is a rotation by omega_bar dt = 2 atan(omega dt / 2): the amplitude is kept exactly
// and the period lengthens by T_bar/T = omega dt / (2 atan(omega dt / 2)) (Chopra, Dynamics of
// Structures, sec. 5.5; Hughes 1987, sec. 9.1). Checked from the first step on, once the state
// satisfies equilibrium.
TEST(NewmarkTest, AverageAccelerationKeepsAmplitudeAndLengthensThePeriod) {
  constexpr double kK = 400.0, kM = 1.0, kP0 = 4.0;
  const double omega = std::sqrt(kK / kM),
               dt = 0.05;  // omega dt = 1: a coarse step, visible elongation
  domain::Domain domain;
  buildStepLoadedSpring(domain, kK, kM, kP0);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 10));
  builder.setAlgorithm(std::make_unique<LinearAlgorithm>(false, false));
  builder.setIntegrator(std::make_unique<GeneralizedAlpha>(1.0, 1.0, 0.5, 0.25));
  builder.setAnalysis(AnalysisBuilder::Kind::Transient);
  const double ust = kP0 / kK;
  const double expectedAngle = 2.0 * std::atan(omega * dt / 2.0);
  ASSERT_EQ(builder.analyze(1, dt), 0);
  double x0 = omega * (domain.node(2).disp(0) - ust), v0 = domain.node(2).vel(0);
  const double radius = std::hypot(x0, v0);
  for (int n = 2; n <= 60; ++n) {
    ASSERT_EQ(builder.analyze(1, dt), 0);
    const double x1 = omega * (domain.node(2).disp(0) - ust), v1 = domain.node(2).vel(0);
    EXPECT_NEAR(std::hypot(x1, v1), radius, 1e-12 * radius) << "step " << n;
    // Signed angle from (x0, v0) to (x1, v1); the motion turns clockwise in the (omega x, v) plane.
    const double angle = std::atan2(x0 * v1 - v0 * x1, x0 * x1 + v0 * v1);
    EXPECT_NEAR(-angle, expectedAngle, 1e-10) << "step " << n;
    x0 = x1;
    v0 = v1;
  }
  // The elongation formula at omega dt = 1: T_bar/T = 1/(2 atan(0.5)) = 1.0784.
  EXPECT_NEAR(omega * dt / expectedAngle, 1.0784, 1e-4);
}

// Central difference: m (u_{n+1} - 2 u_n + u_{n-1}) / dt^2 + k u_n = P0 at every step, and the
// scheme is stable only for omega dt <= 2 (Chopra sec. 5.3, Table 5.3.1).
void runCentralDifference(double omegaDt, std::vector<double>& u) {
  constexpr double kK = 400.0, kM = 1.0, kP0 = 4.0;
  const double dt = omegaDt / std::sqrt(kK / kM);
  domain::Domain domain;
  buildStepLoadedSpring(domain, kK, kM, kP0);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 10));
  builder.setAlgorithm(std::make_unique<LinearAlgorithm>(false, false));
  builder.setIntegrator(std::make_unique<CentralDifference>());
  builder.setAnalysis(AnalysisBuilder::Kind::Transient);
  u.assign(1, 0.0);
  for (int n = 1; n <= 120; ++n) {
    if (builder.analyze(1, dt) != 0) return;
    u.push_back(domain.node(2).disp(0));
    if (n >= 2) {
      const double un = u[n - 1], recurrence = 2.0 * un - u[n - 2] + dt * dt * (kP0 - kK * un) / kM;
      EXPECT_NEAR(u[n], recurrence, 1e-9 * (std::abs(recurrence) + kP0 / kK)) << "step " << n;
    }
  }
}

TEST(CentralDifferenceTest, FollowsItsRecurrenceAndIsStableBelowOmegaDtTwo) {
  constexpr double kUst = 4.0 / 400.0;
  std::vector<double> u;
  runCentralDifference(1.9, u);
  ASSERT_EQ(u.size(), 121u);
  double peak = 0.0;
  for (double v : u) peak = std::max(peak, std::abs(v));
  // Bounded: the discrete oscillation about u_st has amplitude u_st / sqrt(1 - (omega dt / 2)^2)
  // at most (the invariant of the three-term recurrence), 3.2 u_st at omega dt = 1.9.
  EXPECT_LT(peak, kUst * (1.0 + 1.0 / std::sqrt(1.0 - 0.95 * 0.95)) * 1.0001);
  // Above the limit the root of largest modulus of lambda^2 - (2 - (omega dt)^2) lambda + 1 is
  // 1.88 at omega dt = 2.1: the response grows without bound.
  runCentralDifference(2.1, u);
  double last = u.size() > 1 ? std::abs(u.back()) : 0.0;
  EXPECT_TRUE(u.size() < 121u || !std::isfinite(last) || last > 1e20 * kUst) << last;
}

// Load control on a linear spring: the load factor after n steps is n dLambda, and the
// displacement is lambda P0 / k.
TEST(LoadControlTest, ReachesTheLoadFactorInEqualSteps) {
  constexpr double kK = 250.0, kP0 = 5.0;
  domain::Domain domain;
  materials::Elastic::Params p;
  p.E = kK;
  testing::buildSpring(domain, std::make_unique<materials::Elastic>(1, p), 0.0, kP0);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 10));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false));
  builder.setIntegrator(std::make_unique<LoadControl>(0.1, 1, 0.1, 0.1));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder.analyze(10, 0.0), 0);
  EXPECT_NEAR(domain.committedTime(), 1.0, 1e-12);
  EXPECT_NEAR(domain.node(2).disp(0), kP0 / kK, 1e-14);
  // A new integrator between analyze calls takes over from the committed state.
  builder.setIntegrator(std::make_unique<LoadControl>(0.25, 1, 0.25, 0.25));
  ASSERT_EQ(builder.analyze(2, 0.0), 0);
  EXPECT_NEAR(domain.committedTime(), 1.5, 1e-12);
  EXPECT_NEAR(domain.node(2).disp(0), 1.5 * kP0 / kK, 1e-14);
}

// Newton (current tangent) and modified Newton (initial tangent) on the cubic spring, loaded in
// one step to P: the driver's iterates are those of the scalar iterations
// u <- u - (k u + c u^3 - P) / f'(u), stopped at the first |du| < tol, computed here. With the
// initial tangent the iteration contracts by 3 c u^2 / k = 0.63 per step near the solution
// (u = 0.205): linear convergence, many more iterations than Newton's.
struct ScalarRun {
  double u = 0.0;
  int iterations = 0;
};
ScalarRun scalarNewton(double k, double c, double P, bool initialTangent, double tol) {
  ScalarRun r;
  for (r.iterations = 1; r.iterations <= 200; ++r.iterations) {
    const double tangent = initialTangent ? k : k + 3.0 * c * r.u * r.u;
    const double du = (P - k * r.u - c * r.u * r.u * r.u) / tangent;
    r.u += du;
    if (std::abs(du) < tol) break;
  }
  return r;
}

void checkNewton(NewtonRaphson::Tangent tangent, bool modified, bool initialTangent) {
  constexpr double kK = 100.0, kC = 500.0, kP = 25.0, kTol = 1e-12;
  domain::Domain domain;
  testing::buildSpring(domain, std::make_unique<CubicSpring>(kK, kC), 0.0, kP);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(kTol, 200));
  builder.setAlgorithm(std::make_unique<NewtonRaphson>(tangent, modified));
  builder.setIntegrator(std::make_unique<LoadControl>(1.0, 1, 1.0, 1.0));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  ASSERT_EQ(builder.analyze(1, 0.0), 0);
  const ScalarRun expected = scalarNewton(kK, kC, kP, initialTangent, kTol);
  EXPECT_EQ(builder.test()->iterations(), expected.iterations);
  EXPECT_NEAR(domain.node(2).disp(0), expected.u, 1e-13);
  // The converged displacement solves k u + c u^3 = P.
  const double u = domain.node(2).disp(0);
  EXPECT_NEAR(kK * u + kC * u * u * u, kP, 1e-9);
}

TEST(NewtonRaphsonTest, CurrentTangentFollowsScalarNewtonQuadratically) {
  checkNewton(NewtonRaphson::Tangent::Current, false, false);
  // Quadratic convergence: a handful of iterations to 1e-12.
  EXPECT_LE(scalarNewton(100.0, 500.0, 25.0, false, 1e-12).iterations, 12);
}

TEST(NewtonRaphsonTest, InitialTangentFollowsScalarModifiedNewtonLinearly) {
  checkNewton(NewtonRaphson::Tangent::Initial, true, true);
  EXPECT_GT(scalarNewton(100.0, 500.0, 25.0, true, 1e-12).iterations,
            2 * scalarNewton(100.0, 500.0, 25.0, false, 1e-12).iterations);
}

}  // namespace
}  // namespace dabs::analysis
