// SPDX-License-Identifier: MIT
// Over 400 lines: one test file for the contact element, each test a separate case of its
// behaviour (closed forms, FD tangents in every state, sleeping pairs, small impacts).
// Element-level checks of the node-to-surface contact (the hard cases that need no driver):
// closed forms for open/penetration/stick/slide, return-map memory and revert, FD tangents in
// every state, corners, edges, sliding off, nodal equilibrium, search distance, and small
// integrations for the head-on and oblique impacts and the block on a plane.
#include "contact/NodeToSurfaceContact3d.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include "elements/tests/ElementChecks.h"
#include "materials/InputError.h"

namespace dabs::contact {
namespace {

using elements::NodalCoordinates;
using elements::testing::numericalDamping;
using elements::testing::numericalStiffness;
using elements::testing::relativeDifference;
using elements::testing::TrialState;

constexpr double kTol = 1e-9;     // closed forms (relative to the force scale where noted)
constexpr double kFdTol = 1e-6;   // analytic vs central-difference tangent (relative)
constexpr double kFdStep = 1e-7;  // perturbation for the FD tangent (length)
constexpr double kK = 1e5;

// Target quad a(0,0,0) b(2,0,0) c(2,2,0) d(0,2,0): n = +z, t1 = +x, t2 = +y.
NodalCoordinates coords(const Eigen::Vector3d& k) {
  return {k, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(2, 2, 0),
          Eigen::Vector3d(0, 2, 0)};
}

NodeToSurfaceParams params(double muS = 0.0, double muK = 0.0) {
  NodeToSurfaceParams p;
  p.K = kK;
  p.muS = muS;
  p.muK = muK;
  p.validate();
  return p;
}

template <int Ndf = 3>
std::unique_ptr<NodeToSurfaceContact3d<Ndf>> make(const NodeToSurfaceParams& p,
                                                  const Eigen::Vector3d& k = {0.5, 0.8, 0.1}) {
  auto e = std::make_unique<NodeToSurfaceContact3d<Ndf>>(1, 10, std::array<int, 4>{1, 2, 3, 4}, p);
  e->initialize(coords(k));
  return e;
}

TrialState zeroState(int n) {
  TrialState s;
  s.u = Eigen::VectorXd::Zero(n);
  s.v = Eigen::VectorXd::Zero(n);
  s.a = Eigen::VectorXd::Zero(n);
  return s;
}

template <int Ndf = 3>
void setU(TrialState& s, int node, const Eigen::Vector3d& u) {
  s.u.segment<3>(node * Ndf) = u;
}

Eigen::Vector3d nodeForce(const elements::Element& e, int node, int ndf = 3) {
  return e.resistingForce().segment<3>(node * ndf);
}

TEST(NodeToSurfaceContact3dTest, OpenGapGivesZeroForceAndStiffness) {
  auto e = make(params(0.5, 0.4));
  TrialState s = zeroState(15);
  setU(s, 0, {0.3, -0.2, -0.05});  // still 0.05 above the surface
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->tangentStiff().norm(), 0.0);
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_NEAR(e->trialState().gap, 0.05, kTol);
  EXPECT_EQ(numericalStiffness(*e, s, kFdStep).norm(), 0.0);
}

TEST(NodeToSurfaceContact3dTest, PenetrationGivesKTimesGapDistributedByShapeFunctions) {
  auto e = make(params());
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -0.15});  // gap 0.1 - 0.15 = -0.05
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const double N = kK * 0.05;
  EXPECT_NEAR(e->trialState().gap, -0.05, kTol);
  EXPECT_NEAR((nodeForce(*e, 0) - Eigen::Vector3d(0, 0, -N)).norm(), 0.0, kTol * N);
  // Projection (0.5, 0.8) is xi = -0.5, eta = -0.2: N_a..N_d = 0.45, 0.15, 0.10, 0.30.
  const double shape[4] = {0.45, 0.15, 0.10, 0.30};
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR((nodeForce(*e, i + 1) - Eigen::Vector3d(0, 0, shape[i] * N)).norm(), 0.0, kTol * N);
  const auto cf = e->response(std::vector<std::string>{"contactForce"});
  ASSERT_TRUE(cf.has_value());
  EXPECT_NEAR((*cf - Eigen::Vector3d(N, 0, 0)).norm(), 0.0, kTol * N);
  // Normal stiffness K between the contactor and the projected point.
  EXPECT_NEAR(e->tangentStiff()(2, 2), kK, kTol * kK);
  EXPECT_NEAR(e->tangentStiff()(2, 3 + 2), -0.45 * kK, kTol * kK);
}

// Commits a penetrated state with no tangential motion, then returns the trial state.
TrialState penetrated(elements::Element& e, double depth = 0.15) {
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -depth});
  EXPECT_TRUE(ok(e.update(s.kinematics())));
  e.commitState();
  return s;
}

TEST(NodeToSurfaceContact3dTest, StickGivesKtTimesSlip) {
  auto e = make(params(0.5, 0.4));
  TrialState s = penetrated(*e);
  EXPECT_EQ(e->committedState().status, ContactStatus::Stick);
  s.u(0) = 0.001;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Stick);
  EXPECT_NEAR(e->trialState().force(1), -kK * 0.001, kTol * kK);
  EXPECT_NEAR(nodeForce(*e, 0)(0), kK * 0.001, kTol * kK);
}

TEST(NodeToSurfaceContact3dTest, SlipOnConeDissipatesAndKeepsStickPointOnTheLimit) {
  auto e = make(params(0.5, 0.4));
  TrialState s = penetrated(*e);
  const double N = kK * 0.05;
  s.u(0) = 0.1;  // trial Kt * 0.1 = 1e4 > mu_s N = 2500
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Slide);
  EXPECT_NEAR(e->trialState().force(1), -0.4 * N, kTol * N);  // |t| = mu_k N
  e->commitState();
  const double slip = 0.1 - 0.4 * N / kK;
  EXPECT_NEAR(e->committedState().slipLength, slip, kTol);
  EXPECT_NEAR(e->committedState().frictionEnergy, 0.4 * N * slip, kTol * N);
  EXPECT_GT(e->committedState().frictionEnergy, 0.0);
  // Moving back by 0.005 unloads the spring from the limit, not from zero (return map).
  s.u(0) = 0.095;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Stick);
  EXPECT_NEAR(e->trialState().force(1), -(0.4 * N - kK * 0.005), kTol * N);
}

