// SPDX-License-Identifier: MIT
// Contact stepping on one node-to-surface pair whose committed gap the test sets: no prediction
// before a step is known, the contact step when a pair is closed or about to close, the cut at
// the predicted first contact (t_close = g h_last / (g_last - g), times the overshoot), and the
// parameter checks. Expected step lengths are worked out by hand from those rules.
#include "tcl/analysis/driver/ContactStepping.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "contact/NodeToSurfaceContact3d.h"
#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {
namespace {

constexpr double kZ0 = 0.1;  // height of the contactor above the target face at rest

/// A target quad in z = 0 (nodes 1-4) and a contactor (node 10) kZ0 above it; the pair's
/// committed gap is set by moving the contactor down and committing.
class OnePair {
 public:
  /// `masses`: the pair's -masses M1 M2 (none when empty); `nodeMass`: each node's mass.
  explicit OnePair(std::array<double, 2> masses = {0.0, 0.0}, double nodeMass = 0.0,
                   double e = 1.0) {
    domain_.addNode(1, 3, 3, Eigen::Vector3d(0, 0, 0));
    domain_.addNode(2, 3, 3, Eigen::Vector3d(2, 0, 0));
    domain_.addNode(3, 3, 3, Eigen::Vector3d(2, 2, 0));
    domain_.addNode(4, 3, 3, Eigen::Vector3d(0, 2, 0));
    domain_.addNode(10, 3, 3, Eigen::Vector3d(0.5, 0.8, kZ0));
    if (nodeMass > 0.0)
      for (int tag : {1, 2, 3, 4, 10})
        domain_.node(tag).setMass(Eigen::MatrixXd::Identity(3, 3) * nodeMass);
    contact::NodeToSurfaceParams p;
    p.K = 1e5;
    p.M1 = masses[0];
    p.M2 = masses[1];
    p.e = e;
    p.validate();
    auto pair = std::make_unique<contact::NodeToSurfaceContact3d<3>>(
        1, 10, std::array<int, 4>{1, 2, 3, 4}, p);
    pair_ = pair.get();
    domain_.addElement(std::move(pair));
  }
  const domain::Domain& domain() const { return domain_; }
  /// Commits the pair with the contactor at gap g (negative: penetration).
  void commitGap(double g) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(15), zero = Eigen::VectorXd::Zero(15);
    u(2) = g - kZ0;
    ASSERT_TRUE(ok(pair_->update(elements::Kinematics{u, zero, zero, 0.0, 0.0})));
    pair_->commitState();
    ASSERT_NEAR(pair_->committedState().gap, g, 1e-15);
  }

 private:
  domain::Domain domain_;
  contact::NodeToSurfaceContact3d<3>* pair_ = nullptr;
};

ContactSteppingParams params(double maxStep) {
  ContactSteppingParams p;
  p.maxStep = maxStep;
  p.lookAhead = 2.0;
  p.overshoot = 1.2;
  p.validate();
  return p;
}

TEST(ContactSteppingTest, OpenPairWithoutHistoryTakesTheOutputStep) {
  OnePair model;
  ContactStepping stepping(params(0.0005));
  stepping.attach(model.domain());
  EXPECT_EQ(stepping.pairs(), 1u);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
  EXPECT_EQ(stepping.contactSteps(), 0);
}

TEST(ContactSteppingTest, ClosingPairWithinTheLookAheadTakesContactSteps) {
  OnePair model;
  ContactStepping stepping(params(0.0005));
  stepping.attach(model.domain());
  ASSERT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
  // The gap shrank from 0.1 to 0.06 over 0.01 s: contact predicted in 0.06 * 0.01 / 0.04 =
  // 0.015 s, within lookAhead x remaining = 0.02 s, and after the step's end (no cut): maxStep.
  model.commitGap(0.06);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.0005);
  EXPECT_EQ(stepping.contactSteps(), 1);
  // A gap that stopped shrinking predicts nothing; open: the rest of the output step.
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.0095, 0.01), 0.0095);
}

TEST(ContactSteppingTest, StepIsCutAtThePredictedContactTimesTheOvershoot) {
  OnePair model;
  ContactStepping stepping(params(0.1));  // a long maxStep, so the cut decides
  stepping.attach(model.domain());
  ASSERT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
  model.commitGap(0.06);
  // t_close = 0.015 s < remaining 0.05 s: the step ends at 1.2 x 0.015 = 0.018 s.
  EXPECT_NEAR(stepping.nextStep(0.05, 0.05), 0.018, 1e-15);
}

