// SPDX-License-Identifier: MIT
// Over 400 lines: one test file for the bearing material, each test a separate closed form or
// consistency check.
// Closed-form and consistency checks of the Yoshida et al. (1999) bi-axial bearing material.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "materials/InputError.h"
#include "materials/bearing/YoshidaBearingMaterial.h"

namespace dabs::materials {
namespace {

using Params = YoshidaBearingMaterial::Params;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

constexpr double kPi = std::numbers::pi;
constexpr double kY0 = 150.0;            // kN
constexpr double kU0 = 0.012;            // m
constexpr double kFine = 2e-4;           // sub-step (fraction of U0) for closed-form comparisons
constexpr double kClosedFormTol = 2e-3;  // relative to Y; first-order error of the fine sub-step
constexpr double kFdRelTol = 1e-5;       // FD tangent check (style.md section 7)

Params basic(double n) {
  Params p;
  p.Y0 = kY0;
  p.U0 = kU0;
  p.n = n;
  p.maxSubIncrement = kFine;
  return p;
}

/// Drives the material through `path`, committing each point; dt per step.
void drive(YoshidaBearingMaterial& m, const Vec2& target, double dt = 0.0) {
  ASSERT_TRUE(ok(m.setTrialStrain(target, Vec2::Zero(), dt)));
  m.commitState();
}

/// Central-difference tangent at `u` from the committed state.
Mat2 fdTangent(YoshidaBearingMaterial& m, const Vec2& u, const Vec2& rate, double dt, double h) {
  Mat2 k;
  for (int j = 0; j < 2; ++j) {
    Vec2 up = u, um = u;
    up(j) += h;
    um(j) -= h;
    EXPECT_TRUE(ok(m.setTrialStrain(up, rate, dt)));
    const Vec2 fp = m.getStress();
    EXPECT_TRUE(ok(m.setTrialStrain(um, rate, dt)));
    const Vec2 fm = m.getStress();
    k.col(j) = (fp - fm) / (2 * h);
  }
  EXPECT_TRUE(ok(m.setTrialStrain(u, rate, dt)));
  return k;
}

double relDiff(const Mat2& a, const Mat2& b) {
  return (a - b).norm() / std::max(a.norm(), b.norm());
}

TEST(YoshidaBearingMaterialTest, MonotonicN2IsTanh) {
  YoshidaBearingMaterial m(1, basic(2.0));
  const Vec2 dir = Vec2(0.6, -0.8);  // oblique: the law is isotropic
  for (int i = 1; i <= 500; ++i) {
    const double u = 5.0 * kU0 * i / 500.0;
    drive(m, u * dir);
    const double expected = kY0 * std::tanh(u / kU0);  // F = Y tanh(U/U0)
    EXPECT_NEAR(m.getStress().dot(dir), expected, kClosedFormTol * kY0) << "U/U0 = " << u / kU0;
    EXPECT_NEAR(m.getStress().dot(Vec2(0.8, 0.6)), 0.0, 1e-9 * kY0);
  }
}

TEST(YoshidaBearingMaterialTest, MonotonicN1IsExponential) {
  YoshidaBearingMaterial m(1, basic(1.0));
  for (int i = 1; i <= 400; ++i) {
    const double u = 4.0 * kU0 * i / 400.0;
    drive(m, Vec2(u, 0.0));
    EXPECT_NEAR(m.getStress().x(), kY0 * (1.0 - std::exp(-u / kU0)), kClosedFormTol * kY0);
  }
}

// n = 1/2, no back force: dz/du = 1 - sqrt(z) on loading (z = F/Y, u = U/U0), so with w = sqrt(z)
// u = -2 w - 2 ln(1 - w).
TEST(YoshidaBearingMaterialTest, MonotonicNHalfFollowsClosedForm) {
  YoshidaBearingMaterial m(1, basic(0.5));
  const Vec2 dir = Vec2(-0.6, 0.8);
  for (int i = 1; i <= 400; ++i) {
    const double u = 4.0 * kU0 * i / 400.0;
    drive(m, u * dir);
    double lo = 0.0, hi = 1.0;  // -2w - 2 ln(1-w) increases from 0 to infinity on [0, 1)
    for (int it = 0; it < 200; ++it) {
      const double w = 0.5 * (lo + hi);
      (-2.0 * w - 2.0 * std::log1p(-w) < u / kU0 ? lo : hi) = w;
    }
    const double w = 0.5 * (lo + hi);
    EXPECT_NEAR(m.getStress().dot(dir), kY0 * w * w, kClosedFormTol * kY0) << "U/U0 = " << u / kU0;
  }
}

// A set with n < 1 (the fitted high-damping-rubber range) whose local Newton once stopped on
// round-off (the iteration is monotone: a step back is the root): triangular cycles of 0.3.
TEST(YoshidaBearingMaterialTest, SmallNConvergesOnCycles) {
  Params p;
  p.Y0 = 0.466798;
  p.U0 = 0.149951;
  p.n = 0.219817;
  p.alpha0 = 0.478224;
  p.beta = 0.256229;
  p.q = 0.168761;
  p.gamma = 0.00355117;
  YoshidaBearingMaterial m(1, p);
  double u = 0.0;
  for (int half = 0; half < 13; ++half) {
    const double sign = (half % 2 == 0) ? 1.0 : -1.0;
    for (int i = 0; i < (half == 0 ? 40 : 80); ++i) {
      u += sign * 0.3 / 40;
      ASSERT_TRUE(ok(m.setTrialStrain(Vec2(u, 0.0), Vec2::Zero(), 0.0))) << "half cycle " << half;
      m.commitState();
    }
  }
}

TEST(YoshidaBearingMaterialTest, ConstantBackForceGivesPostYieldSlopeAndAsymptote) {
  for (double n : {1.0, 2.0, 3.0}) {
    Params p = basic(n);
    const double c = 0.4;  // alpha0 = c, beta = 0: constant back-force factor
    p.alpha0 = c;
    YoshidaBearingMaterial m(1, p);
    const double k0 = kY0 / kU0;
    const double uEnd = 15.0 * kU0;
    const int steps = 3000;
    for (int i = 1; i <= steps; ++i) drive(m, Vec2(0.0, uEnd * i / steps));
    // Asymptote [Y (1+c)^(-1/n) + c K0 U] / (1+c) and slope K0 c/(1+c).
    const double asymptote = (kY0 * std::pow(1.0 + c, -1.0 / n) + c * k0 * uEnd) / (1.0 + c);
    EXPECT_NEAR(m.getStress().y(), asymptote, kClosedFormTol * kY0) << "n = " << n;
    EXPECT_NEAR(m.getTangent()(1, 1), k0 * c / (1.0 + c), 1e-3 * k0) << "n = " << n;
  }
}

TEST(YoshidaBearingMaterialTest, BackForceFactorIsClippedAtZero) {
  Params p = basic(2.0);
  p.alpha0 = 0.5;
  p.beta = 1.0;
  p.q = 1.0;  // a = 0.5 - Umax/U0 reaches zero at Umax = 0.5 U0
  YoshidaBearingMaterial m(1, p);
  drive(m, Vec2(0.3 * kU0, 0.0));
  EXPECT_GT(m.response("backForce")->norm(), 0.0);
  for (int i = 1; i <= 100; ++i) drive(m, Vec2(0.3 * kU0 + 2.0 * kU0 * i / 100.0, 0.0));
  EXPECT_EQ(m.response("backForce")->norm(), 0.0);
  // Once a = 0, unloading and reloading follow the plain n = 2 law: z = F/Y stays below 1.
  for (int i = 1; i <= 200; ++i) drive(m, Vec2(2.3 * kU0 - 6.0 * kU0 * i / 200.0, 0.0));
  EXPECT_EQ(m.response("backForce")->norm(), 0.0);
  EXPECT_LT(m.getStress().norm(), kY0);
  EXPECT_NEAR(m.getStress().x(), -kY0, 0.05 * kY0);
}

// Before yield (|z| well below 1, |z|^n negligible for a large n) the hysteretic law reduces to
// dF1 = Y(U) dU / U0 with Y = Y0 (1 + gamma (U/U0)^2): a non-linear elastic spring
// F1 = (Y0/U0) (U + gamma U^3 / (3 U0^2)), whatever the back-force factor, and unloading retraces
// it.
TEST(YoshidaBearingMaterialTest, HardeningBeforeYieldIsCubicElasticSpring) {
  Params p = basic(40.0);
  p.alpha0 = 0.5;  // constant back-force factor: must not change the elastic branch
  p.gamma = 0.05;
  YoshidaBearingMaterial m(1, p);
  const Vec2 dir = Vec2(0.8, 0.6);
  const double uEnd = 0.6 * kU0;  // |z| stays below 0.6: |z|^40 < 1e-8
  const int steps = 300;
  auto spring = [&](double u) { return kY0 / kU0 * (u + p.gamma * u * u * u / (3.0 * kU0 * kU0)); };
  for (int i = 1; i <= steps; ++i) {
    const double u = uEnd * i / steps;
    drive(m, u * dir);
    EXPECT_NEAR(m.getStress().dot(dir), spring(u), 1e-5 * kY0) << "U/U0 = " << u / kU0;
  }
  EXPECT_GT(m.getStress().norm(), kY0 / kU0 * uEnd * 1.005);  // stiffer than the linear spring
  for (int i = steps - 1; i >= 0; --i) drive(m, uEnd * i / steps * dir);
  EXPECT_NEAR(m.getStress().norm(), 0.0, 1e-5 * kY0);  // elastic: back to zero force
}

// Circular orbit with no back force: rho = (R/U0) cos(phi), rho^n = sin(phi).
struct Orbit {
  double rho, phi;
};
Orbit solveOrbit(double r, double n) {
  double lo = 0.0, hi = kPi / 2;  // f(phi) = ((R/U0) cos phi)^n - sin phi decreases
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::pow(r * std::cos(mid), n) - std::sin(mid) > 0.0 ? lo : hi) = mid;
  }
  return {r * std::cos(lo), lo};
}

