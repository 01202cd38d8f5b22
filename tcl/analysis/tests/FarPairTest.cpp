// SPDX-License-Identifier: MIT
// The analysis finds elements that may sleep (Element::farPair) and that predict their contact
// (Element::contactPredictor) through those interfaces alone: a fake element written here, with no
// contact header in sight, sleeps while far, is tested once per check, wakes when near, and sets
// contact stepping's step. Expected values follow from the fake's own rules below.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "elements/ContactPredictor.h"
#include "elements/Element.h"
#include "elements/FarPair.h"
#include "tcl/analysis/model/AnalysisModel.h"
#include "tcl/analysis/driver/ContactStepping.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {
namespace {

constexpr double kHeight = 0.2;    // the contactor's height above the face at rest
constexpr double kDistance = 0.1;  // the fake's search distance
constexpr double kStiffness = 4.0 * std::numbers::pi * std::numbers::pi;  // T_c = 1 / sqrt(m)

/// A contactor (element node 1) over a face in z = 0 (nodes 2 to 5) that never carries force:
/// far while its slab bound (height above the face's highest corner) exceeds kDistance; its gap
/// is that bound. It counts the analysis' calls.
class FakePair final : public elements::Element,
                       public elements::FarPair,
                       public elements::ContactPredictor {
 public:
  FakePair(int tag, std::vector<int> nodes, bool search)
      : Element(tag), nodes_(std::move(nodes)), search_(search) {}

  std::string_view typeName() const override { return "fakePair"; }
  const std::vector<int>& nodeTags() const override { return nodes_; }
  int numDof() const override { return 15; }
  int dofPerNode() const override { return 3; }
  void initialize(const elements::NodalCoordinates& x) override {
    for (std::size_t i = 0; i < 5; ++i) X_[i] = x[i];
  }
  [[nodiscard]] Status update(const elements::Kinematics& trial) override {
    ++updates;
    std::array<Eigen::Vector3d, 5> u;
    for (std::size_t i = 0; i < 5; ++i) u[i] = trial.u.segment<3>(3 * static_cast<Eigen::Index>(i));
    trialGap_ = bound(u);
    return Status::Ok;
  }
  Eigen::Ref<const Eigen::VectorXd> resistingForce() const override { return zeroF_; }
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const override { return zeroK_; }
  Eigen::Ref<const Eigen::MatrixXd> initialStiff() const override { return zeroK_; }
  bool isActive() const override { return false; }
  void commitState() override { committedGap_ = trialGap_; }
  void revertToLastCommit() override { trialGap_ = committedGap_; }
  void revertToStart() override { trialGap_ = committedGap_ = kHeight; }

  elements::FarPair* farPair() noexcept override { return search_ ? this : nullptr; }
  const elements::ContactPredictor* contactPredictor() const noexcept override { return this; }

  Geometry farGeometry() const override {
    return Geometry{X_, Eigen::Vector3d::UnitZ(), kDistance};
  }
  bool isFarAt(const std::array<Eigen::Vector3d, 5>& u, double& b) const override {
    ++fullTests;
    b = bound(u);
    return b > kDistance;
  }
  bool committedFar() const override { return committedGap_ > kDistance; }
  bool trialFarBeyond(double factor) const override { return trialGap_ > factor * kDistance; }
  bool farInBothStates() const override { return false; }  // no deferred faces here
  bool setFarTrial(double b, double /*dt*/) override {
    ++farTrials;
    trialGap_ = b;
    return true;
  }
  bool setGapInBothStates(double /*b*/) override { return false; }

  double committedGap() const override { return committedGap_; }
  bool committedClosed() const override { return committedGap_ <= 0.0; }
  double contactDuration(std::span<const double> nodeMasses, double /*gapRate*/) const override {
    return std::numbers::pi * std::sqrt(nodeMasses[0] / kStiffness);
  }

  /// Sets the committed gap as a commit after an update to it would.
  void commitGap(double g) { trialGap_ = committedGap_ = g; }

  mutable int fullTests = 0;
  int farTrials = 0;
  int updates = 0;

 private:
  double bound(const std::array<Eigen::Vector3d, 5>& u) const {
    std::array<Eigen::Vector3d, 4> face;
    for (std::size_t i = 0; i < 4; ++i) face[i] = X_[i + 1] + u[i + 1];
    return FarPair::slabBound(X_[0] + u[0], Eigen::Vector3d::UnitZ(),
                              FarPair::slabTop(face, Eigen::Vector3d::UnitZ()));
  }
  std::vector<int> nodes_;
  bool search_;
  std::array<Eigen::Vector3d, 5> X_{};
  double trialGap_ = kHeight, committedGap_ = kHeight;
  Eigen::VectorXd zeroF_ = Eigen::VectorXd::Zero(15);
  Eigen::MatrixXd zeroK_ = Eigen::MatrixXd::Zero(15, 15);
};

/// Face nodes 1-4 (1 x 1 m, z = 0), contactor node 10 kHeight above its middle, the contactor
/// with mass `mass` in each direction.
struct FakeModel {
  explicit FakeModel(bool search = true, double mass = 0.0) {
    domain.addNode(1, 3, 3, Eigen::Vector3d(0, 0, 0));
    domain.addNode(2, 3, 3, Eigen::Vector3d(1, 0, 0));
    domain.addNode(3, 3, 3, Eigen::Vector3d(1, 1, 0));
    domain.addNode(4, 3, 3, Eigen::Vector3d(0, 1, 0));
    domain.addNode(10, 3, 3, Eigen::Vector3d(0.5, 0.5, kHeight));
    if (mass > 0.0) domain.node(10).setMass(Eigen::MatrixXd::Identity(3, 3) * mass);
    auto e = std::make_unique<FakePair>(7, std::vector<int>{10, 1, 2, 3, 4}, search);
    pair = e.get();
    domain.addElement(std::move(e));
  }
  domain::Domain domain;
  FakePair* pair = nullptr;
};

TEST(FarPairTest, FakePairSleepsIsTestedOncePerCheckAndWakesWhenNear) {
  FakeModel model;
  AnalysisModel analysis(model.domain, ConstraintKind::Plain, NumbererKind::Plain);
  analysis.build();
  ASSERT_EQ(analysis.sleepingPairs(), 1);
  // Far: the analysis' slab test settles it (the fake's whole test is not needed), and the pair
  // gets its bound through setFarTrial without an update.
  EXPECT_EQ(analysis.checkSleepingPairs(), AnalysisModel::SleepCheck::Unchanged);
  EXPECT_EQ(analysis.farTests(), 1);
  EXPECT_EQ(model.pair->farTrials, 1);
  EXPECT_EQ(model.pair->fullTests, 0);
  EXPECT_EQ(model.pair->updates, 0);
  // Within the search distance (0.05 m above the face): the whole test is asked, says near, and
  // the pair is woken with one update (it carries no force, so the step stands).
  model.domain.node(10).disp.head<3>() = Eigen::Vector3d(0, 0, -(kHeight - 0.05));
  EXPECT_EQ(analysis.checkSleepingPairs(), AnalysisModel::SleepCheck::PatternChange);
  EXPECT_EQ(model.pair->fullTests, 1);
  EXPECT_EQ(model.pair->updates, 1);
  EXPECT_DOUBLE_EQ(model.pair->committedGap(), kHeight);  // a check writes no committed state
  model.domain.commit();
  analysis.applySleepChanges();
  EXPECT_EQ(analysis.sleepingPairs(), 0);
  // Beyond twice the search distance (0.25 m above the face): it goes to sleep.
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(analysis.numEquations());
  Eigen::VectorXd U = zero;
  U(analysis.equationOf(10, 2)) = 0.05;
  analysis.setResponse(U, zero, zero);
  ASSERT_TRUE(ok(analysis.updateElements()));
  EXPECT_EQ(analysis.checkSleepingPairs(), AnalysisModel::SleepCheck::PatternChange);
  model.domain.commit();
  analysis.applySleepChanges();
  EXPECT_EQ(analysis.sleepingPairs(), 1);
}

TEST(FarPairTest, ElementWithoutFarPairNeverSleeps) {
  FakeModel model(false);
  AnalysisModel analysis(model.domain, ConstraintKind::Plain, NumbererKind::Plain);
  analysis.build();
  EXPECT_EQ(analysis.sleepingPairs(), 0);
  EXPECT_EQ(analysis.checkSleepingPairs(), AnalysisModel::SleepCheck::Unchanged);
  EXPECT_EQ(analysis.farTests(), 0);
  EXPECT_EQ(model.pair->farTrials, 0);
}

TEST(FarPairTest, ContactSteppingReadsTheFakeThroughItsPredictor) {
  // Contactor mass 4: T_c = pi sqrt(4 / (4 pi^2)) = 1, so with perContact 10 a closed pair
  // limits the step to 0.1.
  FakeModel model(true, 4.0);
  ContactSteppingParams p;
  p.maxStep = 0.5;
  p.lookAhead = 2.0;
  p.overshoot = 1.2;
  p.perContact = 10;
  p.validate();
  ContactStepping stepping(p);
  stepping.attach(model.domain);
  ASSERT_EQ(stepping.pairs(), 1u);
  // Open and no history: the output step.
  EXPECT_DOUBLE_EQ(stepping.nextStep(1.0, 1.0), 1.0);
  // Closed: T_c / perContact.
  model.pair->commitGap(-0.001);
  EXPECT_NEAR(stepping.nextStep(1.0, 1.0), 0.1, 1e-15);
}

}  // namespace
}  // namespace dabs::analysis
