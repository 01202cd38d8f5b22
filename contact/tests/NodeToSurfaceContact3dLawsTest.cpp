// SPDX-License-Identifier: MIT
// NodeToSurfaceContact3d with each impact law (NormalLaw), apart from the Kelvin-law cases of
// NodeToSurfaceContact3dTest.cpp: exact tangents against central differences while approaching and
// separating, friction stick and slip with the law's normal
// force, and the release step's energy.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <algorithm>

#include "contact/NodeToSurfaceContact3d.h"
#include "elements/tests/ElementChecks.h"

namespace dabs::contact {
namespace {

using elements::testing::numericalDamping;
using elements::testing::numericalStiffness;
using elements::testing::relativeDifference;
using elements::testing::TrialState;

constexpr double kFdTol = 1e-6;   // analytic vs central-difference tangent (relative)
constexpr double kFdStep = 1e-7;  // FD perturbation (length, or velocity)
constexpr double kTol = 1e-9;     // closed forms, relative
constexpr double kK = 1e5;        // k_h (force/length^n) or K; also Kt (force/length)

NodeToSurfaceParams lawParams(ImpactLaw law, double mu = 0.0) {
  NodeToSurfaceParams p;
  p.law = law;
  p.K = kK;
  p.Kt = kK;
  p.muS = p.muK = mu;
  if (law == ImpactLaw::HertzDamp) {
    p.e = 0.6;
    p.v0 = 0.3;
    p.n = 1.3;
  }
  if (law == ImpactLaw::Jankowski || law == ImpactLaw::Kelvin) {
    p.e = 0.6;
    p.M1 = 3.0;
    p.M2 = 5.0;
  }
  p.validate();
  return p;
}

template <int Ndf = 3>
std::unique_ptr<NodeToSurfaceContact3d<Ndf>> make(const NodeToSurfaceParams& p) {
  auto e = std::make_unique<NodeToSurfaceContact3d<Ndf>>(1, 10, std::array<int, 4>{1, 2, 3, 4}, p);
  // Target quad a(0,0,0) b(2,0,0) c(2,2,0) d(0,2,0): n = +z; contactor above it at z = 0.1.
  e->initialize({Eigen::Vector3d(0.5, 0.8, 0.1), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                 Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(0, 2, 0)});
  return e;
}

TrialState zeroState(int n) {
  TrialState s;
  s.u = Eigen::VectorXd::Zero(n);
  s.v = Eigen::VectorXd::Zero(n);
  s.a = Eigen::VectorXd::Zero(n);
  return s;
}

// A warped, moved target and a contactor penetrating by about 0.03 with a normal rate `vz`
// (< 0 approaching) on top of small velocities of every node.
TrialState general(double vz, double tangential = 0.0) {
  TrialState s = zeroState(15);
  const double u[5][3] = {{0.003 + tangential, -0.002 + 0.5 * tangential, -0.13},
                          {0.01, -0.02, 0.005},
                          {0.02, 0.01, -0.01},
                          {-0.01, 0.015, 0.02},
                          {0.005, 0.0, -0.005}};
  for (int j = 0; j < 5; ++j)
    for (int d = 0; d < 3; ++d) {
      s.u(3 * j + d) = u[j][d];
      s.v(3 * j + d) = 0.01 * (j + 1) * (d - 1);
    }
  s.v(2) += vz;
  return s;
}

void checkTangents(ImpactLaw law, double vz, double mu, double tangential) {
  auto e = make(lawParams(law, mu));
  ASSERT_TRUE(ok(e->update(general(0.0).kinematics())));
  e->commitState();
  const TrialState s = general(vz, tangential);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_GT(e->trialState().force(0), 0.0);
  const Eigen::MatrixXd k = e->tangentStiff();
  const Eigen::MatrixXd c = e->dampingTangent();
  EXPECT_LT(relativeDifference(k, numericalStiffness(*e, s, kFdStep)), kFdTol)
      << NormalLaw::name(law) << " vz " << vz;
  EXPECT_LT(relativeDifference(c, numericalDamping(*e, s, kFdStep)), kFdTol)
      << NormalLaw::name(law) << " vz " << vz;
}

TEST(NodeToSurfaceContact3dTest, LawTangentsMatchFiniteDifferencesApproachingAndSeparating) {
  for (ImpactLaw law : {ImpactLaw::Hertz, ImpactLaw::HertzDamp, ImpactLaw::Jankowski})
    for (double vz : {-0.2, 0.0, 0.05}) {
      checkTangents(law, vz, 0.0, 0.0);     // frictionless
      checkTangents(law, vz, 0.5, 0.0005);  // stick
      checkTangents(law, vz, 0.5, 0.05);    // slide
    }
}

TEST(NodeToSurfaceContact3dTest, LawDampingTermDependsOnThePenetration) {
  // hertzdamp c_h delta^n deltadot and jankowski c delta^(1/4) deltadot: while approaching the
  // stiffness tangent differs from the spring's alone, d(k delta^n)/d delta.
  for (ImpactLaw law : {ImpactLaw::HertzDamp, ImpactLaw::Jankowski}) {
    auto still = make(lawParams(law));
    auto moving = make(lawParams(law));
    TrialState s0 = zeroState(15), s1 = zeroState(15);
    s0.u(2) = s1.u(2) = -0.13;  // delta = 0.03
    s1.v(2) = -0.2;             // approaching at 0.2
    ASSERT_TRUE(ok(still->update(s0.kinematics())));
    ASSERT_TRUE(ok(moving->update(s1.kinematics())));
    const double delta = 0.03, rate = 0.2;
    const NormalLaw nl(NormalLaw::Params{kK, 0.6, 3.0, 5.0, law, lawParams(law).n, 0.3});
    const double n = nl.exponent();
    // dN/d delta of the damping term (the contactor's own z row: f_z = -N, u_z = -delta).
    const double dDamp = law == ImpactLaw::HertzDamp
                             ? nl.damping() * n * std::pow(delta, n - 1) * rate
                             : nl.damping() * 0.25 * std::pow(delta, -0.75) * rate;
    EXPECT_NEAR(still->tangentStiff()(2, 2), kK * n * std::pow(delta, n - 1),
                kTol * kK * std::pow(delta, n - 1));
    EXPECT_NEAR(moving->tangentStiff()(2, 2) - still->tangentStiff()(2, 2), dDamp,
                1e-9 * std::abs(dDamp));
    EXPECT_GT(dDamp, 0.0);
    EXPECT_TRUE(moving->hasNonSymmetricTangent());
  }
  EXPECT_FALSE(make(lawParams(ImpactLaw::Hertz))->hasNonSymmetricTangent());
}

TEST(NodeToSurfaceContact3dTest, LawJankowskiDampsOnlyWhileApproaching) {
  auto e = make(lawParams(ImpactLaw::Jankowski));
  TrialState s = zeroState(15);
  s.u(2) = -0.13;
  s.v(2) = 0.2;  // separating: the spring alone
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), kK * std::pow(0.03, 1.5), kTol * kK);
  EXPECT_EQ(Eigen::MatrixXd(e->dampingTangent()).norm(), 0.0);
}