struct OrbitResult {
  double minForce = 1e300, maxForce = 0.0, angle = 0.0, energy = 0.0;
};

/// Runs 4 revolutions of U = R (cos t, sin t) after a radial ramp; the last one is measured.
/// `coupled = false` replaces the material by two independent 1D springs with the same law.
OrbitResult runOrbit(bool coupled, double radius, int perRev) {
  const Params p = basic(2.0);
  YoshidaBearingMaterial m(1, p), mx(2, p), my(3, p);
  auto force = [&]() -> Vec2 {
    if (coupled) return m.getStress();
    return Vec2(mx.getStress().x(), my.getStress().x());
  };
  auto set = [&](const Vec2& u) {
    if (coupled) {
      drive(m, u);
    } else {
      drive(mx, Vec2(u.x(), 0.0));
      drive(my, Vec2(u.y(), 0.0));
    }
  };
  for (int i = 1; i <= 200; ++i) set(Vec2(radius * i / 200.0, 0.0));
  OrbitResult res;
  Vec2 uPrev(radius, 0.0), fPrev = force();
  for (int i = 1; i <= 4 * perRev; ++i) {
    const double t = 2 * kPi * i / perRev;
    const Vec2 u = radius * Vec2(std::cos(t), std::sin(t));
    set(u);
    const Vec2 f = force();
    if (i > 3 * perRev) {
      res.minForce = std::min(res.minForce, f.norm());
      res.maxForce = std::max(res.maxForce, f.norm());
      res.energy += 0.5 * (f + fPrev).dot(u - uPrev);
      // angle from U to F, positive in the direction of motion
      res.angle = std::atan2(u.x() * f.y() - u.y() * f.x(), u.dot(f));
    }
    uPrev = u;
    fPrev = f;
  }
  return res;
}