TEST(NodeToSurfaceContact3dTest, RevertAfterTrialSlipRestoresStickPoint) {
  auto e = make(params(0.5, 0.4));
  TrialState s = penetrated(*e);
  const Eigen::Vector2d stick = e->committedState().stickXi;
  s.u(0) = 0.1;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NE(e->trialState().stickXi, stick);
  e->revertToLastCommit();
  EXPECT_EQ(e->trialState().stickXi, stick);
  s.u(0) = 0.001;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(1), -kK * 0.001, kTol * kK);
  EXPECT_EQ(e->trialState().slipLength, 0.0);
}

// A warped, tilted and moved target with a penetrating contactor and velocities.
template <int Ndf>
TrialState general(double tangential) {
  TrialState s = zeroState(5 * Ndf);
  setU<Ndf>(s, 1, {0.01, -0.02, 0.005});
  setU<Ndf>(s, 2, {0.02, 0.01, -0.01});
  setU<Ndf>(s, 3, {-0.01, 0.015, 0.02});
  setU<Ndf>(s, 4, {0.005, 0.0, -0.005});
  setU<Ndf>(s, 0, {0.003 + tangential, -0.002 + 0.5 * tangential, -0.13});
  for (int j = 0; j < 5; ++j)
    for (int d = 0; d < 3; ++d) s.v(j * Ndf + d) = 0.01 * (j + 1) * (d - 1);
  return s;
}

NodeToSurfaceParams dampedFriction() {
  NodeToSurfaceParams p = params(0.5, 0.4);
  p.e = 0.6;
  p.et = 0.7;
  p.M1 = 3.0;
  p.M2 = 5.0;
  p.validate();
  return p;
}

template <int Ndf>
void checkTangents(const NodeToSurfaceParams& p, double tangential, ContactStatus expected) {
  auto e = make<Ndf>(p);
  TrialState s0 = general<Ndf>(0.0);
  ASSERT_TRUE(ok(e->update(s0.kinematics())));
  e->commitState();
  TrialState s = general<Ndf>(tangential);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_EQ(e->trialState().status, expected);
  const Eigen::MatrixXd k = e->tangentStiff();
  const Eigen::MatrixXd c = e->dampingTangent();
  EXPECT_LT(relativeDifference(k, numericalStiffness(*e, s, kFdStep)), kFdTol);
  EXPECT_LT(relativeDifference(c, numericalDamping(*e, s, kFdStep)), kFdTol);
  EXPECT_GT(k.norm(), 0.0);
}

TEST(NodeToSurfaceContact3dTest, TangentMatchesFiniteDifferencesInStickAndSlide) {
  checkTangents<3>(dampedFriction(), 0.0005, ContactStatus::Stick);
  checkTangents<3>(dampedFriction(), 0.05, ContactStatus::Slide);
  checkTangents<6>(dampedFriction(), 0.0005, ContactStatus::Stick);
  checkTangents<6>(dampedFriction(), 0.05, ContactStatus::Slide);
  checkTangents<3>(params(), 0.05, ContactStatus::Slide);  // frictionless
}

TEST(NodeToSurfaceContact3dTest, SlideTangentIsNonSymmetricFrictionlessIsSymmetric) {
  auto e = make(params(0.5, 0.4));
  EXPECT_TRUE(e->hasNonSymmetricTangent());
  ASSERT_TRUE(ok(e->update(general<3>(0.0).kinematics())));
  e->commitState();
  ASSERT_TRUE(ok(e->update(general<3>(0.05).kinematics())));
  const Eigen::MatrixXd k = e->tangentStiff();
  EXPECT_GT((k - k.transpose()).norm(), 1e-3 * k.norm());
  // Frictionless and undamped: the force is the gradient of K g^2/2, so K is symmetric even on
  // a warped, tilted target.
  auto f = make(params());
  EXPECT_FALSE(f->hasNonSymmetricTangent());
  ASSERT_TRUE(ok(f->update(general<3>(0.05).kinematics())));
  const Eigen::MatrixXd kf = f->tangentStiff();
  EXPECT_LT((kf - kf.transpose()).norm(), 1e-10 * kf.norm());
  EXPECT_FALSE(f->rayleighByDefault());
}

TEST(NodeToSurfaceContact3dTest, NdfSixPutsNothingOnRotations) {
  auto e = make<6>(dampedFriction());
  TrialState s = general<6>(0.0);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->numDof(), 30);
  EXPECT_EQ(e->dofPerNode(), 6);
  for (int j = 0; j < 5; ++j) {
    EXPECT_EQ(e->resistingForce().segment<3>(j * 6 + 3).norm(), 0.0);
    EXPECT_EQ(e->tangentStiff().middleRows<3>(j * 6 + 3).norm(), 0.0);
    EXPECT_EQ(e->tangentStiff().middleCols<3>(j * 6 + 3).norm(), 0.0);
  }
  EXPECT_GT(e->resistingForce().norm(), 0.0);
}

TEST(NodeToSurfaceContact3dTest, OpenStateTangentIsZeroLikeItsFiniteDifference) {
  auto e = make(dampedFriction());
  TrialState s = zeroState(15);
  setU(s, 0, {0.1, 0.1, -0.09});
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_EQ(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), 0.0);
}

TEST(NodeToSurfaceContact3dTest, ReleaseStepForceGivesBackOnlyTheStoredEnergy) {
  auto e = make(params());
  TrialState s = penetrated(*e);  // delta_n = 0.05, N_n = K delta_n
  const double Nn = kK * 0.05;
  s.u(2) = -0.08;  // g = +0.02: released within the step
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  // N = -N_n g / (g - g_n): trapezoid work 0.5 (N_n + N)(g - g_n) = 0.5 N_n delta_n.
  const double N = -Nn * 0.02 / (0.02 + 0.05);
  EXPECT_NEAR(e->trialState().force(0), N, kTol * Nn);
  EXPECT_NEAR(0.5 * (Nn + N) * 0.07, 0.5 * Nn * 0.05, kTol * Nn);
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
  // The next step from the released state carries no force.
  e->commitState();
  s.u(2) = -0.07;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
}

// Held statuses (Element::HeldStatus): the branch of the normal law and of friction is that of
// the update at which the analysis held it, whatever the trial, until the converged state
// contradicts it or the step is committed or reverted.
using Held = elements::Element::HeldStatus;