TEST(NodeToSurfaceContact3dTest, LawFrictionSticksAndSlidesOnTheLawsNormalForce) {
  for (ImpactLaw law : {ImpactLaw::Hertz, ImpactLaw::HertzDamp, ImpactLaw::Jankowski}) {
    auto e = make(lawParams(law, 0.5));
    TrialState s = zeroState(15);
    s.u(2) = -0.15;  // delta = 0.05, at rest: N = k delta^n
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->commitState();
    const double n = law == ImpactLaw::HertzDamp ? 1.3 : 1.5;
    const double N = kK * std::pow(0.05, n);
    EXPECT_NEAR(e->trialState().force(0), N, kTol * N);
    s.u(0) = 1e-4;  // stick: Kt times the slip, below 0.5 N
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->trialState().status, ContactStatus::Stick);
    EXPECT_NEAR(e->trialState().force(1), -kK * 1e-4, kTol * kK);
    s.u(0) = 0.1;  // slide: on the cone
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->trialState().status, ContactStatus::Slide);
    EXPECT_NEAR(e->trialState().force(1), -0.5 * N, kTol * N);
    EXPECT_GT(e->trialState().frictionEnergy, 0.0);
  }
}

TEST(NodeToSurfaceContact3dTest, LawReleaseStepForceGivesBackOnlyTheStoredEnergy) {
  for (ImpactLaw law : {ImpactLaw::Hertz, ImpactLaw::HertzDamp, ImpactLaw::Jankowski}) {
    auto e = make(lawParams(law));
    TrialState s = zeroState(15);
    s.u(2) = -0.15;  // delta_n = 0.05 at rest: N_n = k delta_n^n
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->commitState();
    const double n = law == ImpactLaw::HertzDamp ? 1.3 : 1.5;
    const double dn = 0.05, Nn = kK * std::pow(dn, n);
    const double stored = kK * std::pow(dn, n + 1) / (n + 1);  // int_0^dn k x^n dx
    s.u(2) = -0.08;                                            // g = +0.02: released in the step
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    const double N = e->trialState().force(0);
    // Trapezoid work over the step, as Newmark's average acceleration integrates it.
    EXPECT_NEAR(0.5 * (Nn + N) * (dn + 0.02), stored, kTol * Nn * dn) << NormalLaw::name(law);
    EXPECT_LT(N, 0.0);
    EXPECT_EQ(e->trialState().status, ContactStatus::Open);
    EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
    e->commitState();
    s.u(2) = -0.07;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->resistingForce().norm(), 0.0);
  }
}