TEST(YoshidaBearingMaterialTest, CircularOrbitSettlesOnClosedForm) {
  const double r = 3.0;  // R/U0
  const Orbit o = solveOrbit(r, 2.0);
  EXPECT_NEAR(o.rho, 0.97262, 1e-5);  // closed-form values of the circular orbit
  EXPECT_NEAR(o.phi, 1.2406, 1e-4);
  const OrbitResult res = runOrbit(true, r * kU0, 4000);
  EXPECT_NEAR(res.minForce, kY0 * o.rho, kClosedFormTol * kY0);
  EXPECT_NEAR(res.maxForce, kY0 * o.rho, kClosedFormTol * kY0);
  // The force is phi ahead of the displacement in the direction of motion (towards the velocity),
  // i.e. the displacement trails the force by phi.
  EXPECT_NEAR(res.angle, o.phi, 2e-3);
  const double energy = 2 * kPi * r * kU0 * kY0 * std::pow(o.rho, 3.0);  // 2 pi R Y rho^(n+1)
  EXPECT_NEAR(res.energy, energy, 2e-3 * energy);
}

TEST(YoshidaBearingMaterialTest, UncoupledSpringsFailCircularOrbit) {
  const double r = 3.0;
  const Orbit o = solveOrbit(r, 2.0);
  const OrbitResult res = runOrbit(false, r * kU0, 4000);
  // Two independent springs each reach nearly Y: the resultant swings between about Y and
  // sqrt(2) Y instead of staying at Y rho.
  EXPECT_GT(res.maxForce, 1.3 * kY0);
  EXPECT_GT(res.maxForce - res.minForce, 0.2 * kY0);
  EXPECT_GT(res.maxForce - kY0 * o.rho, 0.3 * kY0);
}