TEST(NodeToSurfaceContact3dTest, HeldKelvinBranchPullsWhereTheStateWouldOpen) {
  auto e = make(dampedFriction());  // committed open, 0.1 above the face
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -0.11});  // g = -0.01
  s.v(2) = -1.0;              // approaching
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_GT(e->trialState().force(0), 0.0);
  e->holdStatus();
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
  // Lifted 0.02 above the face and separating: the state is open, the held Kelvin force pulls.
  setU(s, 0, {0, 0, -0.08});  // g = +0.02
  s.v(2) = 0.5;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const NormalLaw law({kK, 0.6, 3.0, 5.0});
  const double N = -kK * 0.02 - law.damping() * 0.5;
  EXPECT_NEAR(e->trialState().force(0), N, kTol * kK);
  EXPECT_NEAR(nodeForce(*e, 0).z(), -N, kTol * kK);
  EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
  EXPECT_LT(relativeDifference(e->dampingTangent(), numericalDamping(*e, s, kFdStep)), kFdTol);
  // The converged state contradicts it: the pair holds open, whose force is zero, and agrees.
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
}

// Closed at the last commit (g_n = -0.05, N_n = K 0.05), the held Kelvin branch separating so
// fast that its force pulls (K 0.01 - C v = -K 0.01): the contact ends in this step, and the
// release force is held before open. Inside the face the held release force goes on along its
// tangent at the face, N = N_n g / g_n; that state is open in turn (the Kelvin force would pull),
// and open agrees.
TEST(NodeToSurfaceContact3dTest, AClosedPairWhoseHeldContactWouldPullHoldsTheReleaseForceFirst) {
  auto e = make(dampedFriction());
  TrialState s = penetrated(*e);  // g_n = -0.05
  const double Nn = kK * 0.05;
  setU(s, 0, {0, 0, -0.11});  // g = -0.01
  s.v(2) = 0.1;               // separating slowly: the Kelvin force still compresses
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_GT(e->trialState().force(0), 0.0);
  e->holdStatus();
  const NormalLaw law({kK, 0.6, 3.0, 5.0});
  s.v(2) = 2.0 * kK * 0.01 / law.damping();  // the Kelvin force K 0.01 - C v = -K 0.01 pulls
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), -kK * 0.01, kTol * kK);
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // release, not open
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), Nn * -0.01 / -0.05, kTol * kK);
  EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // inside the face and pulling: open
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
}

// The case the release force is held first for: the end state lies outside the face, where the
// held release force, N = -N_n g / (g - g_n) (trapezoid work of the step = the stored energy),
// agrees at once.
TEST(NodeToSurfaceContact3dTest, AHeldReleaseForceOutsideTheFaceAgreesAfterTheHeldContactPulled) {
  auto e = make(dampedFriction());
  TrialState s = penetrated(*e);  // g_n = -0.05, N_n = K 0.05
  const double Nn = kK * 0.05;
  setU(s, 0, {0, 0, -0.11});  // g = -0.01, separating slowly: Kelvin compresses
  s.v(2) = 0.1;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->holdStatus();
  const NormalLaw law({kK, 0.6, 3.0, 5.0});
  s.v(2) = 2.0 * kK * 0.01 / law.damping();  // the Kelvin force pulls
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // release
  setU(s, 0, {0, 0, -0.09});                        // g = +0.01
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), -Nn * 0.01 / (0.01 + 0.05), kTol * kK);
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
}

TEST(NodeToSurfaceContact3dTest, HeldOpenBranchCarriesNothingWhilePenetrating) {
  auto e = make(params(0.5, 0.4));
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -0.05});  // still open
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->holdStatus();
  setU(s, 0, {0, 0, -0.12});  // g = -0.02
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // the state is closed: hold Kelvin
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), kK * 0.02, kTol * kK);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
}

TEST(NodeToSurfaceContact3dTest, OpenAndKelvinCyclingAtFirstTouchHoldsTheSpringAlone) {
  // At first touch the dashpot force jumps from 0 to C |gdot|: a state just inside the face
  // is closed with N >= C |gdot|, one just outside is open. When the held branch flips from
  // Kelvin to open and back the end state lies in the jump, and the spring alone (N = -K g,
  // between 0 and the Kelvin force while the pair approaches) is held.
  auto e = make(dampedFriction());
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -0.1001});  // g = -1e-4
  s.v(2) = -1.0;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->holdStatus();              // Kelvin
  setU(s, 0, {0, 0, -0.0999});  // g = +1e-4, still approaching
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // open
  setU(s, 0, {0, 0, -0.1001});
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // the cycle: the spring alone
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), kK * 1e-4, kTol * kK);
  EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
  EXPECT_LT(relativeDifference(e->dampingTangent(), numericalDamping(*e, s, kFdStep)), kFdTol);
  EXPECT_EQ(e->dampingTangent()(2, 2), 0.0);  // no normal dashpot in the spring branch
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
  // Separating, the spring branch no longer agrees (the Kelvin force is below it).
  s.v(2) = 1.0;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);
}

TEST(NodeToSurfaceContact3dTest, HeldStickAndSlideIgnoreTheConeAndAReversedSlideSticks) {
  auto e = make(params(0.5, 0.4));
  TrialState s = penetrated(*e);  // committed stick, N = K 0.05
  const double N = kK * 0.05;
  s.u(0) = 1e-5;  // inside the cone
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_EQ(e->trialState().status, ContactStatus::Stick);
  e->holdStatus();
  s.u(0) = 0.5;  // far outside the cone: the held stick force is the spring's
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Stick);
  EXPECT_NEAR(e->trialState().force(1), -kK * 0.5, kTol * kK);
  EXPECT_EQ(e->checkHeldStatus(), Held::Switched);  // slide
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(1), -0.4 * N, kTol * N);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
  // Held slide inside the cone (the direction kept): mu_k N, tangent exact.
  s.u(0) = 0.01;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Slide);
  EXPECT_NEAR(e->trialState().force(1), -0.4 * N, kTol * N);
  EXPECT_LT(relativeDifference(e->tangentStiff(), numericalStiffness(*e, s, kFdStep)), kFdTol);
  // The held slide reverses: it sticks (one way, within the iterations).
  s.u(0) = -1e-5;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Stick);
  EXPECT_NEAR(e->trialState().force(1), kK * 1e-5, kTol * kK);
  EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
}

TEST(NodeToSurfaceContact3dTest, CommitAndRevertReleaseTheHold) {
  for (const bool commit : {true, false}) {
    auto e = make(params(0.5, 0.4));
    TrialState s = zeroState(15);
    setU(s, 0, {0, 0, -0.05});
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->holdStatus();  // open
    if (commit)
      e->commitState();
    else
      e->revertToLastCommit();
    setU(s, 0, {0, 0, -0.12});
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_NEAR(e->trialState().force(0), kK * 0.02, kTol * kK) << commit;
    EXPECT_EQ(e->checkHeldStatus(), Held::Agrees);
  }
}

