// SPDX-License-Identifier: MIT
#include "contact/NormalLaw.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::contact {
namespace {

// Integrates the relative motion x'' = -F(x, x')/m of an SDOF impact (x = penetration, starting
// at 0 with approach speed v0) with classical RK4 until the penetration is back to zero; returns
// the exit speed ratio, the exit velocity interpolated linearly at the crossing x = 0. `pull`
// lets the force go tensile (the textbook Kelvin-Voigt model).
double integrateImpact(double K, double C, double m, double v0, bool pull) {
  auto force = [&](double x, double v) {
    const double f = K * x + C * v;
    return pull ? f : std::max(f, 0.0);
  };
  const double T = 2 * std::numbers::pi * std::sqrt(m / K);
  const double dt = T / 100000;
  double x = 0.0, v = v0;
  for (int i = 0; i < 1000000; ++i) {
    const double k1x = v, k1v = -force(x, v) / m;
    const double k2x = v + 0.5 * dt * k1v, k2v = -force(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v) / m;
    const double k3x = v + 0.5 * dt * k2v, k3v = -force(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v) / m;
    const double k4x = v + dt * k3v, k4v = -force(x + dt * k3x, v + dt * k3v) / m;
    const double xNew = x + dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vNew = v + dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xNew < 0.0 && vNew < 0.0) return -(v + (vNew - v) * x / (x - xNew)) / v0;
    x = xNew;
    v = vNew;
  }
  return NAN;
}

constexpr double kRestitutionTol = 1e-6;  // RK4 with T/100000 steps; kink at the force zero

TEST(NormalLawTest, DampingRatioReproducesRestitutionWhenTheDashpotMayPull) {
  // e = exp(-xi pi / sqrt(1 - xi^2)) inverts xi = -ln e / sqrt(pi^2 + ln^2 e).
  for (double e : {0.2, 0.5, 0.65, 0.9}) {
    const double xi = NormalLaw::dampingRatio(e);
    EXPECT_NEAR(std::exp(-xi * std::numbers::pi / std::sqrt(1 - xi * xi)), e, 1e-12);
    const double K = 4e6, m = 2.0;
    EXPECT_NEAR(integrateImpact(K, 2 * xi * std::sqrt(K * m), m, 1.3, true), e, kRestitutionTol);
  }
  EXPECT_EQ(NormalLaw::dampingRatio(1.0), 0.0);
  EXPECT_EQ(NormalLaw::dampingRatio(0.0), 1.0);
}

TEST(NormalLawTest, NoTensionRaisesEffectiveRestitutionToClosedForm) {
  for (double e : {0.3, 0.5, 0.65, 0.8}) {
    const double xi = NormalLaw::dampingRatio(e);
    const double K = 1e7, m = 5.0;
    const double eEff = NormalLaw::effectiveRestitution(xi);
    EXPECT_GT(eEff, e);
    EXPECT_NEAR(integrateImpact(K, 2 * xi * std::sqrt(K * m), m, 0.7, false), eEff,
                kRestitutionTol);
  }
}

TEST(NormalLawTest, DashpotFromReducedMassAndClippedForce) {
  const NormalLaw law({1e6, 0.6, 3.0, 6.0});
  const double xi = NormalLaw::dampingRatio(0.6);
  EXPECT_NEAR(law.damping(), 2 * xi * std::sqrt(1e6 * 2.0), 1e-9);  // M1 M2/(M1+M2) = 2
  EXPECT_EQ(law.force(0.01, -5.0), 0.0);                            // open
  EXPECT_NEAR(law.force(-0.002, 0.0), 2000.0, 1e-9);                // K * penetration
  EXPECT_EQ(law.force(-0.002, 1e6), 0.0);                           // would pull: zero
}

TEST(NormalLawTest, BadInputThrows) {
  EXPECT_THROW((NormalLaw::Params{0.0, 1.0}.validate()), InputError);
  EXPECT_THROW((NormalLaw::Params{1.0, 1.5}.validate()), InputError);
  EXPECT_THROW((NormalLaw::Params{1.0, 0.5}.validate()), InputError);  // e < 1 needs masses
  EXPECT_NO_THROW((NormalLaw::Params{1.0, 0.5, 1.0, 2.0}.validate()));
}

}  // namespace
}  // namespace dabs::contact