TEST(NodeToSurfaceContact3dTest, LawReleaseEndStateInTheJumpIsHeldOnTheRamp) {
  // A release step whose held release force converges just inside the face, with a tension
  // between 0 and tail: the end state in the jump (NormalLaw::releaseForce), which agrees; deeper
  // inside, where the ramp pushes, the state is closed and the branch switches.
  for (ImpactLaw law : {ImpactLaw::Hertz, ImpactLaw::HertzDamp, ImpactLaw::Jankowski}) {
    const double n = law == ImpactLaw::HertzDamp ? 1.3 : 1.5;
    const double dn = 0.05, Nn = kK * std::pow(dn, n), tail = Nn * (n - 1) / (n + 1);
    const double w = NormalLaw::kRampWidth * dn;
    for (double g : {-0.5 * w, -3.0 * w}) {
      auto e = make(lawParams(law));
      TrialState s = zeroState(15);
      s.u(2) = -0.15;  // delta_n = 0.05 at rest
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      e->commitState();
      s.u(2) = -0.08;  // g = +0.02: the release force
      s.v(2) = 1.0;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      e->holdStatus();
      s.u(2) = -0.1 + g;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      EXPECT_NEAR(e->trialState().force(0), -tail * (1.0 + g / w), kTol * Nn)
          << NormalLaw::name(law);
      EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
      if (g > -w) {
        EXPECT_EQ(e->trialState().status, ContactStatus::Open);
        EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Agrees);
      } else {
        EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Switched);
      }
    }
  }
}

