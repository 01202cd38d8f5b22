// SPDX-License-Identifier: MIT
// TRBDF2 on a linear damped SDOF against the scheme's own recurrence, worked out independently:
// trapezoidal and three-point backward-difference steps alternating (Bathe and Baig 2005).
#include "tcl/analysis/integrators/TRBDF2.h"

#include <gtest/gtest.h>

#include <cmath>

#include "materials/Elastic.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

constexpr double kM = 2.0, kK = 800.0, kC = 3.0, kP0 = 50.0;

struct State {
  double u = 0.0, v = 0.0, a = 0.0;
};

// One step of the recurrence: equilibrium m a + c v + k u = P0 t at the step's end, with
// v = v0 + cv (u - u0), a = a0 + ca (u - u0) from the scheme's predictor (v0, a0 at u = u0).
State solveStep(double u0, double v0, double a0, double cv, double ca, double t) {
  const double keff = kK + kC * cv + kM * ca;
  const double r = kP0 * t - kK * u0 - kC * v0 - kM * a0;
  const double du = r / keff;
  return {u0 + du, v0 + cv * du, a0 + ca * du};
}

TEST(TRBDF2Test, AlternatesTrapezoidalAndBackwardDifferenceSteps) {
  domain::Domain domain;
  materials::Elastic::Params p;
  p.E = kK;
  p.eta = kC;
  testing::buildSpring(domain, std::make_unique<materials::Elastic>(1, p), kM, kP0);
  AnalysisBuilder builder(domain);
  builder.setIntegrator(std::make_unique<TRBDF2>());
  builder.setAnalysis(AnalysisBuilder::Kind::Transient);

  // Independent recurrence; a new step size restarts with a trapezoidal step.
  State prev, now;  // states at t_{n-1} and t_n
  double t = 0.0;
  const double steps[] = {0.01, 0.01, 0.01, 0.01, 0.01, 0.02, 0.02, 0.02, 0.02};
  double lastDt = 0.0;
  bool bdf = true;
  for (double dt : steps) {
    bdf = !(dt != lastDt || bdf);
    lastDt = dt;
    t += dt;
    State next;
    if (!bdf) {
      // Trapezoidal: predictor v = -v_n, a = -4/dt v_n - a_n.
      next = solveStep(now.u, -now.v, -4.0 / dt * now.v - now.a, 2.0 / dt, 4.0 / (dt * dt), t);
    } else {
      const double v0 = (prev.u - now.u) / (2.0 * dt);
      const double a0 = (prev.v - 4.0 * now.v + 3.0 * v0) / (2.0 * dt);
      next = solveStep(now.u, v0, a0, 1.5 / dt, 2.25 / (dt * dt), t);
    }
    prev = now;
    now = next;
    ASSERT_EQ(builder.analyze(1, dt), 0);
    const domain::Node& n = domain.node(2);
    EXPECT_NEAR(n.disp(0), now.u, 1e-10 * std::abs(now.u) + 1e-15) << "t = " << t;
    EXPECT_NEAR(n.vel(0), now.v, 1e-9 * std::abs(now.v) + 1e-13) << "t = " << t;
    EXPECT_NEAR(n.accel(0), now.a, 1e-9 * std::abs(now.a) + 1e-11) << "t = " << t;
  }
}

}  // namespace
}  // namespace dabs::analysis