TEST(YoshidaBearingMaterialTest, MaxwellAmplitudeUnderHarmonicMotion) {
  Params p = basic(2.0);
  p.k = 2000.0;   // kN/m
  p.eta = 300.0;  // kN s/m -> tau = 0.15 s
  const double tau = p.eta / p.k;
  const double a = 0.02, w = 2 * kPi * 1.5;
  YoshidaBearingMaterial m(1, p);
  const int perPeriod = 2000;
  const double dt = 2 * kPi / w / perPeriod;
  double peak = 0.0;
  for (int i = 1; i <= 10 * perPeriod; ++i) {
    drive(m, Vec2(0.0, a * std::sin(w * i * dt)), dt);
    if (i > 8 * perPeriod) peak = std::max(peak, std::abs((*m.response("viscousForce"))(1)));
  }
  const double expected = p.k * a * w * tau / std::sqrt(1.0 + w * w * tau * tau);
  EXPECT_NEAR(peak, expected, 1e-4 * expected);
}

TEST(YoshidaBearingMaterialTest, MaxwellStaticStepIsSpring) {
  Params p = basic(2.0);
  p.k = 2000.0;
  p.eta = 300.0;
  YoshidaBearingMaterial m(1, p);
  ASSERT_TRUE(ok(m.setTrialStrain(Vec2(1e-4, 0.0), Vec2::Zero(), 0.0)));
  EXPECT_NEAR((*m.response("viscousForce"))(0), p.k * 1e-4, 1e-12);
}

struct TangentCase {
  const char* name;
  Params p;
  std::vector<Vec2> history;  // committed path before the trial
  Vec2 trial;
  double dt;
};