TEST(NodeToSurfaceContact3dTest, LawAsksNewtonForTheStepOnItsForce) {
  // Updates on the closed law that shrink the penetration from 0.01 to 0.004 to 0.0015: the
  // second of two such halvings running asks for NormalLaw::forceVariableStepScale of its
  // change; kelvin asks for nothing, nor does a small change, the first halving, or a pair
  // whose last update was open.
  for (ImpactLaw law : {ImpactLaw::Kelvin, ImpactLaw::Hertz, ImpactLaw::Jankowski}) {
    const NodeToSurfaceParams p = lawParams(law);
    auto e = make(p);
    EXPECT_EQ(e->scalesNewtonSteps(), law != ImpactLaw::Kelvin);
    TrialState s = zeroState(15);
    s.u(2) = -0.05;  // g = +0.05: open
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->commitState();
    s.v(2) = -1.0;
    s.u(2) = -0.11;  // delta = 0.01, after an open update: no step taken on the closed law
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->newtonStepScale(), 1.0);
    s.u(2) = -0.104;  // delta 0.004: the first halving
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->newtonStepScale(), 1.0);
    s.u(2) = -0.1015;  // delta 0.0015: the second
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    // Newton on w = delta^1.5 from 0.004 with the step in w 1.5 sqrt(0.004) (-0.0025): the
    // penetration (w + dw)^(2/3), reached by scale x (-0.0025) from 0.004.
    const double w = std::pow(0.004, 1.5), dw = 1.5 * std::sqrt(0.004) * -0.0025;
    const double expected = (std::pow(w + dw, 1.0 / 1.5) - 0.004) / -0.0025;
    EXPECT_NEAR(e->newtonStepScale(), law == ImpactLaw::Kelvin ? 1.0 : expected, 1e-9)
        << NormalLaw::name(law);
    s.u(2) = -0.1014;  // delta 0.0014: a fifteenth of it removed, no opinion
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->newtonStepScale(), 1.0);
  }
}

TEST(NodeToSurfaceContact3dTest, LawHeldClosedBranchEvaluatesTheLawUnclipped) {
  // Held in contact, a trial that opens the gap still gets the law's force (odd extension: a
  // pull of k g^n), smooth for Newton on the held equations.
  auto e = make(lawParams(ImpactLaw::Hertz));
  TrialState s = zeroState(15);
  s.u(2) = -0.13;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->holdStatus();
  s.u(2) = -0.09;  // g = +0.01
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), -kK * std::pow(0.01, 1.5), kTol * kK);
  EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Switched);
}

TEST(NodeToSurfaceContact3dTest, LawClosedAndOpenCyclingHoldsTheLawsSpringAlone) {
  // A step much longer than the impact: held closed, the end state lies outside the face; held
  // open, inside it. hertzdamp and jankowski have a rate term, so the cycle holds the law's
  // spring alone, k delta^n (no damping), while the pair penetrates and approaches.
  for (ImpactLaw law : {ImpactLaw::HertzDamp, ImpactLaw::Jankowski}) {
    auto e = make(lawParams(law));
    const double n = law == ImpactLaw::HertzDamp ? 1.3 : 1.5;
    TrialState s = zeroState(15);
    s.u(2) = -0.1001;  // g = -1e-4
    s.v(2) = -1.0;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->holdStatus();   // closed
    s.u(2) = -0.0999;  // g = +1e-4, still approaching
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Switched)
        << NormalLaw::name(law);
    s.u(2) = -0.1001;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->resistingForce().norm(), 0.0);                                // held open
    EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Switched);  // the cycle
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_NEAR(e->trialState().force(0), kK * std::pow(1e-4, n), kTol * kK * std::pow(1e-4, n))
        << NormalLaw::name(law);
    EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
    EXPECT_EQ(e->dampingTangent()(2, 2), 0.0);  // no rate term in the spring branch
    EXPECT_EQ(e->checkHeldStatus(), elements::Element::HeldStatus::Agrees);
  }
}