TEST(NodeToSurfaceContact3dTest, ContactAtCornerAndEdgeLoadsOnlyThoseNodes) {
  const double N = kK * 0.05;
  {
    auto e = make(params(), {2, 2, 0.1});  // above corner c
    penetrated(*e);
    EXPECT_NEAR((nodeForce(*e, 3) - Eigen::Vector3d(0, 0, N)).norm(), 0.0, kTol * N);
    for (int i : {1, 2, 4}) EXPECT_NEAR(nodeForce(*e, i).norm(), 0.0, kTol * N);
  }
  {
    auto e = make(params(), {2, 1, 0.1});  // above the midpoint of edge b-c
    penetrated(*e);
    EXPECT_NEAR((nodeForce(*e, 2) - Eigen::Vector3d(0, 0, 0.5 * N)).norm(), 0.0, kTol * N);
    EXPECT_NEAR((nodeForce(*e, 3) - Eigen::Vector3d(0, 0, 0.5 * N)).norm(), 0.0, kTol * N);
    for (int i : {1, 4}) EXPECT_NEAR(nodeForce(*e, i).norm(), 0.0, kTol * N);
  }
}

TEST(NodeToSurfaceContact3dTest, ContactorSlidingOffTheSurfaceLeavesContact) {
  auto e = make(params(0.3, 0.3), {1.9, 1, 0.1});
  TrialState s = penetrated(*e);
  EXPECT_GT(e->resistingForce().norm(), 0.0);
  s.u(0) = 0.05;  // x = 1.95: still on
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->commitState();
  EXPECT_EQ(e->committedState().status, ContactStatus::Slide);
  s.u(0) = 0.2;  // x = 2.1: past edge b-c
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->trialState().status, ContactStatus::Open);
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->tangentStiff().norm(), 0.0);
}

TEST(NodeToSurfaceContact3dTest, ContactorInTwoPairsOnASharedEdge) {
  // Faces A (x in [0,2]) and B (x in [2,4]) share the edge x = 2; one contactor in a pair with
  // each. On the shared edge both pairs act (each K delta, split half and half on the edge
  // nodes): the stiffness there is doubled, a known effect of node-to-surface pairs on adjacent
  // faces. Past the edge only face B carries the contactor.
  const Eigen::Vector3d k0(2, 1, 0.1);
  auto a = make(params(), k0);
  auto b =
      std::make_unique<NodeToSurfaceContact3d<3>>(2, 10, std::array<int, 4>{2, 5, 6, 3}, params());
  b->initialize({k0, Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(4, 0, 0), Eigen::Vector3d(4, 2, 0),
                 Eigen::Vector3d(2, 2, 0)});
  TrialState s = zeroState(15);
  setU(s, 0, {0, 0, -0.15});
  ASSERT_TRUE(ok(a->update(s.kinematics())));
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  const double N = kK * 0.05;
  EXPECT_NEAR(nodeForce(*a, 0).z() + nodeForce(*b, 0).z(), -2 * N, kTol * N);
  EXPECT_NEAR(nodeForce(*a, 2).z(), 0.5 * N, kTol * N);  // node b of face A = (2,0,0)
  EXPECT_NEAR(nodeForce(*b, 1).z(), 0.5 * N, kTol * N);  // node a of face B = (2,0,0)
  setU(s, 0, {0.5, 0, -0.15});                           // x = 2.5: on face B only
  ASSERT_TRUE(ok(a->update(s.kinematics())));
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  EXPECT_EQ(a->resistingForce().norm(), 0.0);
  EXPECT_NEAR(nodeForce(*b, 0).z(), -N, kTol * N);
}

Eigen::Vector3d moment(const elements::Element& e, const NodalCoordinates& X, const TrialState& s) {
  Eigen::Vector3d m = Eigen::Vector3d::Zero();
  for (int j = 0; j < 5; ++j)
    m += (X[j] + s.u.segment<3>(3 * j)).cross(e.resistingForce().segment<3>(3 * j));
  return m;
}

TEST(NodeToSurfaceContact3dTest, NodalForcesAreInEquilibrium) {
  // Frictionless on a flat target: sum and moment vanish.
  const Eigen::Vector3d k0(0.5, 0.8, 0.1);
  {
    auto e = make(params(), k0);
    TrialState s = zeroState(15);
    setU(s, 0, {0.2, 0.1, -0.15});
    for (int j = 1; j < 5; ++j) setU(s, j, {0.05, -0.03, 0.01});
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    const double scale = e->resistingForce().norm();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int j = 0; j < 5; ++j) sum += nodeForce(*e, j);
    EXPECT_LT(sum.norm(), kTol * scale);
    EXPECT_LT(moment(*e, coords(k0), s).norm(), kTol * scale);
  }
  // With friction on a warped target: the sum vanishes; the moment is the couple of the contact
  // force R across the penetration, -(x_k - x_p) x R, with x_p the projection point.
  {
    auto e = make(params(0.5, 0.4), k0);
    ASSERT_TRUE(ok(e->update(general<3>(0.0).kinematics())));
    e->commitState();
    const TrialState s = general<3>(0.0005);
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    ASSERT_EQ(e->trialState().status, ContactStatus::Stick);
    const double scale = e->resistingForce().norm();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int j = 0; j < 5; ++j) sum += nodeForce(*e, j);
    EXPECT_LT(sum.norm(), kTol * scale);
    const NodalCoordinates X = coords(k0);
    const Eigen::Vector2d xi = e->trialState().projXi;
    const auto N = shapeFunctions(xi.x(), xi.y());
    Eigen::Vector3d xp = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) xp += N[i] * (X[i + 1] + s.u.segment<3>(3 * (i + 1)));
    const Eigen::Vector3d xk = X[0] + s.u.segment<3>(0);
    EXPECT_NEAR((xk - xp).head<2>().norm(), 0.0, 1e-12);  // projection along n = z
    const Eigen::Vector3d R = -nodeForce(*e, 0);
    EXPECT_LT((moment(*e, X, s) + (xk - xp).cross(R)).norm(), kTol * scale);
    EXPECT_NEAR((xk - xp).z(), e->trialState().gap, 1e-12);
  }
}