TEST(YoshidaBearingMaterialTest, TangentMatchesFiniteDifference) {
  Params plain = basic(2.0);
  plain.maxSubIncrement = 0.05;
  Params full = plain;
  full.n = 1.7;
  full.alpha0 = 0.6;
  full.beta = 0.2;
  full.q = 1.5;
  full.gamma = 0.05;
  full.k = 3000.0;
  full.eta = 200.0;
  const Vec2 a(1.5 * kU0, 0.5 * kU0);
  const Vec2 b(2.0 * kU0, 1.0 * kU0);
  const std::vector<TangentCase> cases = {
      {"loading, one step", plain, {}, Vec2(0.3 * kU0, 0.1 * kU0), 0.0},
      {"loading, many sub-steps", plain, {}, Vec2(2.013 * kU0, -1.3 * kU0), 0.0},
      {"unloading", plain, {a, b}, Vec2(1.2 * kU0, 0.9 * kU0), 0.0},
      {"near zero increment", plain, {a, b}, b + Vec2(1e-4 * kU0, -0.5e-4 * kU0), 0.0},
      {"all terms, loading", full, {a}, Vec2(2.7 * kU0, 1.1 * kU0), 0.01},
      {"all terms, unloading", full, {a, b}, Vec2(0.4 * kU0, -0.3 * kU0), 0.02},
      {"all terms, near zero increment", full, {a, b}, b + Vec2(-0.7e-4 * kU0, 1e-4 * kU0), 0.01},
      {"all terms, static Maxwell", full, {a, b}, Vec2(1.1 * kU0, 1.9 * kU0), 0.0},
      {"back force clipped",
       [&] {
         Params q = full;
         q.alpha0 = 0.1;
         return q;
       }(),
       {a, b},
       Vec2(3.1 * kU0, 0.2 * kU0),
       0.01},
      {"n < 1, loading",
       [&] {
         Params q = full;
         q.n = 0.4;
         return q;
       }(),
       {a},
       Vec2(2.7 * kU0, 1.1 * kU0),
       0.01},
      {"n < 1, unloading",
       [&] {
         Params q = full;
         q.n = 0.4;
         return q;
       }(),
       {a, b},
       Vec2(0.4 * kU0, -0.3 * kU0),
       0.02},
      // n = 1 is solved in closed form rather than by the local Newton iteration.
      {"n = 1, loading",
       [&] {
         Params q = full;
         q.n = 1.0;
         return q;
       }(),
       {a},
       Vec2(2.7 * kU0, 1.1 * kU0),
       0.01},
      {"n = 1, unloading",
       [&] {
         Params q = full;
         q.n = 1.0;
         return q;
       }(),
       {a, b},
       Vec2(0.4 * kU0, -0.3 * kU0),
       0.02},
  };
  for (const auto& c : cases) {
    YoshidaBearingMaterial m(1, c.p);
    for (const Vec2& u : c.history) drive(m, u, c.dt);
    ASSERT_TRUE(ok(m.setTrialStrain(c.trial, Vec2::Zero(), c.dt)));
    const Mat2 k = m.getTangent();
    const double h = 1e-7 * kU0;
    const Mat2 kfd = fdTangent(m, c.trial, Vec2::Zero(), c.dt, h);
    EXPECT_LT(relDiff(k, kfd), kFdRelTol) << c.name << "\nanalytic\n" << k << "\nFD\n" << kfd;
  }
}