// Duration of an undamped impact m x'' = -k x^n from touch at speed v to separation, by RK4 with
// 20000 steps over an estimate of it (an independent calculation of contactDuration).
double integratedContactDuration(double m, double k, double n, double v) {
  const double h =
      4.0 * std::pow(m / k, 1.0 / (n + 1.0)) * std::pow(v, (1.0 - n) / (n + 1.0)) / 20000.0;
  auto acc = [&](double x) { return -k * std::pow(std::max(x, 0.0), n) / m; };
  double x = 0.0, xd = v, t = 0.0;
  for (int i = 0; i < 1000000; ++i) {
    const double a1 = acc(x), x2 = x + 0.5 * h * xd, v2 = xd + 0.5 * h * a1;
    const double a2 = acc(x2), x3 = x + 0.5 * h * v2, v3 = xd + 0.5 * h * a2;
    const double a3 = acc(x3), x4 = x + h * v3, v4 = xd + h * a3;
    const double a4 = acc(x4);
    const double xn = x + h / 6.0 * (xd + 2.0 * v2 + 2.0 * v3 + v4);
    const double vn = xd + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    if (xn < 0.0) return t + h * x / (x - xn);  // back through the touch point
    x = xn;
    xd = vn;
    t += h;
  }
  return -1.0;
}

TEST(NodeToSurfaceContact3dTest, LawContactDurationFollowsTheImpactSpeed) {
  // -masses 3 and 5: m = 15/8. Kelvin: pi sqrt(m/K) whatever the rate. Power laws: the duration
  // of the undamped impact at the speed the gap rate and the penetration give (energy), checked
  // against an RK4 integration; a pair at rest, open, bounds nothing.
  const double m = 3.0 * 5.0 / 8.0;
  auto kelvin = make(lawParams(ImpactLaw::Kelvin));
  EXPECT_NEAR(kelvin->contactDuration({}, -2.0), std::numbers::pi * std::sqrt(m / kK), 1e-12);
  for (ImpactLaw law : {ImpactLaw::Hertz, ImpactLaw::Jankowski}) {
    NodeToSurfaceParams p = lawParams(law);
    p.M1 = 3.0;
    p.M2 = 5.0;
    auto e = make(p);
    EXPECT_TRUE(std::isinf(e->contactDuration({}, 0.0)));  // open, still: no contact to resolve
    for (double v : {0.1, 1.0, 3.0}) {
      const double expected = integratedContactDuration(m, kK, 1.5, v);
      EXPECT_NEAR(e->contactDuration({}, -v), expected, 1e-6 * expected)
          << NormalLaw::name(law) << " v " << v;
    }
    // In contact: penetration 0.03 and a rate; the same energy as a touch at speed w.
    TrialState s = zeroState(15);
    s.u(2) = -0.13;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->commitState();
    const double delta = -e->committedGap();
    ASSERT_GT(delta, 0.0);
    const double rate = 0.4;
    const double w = std::sqrt(rate * rate + 2.0 * kK * std::pow(delta, 2.5) / (2.5 * m));
    const double expected = integratedContactDuration(m, kK, 1.5, w);
    EXPECT_NEAR(e->contactDuration({}, rate), expected, 1e-6 * expected) << NormalLaw::name(law);
  }
  // hertzdamp with its own exponent 1.3, masses from the nodes (contactor 2, face 4 x 1.5 = 6)
  auto hd = make(lawParams(ImpactLaw::HertzDamp));
  const double nodes[5] = {2.0, 1.5, 1.5, 1.5, 1.5};
  const double expected = integratedContactDuration(1.5, kK, 1.3, 0.7);
  EXPECT_NEAR(hd->contactDuration(nodes, -0.7), expected, 1e-6 * expected);
}

TEST(NodeToSurfaceContact3dTest, LawDescribeNamesTheLaw) {
  EXPECT_NE(
      make(lawParams(ImpactLaw::HertzDamp))->describe().find("law hertzdamp K 100000 n 1.3 v0 0.3"),
      std::string::npos);
  EXPECT_NE(make(lawParams(ImpactLaw::Kelvin))->describe().find("law kelvin K 100000"),
            std::string::npos);
}

}  // namespace
}  // namespace dabs::contact