TEST(NodeToSurfaceContact3dTest, FarPairCostsOnlyADistanceCheck) {
  NodeToSurfaceParams p = params(0.5, 0.4);
  p.search = 0.5;
  auto e = make(p, {1, 1, 10});
  TrialState s = zeroState(15);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_FALSE(e->trialState().projValid);
  // lower bound: the larger of the sphere's 10 - sqrt(2) and the slab's 10 (the height above the
  // plane z = 0 of the quad, here the distance itself)
  EXPECT_NEAR(e->trialState().gap, 10.0, kTol);
  // Brought within the search distance and through the surface, the pair acts again.
  setU(s, 0, {0, 0, -10.05});
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().force(0), kK * 0.05, kTol * kK);
}

// Across a narrow gap of two parallel faces the bounding sphere of the 2 x 2 face reaches past a
// contactor over its corner ((0,0,0.2): sphere bound sqrt(1 + 1 + 0.04) - sqrt(2) = 0.0142 < 0.05);
// the slab along n gives the gap 0.2 itself, so the pair is far.
TEST(NodeToSurfaceContact3dTest, ParallelFacesAcrossAGapAreFarByTheSlab) {
  NodeToSurfaceParams p = params();
  p.search = 0.05;
  auto e = make(p, {0.0, 0.0, 0.2});
  TrialState s = zeroState(15);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_FALSE(e->trialState().projValid);
  EXPECT_NEAR(e->trialState().gap, 0.2, kTol);
  EXPECT_NEAR(ContactSearch::distanceLowerBound(
                  Eigen::Vector3d(0, 0, 0.2), {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                               Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(0, 2, 0)}),
              std::sqrt(2.04) - std::sqrt(2.0), kTol);
  // Behind the face (penetrated 0.3 m, more than the search distance) is contact, never far.
  auto deep = make(p, {1.0, 1.0, 0.1});
  setU(s, 0, {0.0, 0.0, -0.4});
  ASSERT_TRUE(ok(deep->update(s.kinematics())));
  EXPECT_TRUE(deep->trialState().projValid);
  EXPECT_NEAR(deep->trialState().gap, -0.3, kTol);
  EXPECT_NEAR(deep->trialState().force(0), kK * 0.3, kTol * kK);
  // A warped face: corners at heights 0, 0.1, 0, -0.1; the slab is bounded by the highest, 0.1.
  std::array<Eigen::Vector3d, 4> warped{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0.1),
                                        Eigen::Vector3d(2, 2, 0), Eigen::Vector3d(0, 2, -0.1)};
  EXPECT_NEAR(ContactSearch::distanceLowerBound(Eigen::Vector3d(1, 1, 0.5), warped,
                                                Eigen::Vector3d(0, 0, 1)),
              0.4, kTol);
  // The same slab in two parts, as a broad phase per face forms it: the top once (the highest
  // corner, 0.1), then a contactor's height above it (0.5 - 0.1); along a tilted unit normal
  // (0.6, 0, 0.8) the corners' heights are 0, 1.28, 1.2 and -0.08, so the top is 1.28 and the
  // point (1, 1, 0.5) is 0.6 + 0.4 - 1.28 = -0.28 above it. The far test takes the same bound.
  EXPECT_EQ(ContactSearch::slabTop(warped, Eigen::Vector3d(0, 0, 1)), 0.1);
  EXPECT_NEAR(ContactSearch::slabBound(Eigen::Vector3d(1, 1, 0.5), Eigen::Vector3d(0, 0, 1), 0.1),
              0.4, kTol);
  const Eigen::Vector3d tilted(0.6, 0.0, 0.8);
  EXPECT_NEAR(ContactSearch::slabTop(warped, tilted), 1.28, kTol);
  EXPECT_NEAR(ContactSearch::slabBound(Eigen::Vector3d(1, 1, 0.5), tilted, 1.28), -0.28, kTol);
  double bound = 0.0;
  EXPECT_TRUE(ContactSearch(0.3).isFar(Eigen::Vector3d(1, 1, 0.5), warped, Eigen::Vector3d(0, 0, 1),
                                       bound));
  EXPECT_EQ(bound,
            ContactSearch::slabBound(Eigen::Vector3d(1, 1, 0.5), Eigen::Vector3d(0, 0, 1),
                                     ContactSearch::slabTop(warped, Eigen::Vector3d(0, 0, 1))));
}

// updateIfFar gives the state update() gives for a far pair, and declines a near one.
TEST(NodeToSurfaceContact3dTest, FarShortcutMatchesUpdate) {
  NodeToSurfaceParams p = params(0.5, 0.4);
  p.search = 0.05;
  auto a = make(p, {0.5, 0.8, 0.1});
  auto b = make(p, {0.5, 0.8, 0.1});
  TrialState s = zeroState(15);
  setU(s, 0, {0.01, -0.02, 0.3});
  setU(s, 2, {0.0, 0.0, -0.01});
  ASSERT_TRUE(ok(a->update(s.kinematics())));
  std::array<Eigen::Vector3d, 5> u;
  for (int j = 0; j < 5; ++j) u[static_cast<std::size_t>(j)] = s.u.segment<3>(3 * j);
  ASSERT_TRUE(b->updateIfFar(u, s.kinematics().dt));
  EXPECT_EQ(a->trialState().gap, b->trialState().gap);
  EXPECT_EQ(a->trialState().status, b->trialState().status);
  EXPECT_EQ(a->trialState().projValid, b->trialState().projValid);
  EXPECT_EQ(b->resistingForce().norm(), 0.0);
  EXPECT_FALSE(b->isActive());
  // Near (gap 0.1 - 0.08 = 0.02 < 0.05): declined, state untouched.
  setU(s, 0, {0.0, 0.0, -0.08});
  for (int j = 0; j < 5; ++j) u[static_cast<std::size_t>(j)] = s.u.segment<3>(3 * j);
  const double before = b->trialState().gap;
  EXPECT_FALSE(b->updateIfFar(u, 0.01));
  EXPECT_EQ(b->trialState().gap, before);
}