TEST(YoshidaBearingMaterialTest, ZeroIncrementTangentFollowsDefinedDirection) {
  Params p = basic(2.0);
  p.maxSubIncrement = 0.05;
  YoshidaBearingMaterial m(1, p);
  drive(m, Vec2(1.0 * kU0, 0.4 * kU0));
  const Vec2 u = m.getStrain();
  const double h = 1e-8 * kU0;
  for (const Vec2& rate : {Vec2(0.3, 0.7), Vec2(-1.0, 0.2)}) {
    ASSERT_TRUE(ok(m.setTrialStrain(u, rate, 0.0)));
    const Vec2 e = rate.normalized();
    const Vec2 kTimesE = m.getTangent() * e;
    ASSERT_TRUE(ok(m.setTrialStrain(u + h * e, rate, 0.0)));
    const Vec2 f1 = m.getStress();
    ASSERT_TRUE(ok(m.setTrialStrain(u, rate, 0.0)));
    const Vec2 oneSided = (f1 - m.getStress()) / h;  // derivative for motion along e
    EXPECT_LT((kTimesE - oneSided).norm() / oneSided.norm(), 1e-5) << rate.transpose();
  }
  // Without a rate: continued loading along the committed z.
  ASSERT_TRUE(ok(m.setTrialStrain(u, Vec2::Zero(), 0.0)));
  const Vec2 e = m.trialState().z.normalized();
  const Vec2 kTimesE = m.getTangent() * e;
  ASSERT_TRUE(ok(m.setTrialStrain(u + h * e, Vec2::Zero(), 0.0)));
  const Vec2 f1 = m.getStress();
  ASSERT_TRUE(ok(m.setTrialStrain(u, Vec2::Zero(), 0.0)));
  EXPECT_LT((kTimesE - (f1 - m.getStress()) / h).norm() / kTimesE.norm(), 1e-5);
}

TEST(YoshidaBearingMaterialTest, TrialIsIdempotentAndRevertRestores) {
  Params p = basic(2.0);
  p.alpha0 = 0.3;
  p.beta = 0.1;
  p.k = 1000.0;
  p.eta = 100.0;
  YoshidaBearingMaterial m(1, p);
  drive(m, Vec2(0.01, 0.004), 0.01);
  ASSERT_TRUE(ok(m.setTrialStrain(Vec2(0.03, -0.01), Vec2::Zero(), 0.01)));
  ASSERT_TRUE(ok(m.setTrialStrain(Vec2(0.015, 0.02), Vec2::Zero(), 0.01)));
  const Vec2 f12 = m.getStress();
  const Mat2 k12 = m.getTangent();
  auto copy = m.clone();
  m.revertToLastCommit();
  EXPECT_EQ(m.getStrain(), Vec2(0.01, 0.004));
  ASSERT_TRUE(ok(m.setTrialStrain(Vec2(0.015, 0.02), Vec2::Zero(), 0.01)));
  EXPECT_EQ(m.getStress(), f12);
  EXPECT_EQ(m.getTangent(), k12);
  EXPECT_EQ(copy->getStress(), f12);  // the clone kept the trial state
  m.revertToStart();
  EXPECT_EQ(m.getStress(), Vec2::Zero());
  EXPECT_EQ(m.getTangent(), m.getInitialTangent());
  EXPECT_EQ(copy->getStress(), f12);  // and is independent of the original
  EXPECT_EQ(m.getInitialTangent()(0, 0), kY0 / kU0 + 1000.0);
}

// A trial that is reverted leaves no trace: the same committed history gives the same bits
// whatever trials came between (the back-force factor's (Umax/U0)^q is cached by its argument,
// and a trial far out sets a larger Umax than the committed one).
TEST(YoshidaBearingMaterialTest, RevertedTrialsLeaveNoTrace) {
  Params p = basic(2.0);
  p.alpha0 = 0.4, p.beta = 0.05, p.q = 0.7, p.maxSubIncrement = 0.05;  // a decaying back force
  YoshidaBearingMaterial plain(1, p), probed(2, p);
  for (int i = 1; i <= 60; ++i) {
    const double t = 2 * kPi * i / 60;
    const Vec2 u = 3.0 * kU0 * std::min(1.0, i / 20.0) * Vec2(std::sin(t), std::sin(2 * t));
    ASSERT_TRUE(ok(probed.setTrialStrain(u * (1.5 + 0.01 * i), Vec2::Zero(), 0.0)));
    probed.revertToLastCommit();
    drive(plain, u);
    drive(probed, u);
    ASSERT_EQ(probed.getStress(), plain.getStress()) << "point " << i;
    ASSERT_EQ(probed.getTangent(), plain.getTangent()) << "point " << i;
  }
}