// A Kelvin pair with a strong dashpot (e = 0.1, masses 1 and 1, K 1e5): the dashpot force jumps
// to C v at the touch, and the step holding the touch is at most touchStep = 0.02 m / C (C h /
// (2 m) = 1 %), here 3.8e-5 s, shorter than the contact step (maxStep 1e-3 s, no -perContact).
// The gap fell from 0.1 to 0.002 over 0.01 s: t_close = 0.002 * 0.01 / 0.098 = 2.04e-4 s, and
// the step ends half a touch step before it (not at 1.2 t_close = 2.45e-4 s); the gap then left,
// 0.002 - 9.8 * h, predicts the touch half a touch step ahead, and the step holding it is 1.2
// times that; a step in contact is then no longer than the time the pair has been closed (or
// the touch step), and a step cut short by the output step's end does not restart that growth.
TEST(ContactSteppingTest, ATouchWithADashpotJumpIsTakenInAShortStep) {
  OnePair model({1.0, 1.0}, 0.0, 0.1);
  ContactSteppingParams p = params(0.001);
  p.perContact = 0;
  ContactStepping stepping(p);
  stepping.attach(model.domain());
  const double logE = std::log(0.1);
  const double xi = -logE / std::sqrt(std::numbers::pi * std::numbers::pi + logE * logE);
  const double m = 0.5;
  const double touch = 0.02 * m / (2.0 * xi * std::sqrt(1e5 * m));
  model.commitGap(0.1);
  ASSERT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
  model.commitGap(0.002);
  const double tClose = 0.002 * 0.01 / 0.098;
  const double h = stepping.nextStep(0.01, 0.01);
  EXPECT_NEAR(h, tClose - 0.5 * touch, 1e-15);
  const double gap = 0.002 - 9.8 * h;
  model.commitGap(gap);
  const double tClose2 = gap * h / (0.002 - gap);
  EXPECT_NEAR(tClose2, 0.5 * touch, 1e-12);
  const double hTouch = stepping.nextStep(0.01, 0.01);
  EXPECT_NEAR(hTouch, 1.2 * tClose2, 1e-15);
  // Closed at the end of the touch step: its age in contact counts from that step's start,
  // hTouch (0.6 touch), and the next step is the touch step.
  model.commitGap(-1e-6);
  const double h1 = stepping.nextStep(0.01, 0.01);
  EXPECT_NEAR(h1, touch, 1e-15);
  // Age hTouch + touch: the step is as long. It is not committed (the analysis stopped in it),
  // and the step chosen next is the same: it added nothing to the age.
  model.commitGap(-2e-6);
  EXPECT_NEAR(stepping.nextStep(0.01, 0.01), hTouch + touch, 1e-15);
  stepping.stepNotTaken();
  const double h2 = stepping.nextStep(0.01, 0.01);
  EXPECT_NEAR(h2, hTouch + touch, 1e-15);
  // The output step ends 1e-6 s later: that step is cut to it ...
  model.commitGap(-3e-6);
  EXPECT_NEAR(stepping.nextStep(1e-6, 0.01), 1e-6, 1e-18);
  // ... and the next is the pair's age, hTouch + touch + h2 + 1e-6, not a growth from 1e-6.
  model.commitGap(-4e-6);
  EXPECT_NEAR(stepping.nextStep(0.01, 0.01), hTouch + touch + h2 + 1e-6, 1e-15);
}

TEST(ContactSteppingTest, APairAtTheTopOfABounceIsPredictedToCloseAgain) {
  // A contactor thrown up from the face: g(t) = 0.02 + 1.5 t - 50 t^2 (a free flight under a
  // constant force), committed at t = 0, 0.01, 0.02: 0.02, 0.03, 0.03. Over the last step the gap
  // did not change, so the linear prediction sees nothing; the parabola through the three gaps
  // closes at t = 0.04, 0.02 s after the last commit (the root of 50 t^2 - 1.5 t - 0.02).
  OnePair model;
  ContactStepping stepping(params(0.1));  // a long maxStep, so the cut decides
  stepping.attach(model.domain());
  model.commitGap(0.02);
  ASSERT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
  model.commitGap(0.03);
  ASSERT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);  // opening: no prediction
  model.commitGap(0.03);
  EXPECT_NEAR(stepping.nextStep(0.05, 0.05), 1.2 * 0.02, 1e-12);
  // Rising and slowing but far from the face: the parabola closes after the output step.
  OnePair far;
  ContactStepping farStepping(params(0.1));
  farStepping.attach(far.domain());
  far.commitGap(0.5);
  ASSERT_DOUBLE_EQ(farStepping.nextStep(0.01, 0.01), 0.01);
  far.commitGap(0.51);
  ASSERT_DOUBLE_EQ(farStepping.nextStep(0.01, 0.01), 0.01);
  far.commitGap(0.51);
  EXPECT_DOUBLE_EQ(farStepping.nextStep(0.01, 0.01), 0.01);
}