// A pair with a search distance driven the way the analysis drives a sleeping pair (the far test
// on its own copy of the data, setFarTrial, commit; update() once the test finds it near) against
// the same pair with no search distance updated at every step: while far both carry nothing,
// and from the wake-up on every state and matrix is the same to the bit. The contactor
// approaches at a constant rate with a tangential drift (friction and both dashpots at work),
// then holds a penetration of 0.01 m at rest: N = K x 0.01 there.
TEST(NodeToSurfaceContact3dTest, SleepingPairWokenByApproachGivesTheAlwaysAwakeForce) {
  NodeToSurfaceParams p = params(0.5, 0.4);
  p.e = 0.6;
  p.et = 0.8;
  p.M1 = p.M2 = 50.0;
  p.validate();
  auto awake = make(p, {0.5, 0.8, 0.3});
  p.search = 0.05;
  auto sleeper = make(p, {0.5, 0.8, 0.3});
  const FarTest test = sleeper->farTest();
  const double dt = 0.01;
  TrialState s = zeroState(15);
  s.dt = dt;
  int farSteps = 0, wokenAt = -1;
  bool sleeping = sleeper->committedFar();
  ASSERT_TRUE(sleeping);
  for (int i = 1; i <= 30; ++i) {
    const bool moving = i <= 20;  // 0.3 m closed and 0.01 m more in 20 steps, then at rest
    const Eigen::Vector3d u(0.001 * std::min(i, 20), 0.0, -0.0155 * std::min(i, 20));
    const Eigen::Vector3d v = moving ? Eigen::Vector3d(0.1, 0.0, -1.55) : Eigen::Vector3d::Zero();
    setU(s, 0, u);
    s.v.segment<3>(0) = v;
    s.time = i * dt;
    ASSERT_TRUE(ok(awake->update(s.kinematics())));
    std::array<Eigen::Vector3d, 5> un;
    for (std::size_t j = 0; j < 5; ++j) un[j] = s.u.segment<3>(3 * static_cast<int>(j));
    double bound = 0.0;
    if (sleeping && test.isFar(un, bound) && sleeper->setFarTrial(bound, dt)) {
      ++farSteps;
      EXPECT_GT(bound, p.search);
      EXPECT_EQ(sleeper->trialState().gap, bound);
    } else {
      if (sleeping) wokenAt = i;
      sleeping = false;
      ASSERT_TRUE(ok(sleeper->update(s.kinematics())));
    }
    // Every step, awake or sleeping: the same force, impulse and energies.
    const NodeToSurfaceState& a = awake->trialState();
    const NodeToSurfaceState& b = sleeper->trialState();
    EXPECT_EQ(a.force, b.force) << "step " << i;
    EXPECT_EQ(a.impulse, b.impulse) << "step " << i;
    EXPECT_EQ(a.dampingEnergy, b.dampingEnergy) << "step " << i;
    EXPECT_EQ(a.frictionEnergy, b.frictionEnergy) << "step " << i;
    EXPECT_EQ(a.status, b.status) << "step " << i;
    if (!sleeping) {
      EXPECT_EQ(a.gap, b.gap) << "step " << i;
      EXPECT_EQ(a.stickXi, b.stickXi) << "step " << i;
      EXPECT_EQ(Eigen::VectorXd(awake->resistingForce()),
                Eigen::VectorXd(sleeper->resistingForce()));
      EXPECT_EQ(Eigen::MatrixXd(awake->tangentStiff()), Eigen::MatrixXd(sleeper->tangentStiff()));
      EXPECT_EQ(Eigen::MatrixXd(awake->dampingTangent()),
                Eigen::MatrixXd(sleeper->dampingTangent()));
    }
    awake->commitState();
    sleeper->commitState();
  }
  // Sleeping while the gap exceeded 0.05 m (0.3 - 0.0155 i > 0.05 up to i = 16), woken after.
  EXPECT_EQ(farSteps, 16);
  EXPECT_EQ(wokenAt, 17);
  EXPECT_NEAR(sleeper->committedState().gap, -0.01, 1e-12);
  EXPECT_NEAR(sleeper->committedState().force(0), kK * 0.01, 1e-9 * kK);
  EXPECT_GT(sleeper->committedState().impulse(0), 0.0);
}

// A far pair whose committed state is far and quiet commits and reverts the gap alone; the result
// is the state of the same pair updated the ordinary way.
TEST(NodeToSurfaceContact3dTest, PairFarInBothStatesCommitsAndRevertsItsGap) {
  NodeToSurfaceParams p = params(0.5, 0.4);
  p.search = 0.05;
  auto a = make(p, {0.5, 0.8, 0.3});
  auto b = make(p, {0.5, 0.8, 0.3});
  TrialState s = zeroState(15);
  s.dt = 0.01;
  auto step = [&](double uz) {
    setU(s, 0, {0.0, 0.0, uz});
    std::array<Eigen::Vector3d, 5> u;
    for (std::size_t j = 0; j < 5; ++j) u[j] = s.u.segment<3>(3 * static_cast<int>(j));
    EXPECT_TRUE(ok(a->update(s.kinematics())));
    EXPECT_TRUE(b->updateIfFar(u, s.dt));
  };
  step(-0.05);  // gap bound 0.25
  a->commitState();
  b->commitState();
  step(-0.1);  // 0.2, then reverted to 0.25
  EXPECT_EQ(b->trialState().gap, a->trialState().gap);
  EXPECT_NEAR(b->trialState().gap, 0.2, 1e-12);
  a->revertToLastCommit();
  b->revertToLastCommit();
  EXPECT_EQ(b->trialState().gap, a->trialState().gap);
  EXPECT_NEAR(b->trialState().gap, 0.25, 1e-12);
  step(-0.15);
  a->commitState();
  b->commitState();
  EXPECT_NEAR(b->committedState().gap, 0.15, 1e-12);
  EXPECT_EQ(b->committedState().gap, a->committedState().gap);
  EXPECT_EQ(b->committedState().impulse, a->committedState().impulse);
  EXPECT_EQ(*b->response(std::vector<std::string>{"gap"}),
            *a->response(std::vector<std::string>{"gap"}));
  // Woken: from far in both states into contact, the same force as the ordinary pair.
  setU(s, 0, {0.0, 0.0, -0.31});
  ASSERT_TRUE(ok(a->update(s.kinematics())));
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  EXPECT_EQ(b->trialState().force, a->trialState().force);
  EXPECT_NEAR(b->trialState().force(0), kK * 0.01, 1e-9 * kK);
  // Reverted to the far committed state: the trial gap is the committed one again.
  b->revertToLastCommit();
  EXPECT_EQ(b->trialState().gap, b->committedState().gap);
  EXPECT_EQ(b->trialState().status, ContactStatus::Open);
}

