// SPDX-License-Identifier: MIT
// The Linear algorithm takes one solve per step with the tangent it is told to use, and
// factorises only when that tangent may have changed; Newton and modified Newton factorise per
// iteration and per step. All on a cubic spring under load control, against the scalar steps
// u_{n+1} = u_n + (P_{n+1} - f(u_n)) / K, K = f'(u_n) (current) or k (initial).
#include "tcl/analysis/algorithms/LinearAlgorithm.h"

#include <gtest/gtest.h>

#include <memory>

#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/analysis/tests/SpringModel.h"

namespace dabs::analysis {
namespace {

using testing::CubicSpring;
using testing::dispTest;

constexpr double kK = 100.0, kC = 500.0, kP = 25.0, kDLambda = 0.25;
constexpr int kSteps = 4;

double force(double u) { return kK * u + kC * u * u * u; }
double tangent(double u) { return kK + 3.0 * kC * u * u; }

struct Outcome {
  std::vector<double> u;
  long factorizations = 0;
  long iterations = 0;
};

Outcome run(std::unique_ptr<SolutionAlgorithm> algorithm,
            std::unique_ptr<materials::UniaxialMaterial> spring) {
  domain::Domain domain;
  testing::buildSpring(domain, std::move(spring), 0.0, kP);
  AnalysisBuilder builder(domain);
  builder.setTest(dispTest(1e-12, 50));
  builder.setAlgorithm(std::move(algorithm));
  builder.setIntegrator(std::make_unique<LoadControl>(kDLambda, 1, kDLambda, kDLambda));
  builder.setAnalysis(AnalysisBuilder::Kind::Static);
  Outcome r;
  for (int n = 0; n < kSteps; ++n) {
    EXPECT_EQ(builder.analyze(1, 0.0), 0);
    r.u.push_back(domain.node(2).disp(0));
  }
  r.factorizations = builder.statistics().factorizations;
  r.iterations = builder.statistics().iterations;
  return r;
}

std::vector<double> scalarLinear(bool initial) {
  std::vector<double> u;
  double x = 0.0;
  for (int n = 1; n <= kSteps; ++n) {
    x += (n * kDLambda * kP - force(x)) / (initial ? kK : tangent(x));
    u.push_back(x);
  }
  return u;
}

void expectSame(const std::vector<double>& got, const std::vector<double>& expected) {
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    EXPECT_NEAR(got[i], expected[i], 1e-14) << "step " << i + 1;
}

TEST(LinearAlgorithmTest, CurrentTangentOneSolveAndOneFactorisationPerStep) {
  const Outcome r =
      run(std::make_unique<LinearAlgorithm>(false, false), std::make_unique<CubicSpring>(kK, kC));
  expectSame(r.u, scalarLinear(false));
  EXPECT_EQ(r.iterations, kSteps);
  EXPECT_EQ(r.factorizations, kSteps);
}

TEST(LinearAlgorithmTest, InitialTangentAndFactorOnceFactoriseOnce) {
  Outcome r =
      run(std::make_unique<LinearAlgorithm>(true, false), std::make_unique<CubicSpring>(kK, kC));
  expectSame(r.u, scalarLinear(true));
  EXPECT_EQ(r.factorizations, 1);
  // -factorOnce keeps the first step's tangent, here the initial one (u = 0).
  r = run(std::make_unique<LinearAlgorithm>(false, true), std::make_unique<CubicSpring>(kK, kC));
  expectSame(r.u, scalarLinear(true));
  EXPECT_EQ(r.factorizations, 1);
}

TEST(NewtonRaphsonTest, NewtonFactorisesPerIterationModifiedNewtonPerStep) {
  const Outcome newton =
      run(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false),
          std::make_unique<CubicSpring>(kK, kC));
  EXPECT_EQ(newton.factorizations, newton.iterations);
  const Outcome modified =
      run(std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, true),
          std::make_unique<CubicSpring>(kK, kC));
  EXPECT_EQ(modified.factorizations, kSteps);
  EXPECT_GT(modified.iterations, newton.iterations);
  // Both converge to the same points on the curve: f(u_n) = n dLambda P.
  for (int n = 0; n < kSteps; ++n) {
    EXPECT_NEAR(force(newton.u[n]), (n + 1) * kDLambda * kP, 1e-9);
    EXPECT_NEAR(force(modified.u[n]), (n + 1) * kDLambda * kP, 1e-9);
  }
}

}  // namespace
}  // namespace dabs::analysis