/// Forces along a Lissajous path (1.5 figure-eights of amplitude 4 U0, 240 points) integrated
/// with sub-steps of at most `subIncrement` U0.
void lissajousForces(double subIncrement, std::vector<Vec2>& out) {
  Params p = basic(2.0);
  p.alpha0 = 0.4;
  p.beta = 0.05;
  p.gamma = 0.02;
  p.maxSubIncrement = subIncrement;
  YoshidaBearingMaterial m(1, p);
  const int points = 240;
  out.clear();
  for (int i = 1; i <= points; ++i) {
    const double t = 2 * kPi * i / points * 1.5;
    drive(m, 4.0 * kU0 * Vec2(std::sin(t), std::sin(2 * t)));
    out.push_back(m.getStress());
  }
}

TEST(YoshidaBearingMaterialTest, StepSizeStudyShowsFirstOrder) {
  std::vector<Vec2> ref, f;
  lissajousForces(1e-4, ref);
  std::vector<double> err;
  const std::vector<double> steps = {0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625};
  for (double h : steps) {
    lissajousForces(h, f);
    double e = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) e = std::max(e, (f[i] - ref[i]).norm() / kY0);
    err.push_back(e);
    RecordProperty("error_at_" + std::to_string(h), std::to_string(e));
    std::printf("sub-step %g U0: max force error %.3e Y0\n", h, e);
  }
  // Observed order: least-squares slope of log(error) against log(sub-step).
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double np = static_cast<double>(steps.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double x = std::log(steps[i]), y = std::log(err[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double order = (np * sxy - sx * sy) / (np * sxx - sx * sx);
  EXPECT_GT(order, 0.85);  // backward Euler is first order
  EXPECT_LT(order, 1.15);
  // Accuracy claim for the default sub-step (0.02 U0): force error below 1 % of Y0.
  lissajousForces(Params{}.maxSubIncrement, f);
  double eDefault = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i)
    eDefault = std::max(eDefault, (f[i] - ref[i]).norm() / kY0);
  EXPECT_LT(eDefault, 0.01);
}

TEST(YoshidaBearingMaterialTest, ValidateRejectsBadInput) {
  struct Bad {
    const char* field;
    void (*edit)(Params&);
  };
  const Bad bad[] = {
      {"Y0", [](Params& p) { p.Y0 = 0.0; }},
      {"Y0", [](Params& p) { p.Y0 = NAN; }},
      {"U0", [](Params& p) { p.U0 = -1.0; }},
      {"n", [](Params& p) { p.n = 0.0; }},
      {"n", [](Params& p) { p.n = -0.5; }},
      {"alpha0", [](Params& p) { p.alpha0 = -0.1; }},
      {"beta", [](Params& p) { p.beta = -1.0; }},
      {"q", [](Params& p) { p.q = 0.0; }},
      {"gamma", [](Params& p) { p.gamma = -0.01; }},
      {"k", [](Params& p) { p.k = -5.0; }},
      {"eta", [](Params& p) { p.eta = -5.0; }},
      {"eta", [](Params& p) { p.k = 5.0; }},
      {"eta", [](Params& p) { p.eta = 5.0; }},
      {"subIncrement", [](Params& p) { p.maxSubIncrement = 0.0; }},
      {"U0", [](Params& p) { p.U0 = INFINITY; }},
  };
  EXPECT_NO_THROW(basic(2.0).validate());
  for (const Bad& b : bad) {
    Params p = basic(2.0);
    b.edit(p);
    try {
      p.validate();
      ADD_FAILURE() << "accepted bad " << b.field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), b.field);
    }
  }
}

TEST(YoshidaBearingMaterialTest, NonFiniteTrialIsReported) {
  YoshidaBearingMaterial m(1, basic(2.0));
  EXPECT_EQ(m.setTrialStrain(Vec2(NAN, 0.0), Vec2::Zero(), 0.0), Status::NonFinite);
}

}  // namespace
}  // namespace dabs::materials