// A pair keeps no mass, no initial or committed tangent (they read as zero, of its size), and
// holds its tangent matrices from its first contact on, so a pair that never touches is smaller
// than one 15 x 15 matrix.
TEST(NodeToSurfaceContact3dTest, PairHoldsItsMatricesFromItsFirstContactOn) {
  EXPECT_LT(sizeof(NodeToSurfaceContact3d<3>), sizeof(Eigen::Matrix<double, 15, 15>));
  EXPECT_LT(sizeof(NodeToSurfaceContact3d<6>), sizeof(Eigen::Matrix<double, 15, 15>));
  auto e = make(params(0.5, 0.4), {0.5, 0.8, 0.1});
  for (const auto& m : {Eigen::MatrixXd(e->mass()), Eigen::MatrixXd(e->initialStiff()),
                        Eigen::MatrixXd(e->committedStiff()), Eigen::MatrixXd(e->tangentStiff()),
                        Eigen::MatrixXd(e->dampingTangent())}) {
    EXPECT_EQ(m.rows(), 15);
    EXPECT_EQ(m.cols(), 15);
    EXPECT_TRUE(m.isZero(0.0));
  }
  TrialState s = zeroState(15);
  setU(s, 0, {0.0, 0.0, -0.12});
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->tangentStiff()(2, 2), kK, 1e-9 * kK);  // d(-N)/d(u_kz) with N = K (0.02)
  EXPECT_TRUE(Eigen::MatrixXd(e->mass()).isZero(0.0));
  // Open again: zero force and tangent.
  setU(s, 0, {0.0, 0.0, 0.0});
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_TRUE(Eigen::MatrixXd(e->tangentStiff()).isZero(0.0));
}

TEST(NodeToSurfaceContact3dTest, ContactorOnTheWrongSideIsAnInputError) {
  NodeToSurfaceContact3d<3> e(1, 10, {1, 2, 3, 4}, params());
  EXPECT_THROW(e.initialize(coords({0.5, 0.5, -0.1})), InputError);
  NodeToSurfaceContact3d<3> reversed(2, 10, {1, 4, 3, 2}, params());
  EXPECT_THROW(reversed.initialize({Eigen::Vector3d(0.5, 0.5, 0.1), Eigen::Vector3d(0, 0, 0),
                                    Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(2, 2, 0),
                                    Eigen::Vector3d(2, 0, 0)}),
               InputError);
  NodeToSurfaceParams bad = params();
  bad.muK = 0.3;  // mu_k > mu_s = 0
  EXPECT_THROW(bad.validate(), InputError);
  bad = params();
  bad.e = 0.5;  // needs -masses
  EXPECT_THROW(bad.validate(), InputError);
}

// --- small integrations ----------------------------------------------------------------------

// Head-on impact of a contactor mass M1 on a target of mass M2 whose four nodes move together
// along n. RK4 on (u1, v1, u2, v2); the element is path-independent without friction, so the
// stages may call update() freely. Returns {exit relative-velocity ratio, momentum error,
// normal impulse / (M1 |dv1|)}.
struct ImpactResult {
  double restitution, momentumError, impulseRatio;
};
ImpactResult headOn(double e, double M1, double M2, double v1, double v2) {
  NodeToSurfaceParams p = params();
  p.e = e;
  p.M1 = M1;
  p.M2 = M2;
  p.validate();
  auto el = make(p, {1, 1, 0.01});
  TrialState s = zeroState(15);
  auto accel = [&](double u1, double w1, double u2, double w2, double dt) {
    s.u.setZero();
    s.v.setZero();
    s.u(2) = u1;
    s.v(2) = w1;
    for (int j = 1; j < 5; ++j) {
      s.u(3 * j + 2) = u2;
      s.v(3 * j + 2) = w2;
    }
    s.dt = dt;
    EXPECT_TRUE(ok(el->update(s.kinematics())));
    double f2 = 0.0;
    for (int j = 1; j < 5; ++j) f2 += el->resistingForce()(3 * j + 2);
    return std::pair{-el->resistingForce()(2) / M1, -f2 / M2};
  };
  const double mred = M1 * M2 / (M1 + M2);
  const double dt = 2 * std::numbers::pi * std::sqrt(mred / kK) / 4000;
  double u1 = 0, w1 = v1, u2 = 0, w2 = v2;
  const double p0 = M1 * v1 + M2 * v2;
  bool touched = false;
  for (int i = 0; i < 2000000; ++i) {
    const auto [a1, b1] = accel(u1, w1, u2, w2, 0);
    const auto [a2, b2] =
        accel(u1 + 0.5 * dt * w1, w1 + 0.5 * dt * a1, u2 + 0.5 * dt * w2, w2 + 0.5 * dt * b1, 0);
    const auto [a3, b3] = accel(u1 + 0.5 * dt * (w1 + 0.5 * dt * a1), w1 + 0.5 * dt * a2,
                                u2 + 0.5 * dt * (w2 + 0.5 * dt * b1), w2 + 0.5 * dt * b2, 0);
    const auto [a4, b4] = accel(u1 + dt * (w1 + 0.5 * dt * a2), w1 + dt * a3,
                                u2 + dt * (w2 + 0.5 * dt * b2), w2 + dt * b3, 0);
    u1 += dt * w1 + dt * dt / 6 * (a1 + a2 + a3);
    u2 += dt * w2 + dt * dt / 6 * (b1 + b2 + b3);
    w1 += dt / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    w2 += dt / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
    (void)accel(u1, w1, u2, w2, dt);  // end-of-step state, committed: impulse accumulates
    el->commitState();
    if (el->committedState().gap < 0) touched = true;
    if (touched && el->committedState().gap > 0.001) break;
  }
  return {(w2 - w1) / (v1 - v2), std::abs(M1 * w1 + M2 * w2 - p0) / std::abs(p0),
          el->committedState().impulse(0) / (M1 * std::abs(w1 - v1))};
}

constexpr double kIntegrationTol = 2e-4;  // RK4 with T/4000 steps through the force kink

TEST(NodeToSurfaceContact3dTest, HeadOnImpactConservesMomentumWithNoTensionRestitution) {
  for (double e : {1.0, 0.8, 0.5}) {
    const auto r = headOn(e, 2.0, 3.0, -1.5, 0.2);
    EXPECT_LT(r.momentumError, 1e-10);
    const double expected = NormalLaw::effectiveRestitution(NormalLaw::dampingRatio(e));
    EXPECT_NEAR(r.restitution, expected, kIntegrationTol) << "e = " << e;
    EXPECT_NEAR(r.impulseRatio, 1.0, 1e-3);  // trapezoid impulse of the committed forces
  }
}