TEST(ContactSteppingTest, ClosedPairTakesTheContactStepAndResetForgetsTheHistory) {
  OnePair model;
  ContactStepping stepping(params(0.0005));
  stepping.attach(model.domain());
  model.commitGap(-0.001);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.0005);
  model.commitGap(0.1);
  stepping.reset();
  model.commitGap(0.06);  // closing, but with no step remembered there is no prediction
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
}

// A release step ends in tension (K 1e5, committed at g_n = -1e-4 with N_n = K delta_n = 10, then
// open at g = 1e-3: N = -N_n g / (g - g_n) = -9.09); the trapezoid rule carries that force through
// the next step as well, so the next step is no longer than the release step (here 0.2 ms,
// shorter than maxStep), and once the pair is open without force it takes the output step again.
TEST(ContactSteppingTest, TheStepAfterAReleaseInTensionIsNoLongerThanTheRelease) {
  OnePair model;
  ContactStepping stepping(params(0.0005));
  stepping.attach(model.domain());
  model.commitGap(-1e-4);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.0002, 0.01), 0.0002);  // closed: the rest of the step
  model.commitGap(1e-3);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.0002);
  // open, no force, moving apart no slower than over the release step: nothing predicted
  model.commitGap(2.2e-3);
  EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);
}

TEST(ContactSteppingTest, PerContactLimitsTheStepToAFractionOfTheContactDuration) {
  // -masses 2 3, K 1e5: m = 1.2, T_c = pi sqrt(1.2 / 1e5); 20 steps per contact.
  {
    OnePair model({2.0, 3.0});
    ContactSteppingParams p = params(0.01);  // long: the contact decides
    p.perContact = 20;
    ContactStepping stepping(p);
    stepping.attach(model.domain());
    EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.01);  // open: no limit
    model.commitGap(-0.001);
    EXPECT_NEAR(stepping.nextStep(0.01, 0.01), std::numbers::pi * std::sqrt(1.2 / 1e5) / 20, 1e-18);
  }
  // No -masses: the nodes' masses, 0.5 each: contactor 0.5, face 2.0, m = 0.4.
  {
    OnePair model({0.0, 0.0}, 0.5);
    ContactSteppingParams p = params(0.01);  // long: the contact decides
    p.perContact = 10;
    ContactStepping stepping(p);
    stepping.attach(model.domain());
    model.commitGap(-0.001);
    EXPECT_NEAR(stepping.nextStep(0.01, 0.01), std::numbers::pi * std::sqrt(0.4 / 1e5) / 10, 1e-18);
  }
  // A longer contact than maxStep allows: maxStep decides.
  {
    OnePair model({2000.0, 3000.0});
    ContactSteppingParams p = params(0.0005);
    p.perContact = 20;
    ContactStepping stepping(p);
    stepping.attach(model.domain());
    model.commitGap(-0.001);
    EXPECT_DOUBLE_EQ(stepping.nextStep(0.01, 0.01), 0.0005);
  }
}

TEST(ContactSteppingTest, ParametersAreChecked) {
  ContactSteppingParams p;
  p.maxStep = 0.0;
  EXPECT_THROW(p.validate(), InputError);
  p = ContactSteppingParams();
  p.lookAhead = -1.0;
  EXPECT_THROW(p.validate(), InputError);
  p = ContactSteppingParams();
  p.overshoot = 0.9;
  EXPECT_THROW(p.validate(), InputError);
  p = ContactSteppingParams();
  p.perContact = -1;
  EXPECT_THROW(p.validate(), InputError);
  EXPECT_NO_THROW(ContactSteppingParams().validate());
}

}  // namespace
}  // namespace dabs::analysis