// Symplectic Euler with a commit per step (friction needs the return map's history): a
// contactor of mass m against a fixed target; `load` is the applied force at time t.
template <class Load>
void explicitRun(NodeToSurfaceContact3d<3>& el, TrialState& s, double m, double dt, int steps,
                 Load load, const std::function<bool(double)>& stop = {}) {
  for (int i = 0; i < steps; ++i) {
    s.dt = dt;
    ASSERT_TRUE(ok(el.update(s.kinematics())));
    el.commitState();
    const Eigen::Vector3d a = (load(i * dt) - el.resistingForce().head<3>()) / m;
    s.v.head<3>() += dt * a;
    s.u.head<3>() += dt * s.v.head<3>();
    if (stop && stop(i * dt)) return;
  }
}

struct Oblique {
  double dvn, dvt, vy, dissipated;
};
Oblique oblique(double e, double mu, double vn, double vt) {
  const double m = 1.0;
  NodeToSurfaceParams p = params(mu, mu);
  p.e = e;
  p.M1 = m;
  p.M2 = 1e9 * m;  // fixed target
  p.validate();
  auto el = make(p, {1, 1, 0.001});
  TrialState s = zeroState(15);
  s.v.head<3>() = Eigen::Vector3d(vt, 0, -vn);
  const double dt = 2 * std::numbers::pi * std::sqrt(m / kK) / 2000;
  explicitRun(*el, s, m, dt, 20000, [](double) { return Eigen::Vector3d::Zero(); });
  return {s.v(2) + vn, vt - s.v(0), s.v(1),
          el->committedState().frictionEnergy + el->committedState().dampingEnergy};
}

TEST(NodeToSurfaceContact3dTest, ObliqueImpactTangentialSpeedDropsByMuTimesNormalChange) {
  const double vn = 1.0, vt = 2.0, mu = 0.3;
  {
    // Elastic (e = 1): the contactor slides from first touch, so the friction impulse is mu times
    // the normal impulse, except for the release step's small normal force (no friction there),
    // an impulse of at most N dt with N <= K |v_n| dt: relative error <= (w dt)^2.
    const Oblique r = oblique(1.0, mu, vn, vt);
    const double wdt = 2 * std::numbers::pi / 2000;
    EXPECT_NEAR(r.dvt, std::min(vt, mu * r.dvn), wdt * wdt * mu * r.dvn);
    EXPECT_NEAR(r.dvn, 2 * vn, 1e-2 * vn);  // first-order explicit scheme
    EXPECT_NEAR(r.vy, 0.0, 1e-12);
    EXPECT_GT(r.dissipated, 0.0);
  }
  {
    // e = 0.5: the normal speed reverses by the no-tension restitution. The dashpot force C vn at
    // first touch makes the contactor stick for t_s ~ mu C vn / (K vt), losing at most
    // mu^2 C^2 vn^2 / (K m vt) = mu^2 4 xi^2 vn^2 / vt of tangential speed change.
    const double e = 0.5;
    const Oblique r = oblique(e, mu, vn, vt);
    const double xi = NormalLaw::dampingRatio(e);
    const double eEff = NormalLaw::effectiveRestitution(xi);
    EXPECT_NEAR(r.dvn, (1 + eEff) * vn, 1e-2 * vn);
    EXPECT_LE(r.dvt, mu * r.dvn + 1e-12);
    EXPECT_GE(r.dvt, mu * r.dvn - mu * mu * 4 * xi * xi * vn * vn / vt);
  }
  {
    // Small tangential speed (v_t < mu v_n): the contactor sticks for the whole impact. The
    // rigid-body result min(|v_t|, mu (1 + e)|v_n|) assumes the tangential motion simply stops;
    // in this model the stick spring (Kt = K, same period as the normal spring, contact lasting
    // half of it) returns the tangential motion with the tangential restitution e_t = 1, so the
    // change is exactly 2 v_t, not v_t.
    const Oblique r = oblique(1.0, mu, vn, 0.05);
    EXPECT_NEAR(r.dvt, 2 * 0.05, 1e-2 * 0.05);
  }
}

TEST(NodeToSurfaceContact3dTest, BlockOnPlaneSticksUntilMuSNThenSlidesAndStops) {
  const double m = 1.0, g = 9.81, muS = 0.4, muK = 0.3, W = m * g;
  NodeToSurfaceParams p = params(muS, muK);
  p.e = 0.2;   // damps the normal vibration
  p.et = 0.5;  // and the tangential one once the block sticks
  p.M1 = m;
  p.M2 = 1e9 * m;
  p.validate();
  const double dt = 2 * std::numbers::pi * std::sqrt(m / kK) / 50;
  {
    auto el = make(p, {1, 1, 0.0});
    TrialState s = zeroState(15);
    s.u(2) = -W / kK;          // static penetration
    const double rate = 10.0;  // ramp P = rate t
    double tSlide = -1.0;
    explicitRun(
        *el, s, m, dt, 200000, [&](double t) { return Eigen::Vector3d(rate * t, 0, -W); },
        [&](double t) {
          if (tSlide < 0 && el->committedState().status == ContactStatus::Slide) tSlide = t;
          return t >= 0.8;
        });
    // Stuck until P = mu_s N (within two steps of the ramp; the inertia of the quasi-static
    // stick phase is negligible).
    EXPECT_NEAR(rate * tSlide, muS * W, rate * 2 * dt);
    // Then a = (P - mu_k N)/m: v(t) = [rate (t^2 - ts^2)/2 - mu_k W (t - ts)]/m.
    const double t = 0.8 + dt;  // the velocity after the last step
    const double ts = muS * W / rate;
    const double v = (rate * (t * t - ts * ts) / 2 - muK * W * (t - ts)) / m;
    EXPECT_NEAR(s.v(0), v, 1e-2 * v);
  }
  {
    auto el = make(p, {0.1, 1, 0.0});
    TrialState s = zeroState(15);
    s.u(2) = -W / kK;
    const double v0 = 1.0;
    s.v(0) = v0;
    explicitRun(*el, s, m, dt, 5000, [&](double) { return Eigen::Vector3d(0, 0, -W); });
    // Stops after sliding v0^2 / (2 mu_k g).
    EXPECT_NEAR(el->committedState().slipLength, v0 * v0 / (2 * muK * g),
                1e-2 * v0 * v0 / (2 * muK * g));
    EXPECT_LT(std::abs(s.v(0)), 1e-3);
  }
}

}  // namespace
}  // namespace dabs::contact
