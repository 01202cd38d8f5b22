// SPDX-License-Identifier: MIT
// Over 400 lines: the model of faces and contactors and the harness that stands in for
// AnalysisModel are written here, beside the cases that share them.
// SleepingPairs, driven by a harness written here in place of AnalysisModel (every node dof an
// equation; the pairs updated from their nodes). Its once-a-step far test, made per target face
// (the face's slab top formed once for every pair against it), against the pair's own test
// (FarTest::isFar, the slab and the bounding sphere on its five nodes) and against a brute-force
// distance from the contactor to the bilinear face: on random configurations every sleeper gets the
// verdict and the bound of its own test to the bit, and no pair found far is within its search
// distance. Then a contactor that crosses the search distance and the face in one step while the
// other pairs of its face stay far is woken and the step is redone. Deferred tests (a face whose
// pairs all sleep is left alone until the motion of their nodes could bring one to its search
// distance): on random walks of the nodes, pairs wake at the same checks as with the test of
// every step, with fewer tests, and are left out of the domain's commit while deferred.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "contact/NodeToSurfaceContact3d.h"
#include "tcl/analysis/model/SleepingPairs.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/Recorder.h"

namespace dabs::analysis {
namespace {

using contact::NodeToSurfaceContact3d;
using contact::NodeToSurfaceParams;

constexpr double kSearch = 0.05;
constexpr double kHeight = 0.2;  // contactors' height above their face at rest

/// One pair as built: its element, the tags of its contactor and face nodes (a b c d).
struct Pair {
  elements::Element* element = nullptr;
  int contactor = 0;
  std::array<int, 4> face{};
  double search = kSearch;
};

/// Faces of 2 x 1 m in planes z = 0 (nodes 100 f + 1..4, counterclockwise seen from above, so
/// the outward normal is +z), 10 m apart along x; each with four contactors (nodes 100 f + 11..14)
/// kHeight above it at points inside and just outside its edges. Pairs: each contactor against
/// its face; against face 0 also one more contactor with a larger search distance and one that
/// names the face's nodes in another order (a face of its own to the broad phase). Face 2 and its
/// contactors have 6 dofs per node (NodeToSurfaceContact3d<6>).
class Faces {
 public:
  explicit Faces(int faces = 3) {
    for (int f = 0; f < faces; ++f) {
      const int ndf = f == 2 ? 6 : 3;
      const double x0 = 10.0 * f;
      const int base = 100 * f;
      const std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 0),
                                                   Eigen::Vector2d(2, 1), Eigen::Vector2d(0, 1)};
      for (int i = 0; i < 4; ++i)
        domain_.addNode(base + 1 + i, 3, ndf,
                        Eigen::Vector3d(x0 + corners[static_cast<std::size_t>(i)].x(),
                                        corners[static_cast<std::size_t>(i)].y(), 0.0));
      const std::array<Eigen::Vector2d, 6> spots{
          Eigen::Vector2d(0.5, 0.5), Eigen::Vector2d(1.9, 0.1), Eigen::Vector2d(-0.1, 0.9),
          Eigen::Vector2d(2.2, 0.5), Eigen::Vector2d(1.0, 0.3), Eigen::Vector2d(0.2, 0.2)};
      const int contactors = f == 0 ? 6 : 4;
      for (int i = 0; i < contactors; ++i) {
        const Eigen::Vector2d s = spots[static_cast<std::size_t>(i)];
        const int tag = base + 11 + i;
        domain_.addNode(tag, 3, ndf, Eigen::Vector3d(x0 + s.x(), s.y(), kHeight));
        std::array<int, 4> face{base + 1, base + 2, base + 3, base + 4};
        if (f == 0 && i == 5) face = {base + 2, base + 3, base + 4, base + 1};  // the same face
        add(tag, face, f == 0 && i == 4 ? 2.0 * kSearch : kSearch, ndf);
      }
    }
  }

  domain::Domain& domain() { return domain_; }
  const std::vector<Pair>& pairs() const { return pairs_; }
  /// The translations of the pair's nodes (k, a, b, c, d).
  std::array<Eigen::Vector3d, 5> translations(const Pair& p) {
    std::array<Eigen::Vector3d, 5> u;
    u[0] = domain_.node(p.contactor).disp.head<3>();
    for (std::size_t j = 0; j < 4; ++j) u[j + 1] = domain_.node(p.face[j]).disp.head<3>();
    return u;
  }
  contact::FarTest farTest(const Pair& p) const {
    if (auto* e3 = dynamic_cast<NodeToSurfaceContact3d<3>*>(p.element)) return e3->farTest();
    return dynamic_cast<NodeToSurfaceContact3d<6>*>(p.element)->farTest();
  }
  const contact::NodeToSurfaceState& trial(const Pair& p) const {
    if (auto* e3 = dynamic_cast<NodeToSurfaceContact3d<3>*>(p.element)) return e3->trialState();
    return dynamic_cast<NodeToSurfaceContact3d<6>*>(p.element)->trialState();
  }
  /// Brute force: the smallest distance from the contactor to points of the bilinear face on a
  /// 101 x 101 grid of its parameters (at least the true distance, and within 1.2 cm of it).
  double sampledDistance(const Pair& p) {
    const auto u = translations(p);
    std::array<Eigen::Vector3d, 5> x;
    x[0] = domain_.node(p.contactor).coords() + u[0];
    for (std::size_t j = 0; j < 4; ++j) x[j + 1] = domain_.node(p.face[j]).coords() + u[j + 1];
    double best = INFINITY;
    const int n = 100;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double s = double(i) / n, t = double(j) / n;
        const Eigen::Vector3d q =
            (1 - s) * (1 - t) * x[1] + s * (1 - t) * x[2] + s * t * x[3] + (1 - s) * t * x[4];
        best = std::min(best, (x[0] - q).norm());
      }
    return best;
  }

 private:
  void add(int contactor, const std::array<int, 4>& face, double search, int ndf) {
    NodeToSurfaceParams p;
    p.K = 1.0e6;
    p.muS = p.muK = 0.3;
    p.search = search;
    p.validate();
    const int tag = 1000 + static_cast<int>(pairs_.size());
    std::unique_ptr<elements::Element> e;
    if (ndf == 3)
      e = std::make_unique<NodeToSurfaceContact3d<3>>(tag, contactor, face, p);
    else
      e = std::make_unique<NodeToSurfaceContact3d<6>>(tag, contactor, face, p);
    pairs_.push_back(Pair{&domain_.addElement(std::move(e)), contactor, face, search});
  }

  domain::Domain domain_;
  std::vector<Pair> pairs_;
};

/// SleepingPairs over a model without an AnalysisModel: every node dof one equation (nodes in
/// tag order), each pair sleeping as SleepingPairs::wantsSleep says at every rebuild, and a waker
/// that updates the pair from its nodes' trial displacements (velocities and accelerations zero,
/// time and step 0) and tells whether it carries force.
class Harness {
 public:
  explicit Harness(Faces& model) : model_(model), sleepers_(model.domain()) {
    int next = 0;
    for (auto& [tag, node] : model.domain().nodes()) {
      first_[tag] = next;
      for (int d = 0; d < node.ndf(); ++d) {
        directEq_.push_back(next);
        terms_.push_back({DofTerm{next, 1.0}});
        ++next;
      }
    }
    neq_ = next;
    rebuild();
  }

  int numEquations() const { return neq_; }
  int equationOf(int tag, int dof) const { return first_.at(tag) + dof; }
  long sleepingPairs() const { return sleepers_.sleeping(); }
  long farTests() const { return sleepers_.farTests(); }
  std::size_t deferredFaces() const { return sleepers_.deferredFaces(); }
  long elementUpdates() const { return updates_; }
  void beginSteps(bool observeAll) { sleepers_.beginSteps(observeAll); }
  void endSteps() { sleepers_.endSteps(); }

  /// The check on the nodes' trial displacements as they are.
  SleepingPairs::Check checkSleepingPairs() {
    return sleepers_.check(0.0, {}, [this](std::size_t i) {
      const Status s = update(i);
      return !ok(s) || model_.pairs()[i].element->isActive();
    });
  }

  /// One step as the analysis makes it: nodes' trial displacements from U, the awake pairs
  /// updated, the sleepers checked, the domain committed and the pairs rebuilt when some woke or
  /// went to sleep.
  SleepingPairs::Check step(const Eigen::VectorXd& U) {
    for (auto& [tag, node] : model_.domain().nodes())
      for (int d = 0; d < node.ndf(); ++d) node.disp(d) = U(equationOf(tag, d));
    sleepers_.setDisplacements(U);
    for (std::size_t i = 0; i < sleeping_.size(); ++i)
      if (!sleeping_[i]) {
        EXPECT_TRUE(ok(update(i)));
      }
    const auto result = checkSleepingPairs();
    model_.domain().commit();
    if (result == SleepingPairs::Check::PatternChange) {
      const SleepingPairs::Carried carried = sleepers_.beforeRebuild();
      rebuild();
      sleepers_.afterRebuild(carried);
    }
    return result;
  }

 private:
  void rebuild() {
    std::map<const elements::Element*, std::uint32_t> domainIndex;
    for (const auto& [tag, e] : model_.domain().elements())
      domainIndex.emplace(e.get(), static_cast<std::uint32_t>(domainIndex.size()));
    std::vector<SleepingPairs::Pair> pairs;
    sleeping_.clear();
    for (std::size_t i = 0; i < model_.pairs().size(); ++i) {
      const Pair& q = model_.pairs()[i];
      SleepingPairs::Pair p;
      p.link = i;
      p.tag = q.element->tag();
      p.far = q.element->farPair();
      p.contactor = &model_.domain().node(q.contactor);
      for (std::size_t j = 0; j < 4; ++j) p.face[j] = &model_.domain().node(q.face[j]);
      p.sleeping = sleepers_.wantsSleep(*p.far);
      p.domainIndex = domainIndex.at(q.element);
      sleeping_.push_back(p.sleeping);
      pairs.push_back(p);
    }
    sleepers_.build(
        std::move(pairs),
        SleepingPairs::DofSource{[this](int tag) { return first_.at(tag); }, directEq_, terms_});
  }
  Status update(std::size_t i) {
    const Pair& q = model_.pairs()[i];
    const int n = q.element->numDof();
    Eigen::VectorXd u(n);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
    int k = 0;
    for (int tag : q.element->nodeTags()) {
      const domain::Node& node = model_.domain().node(tag);
      u.segment(k, node.ndf()) = node.disp;
      k += node.ndf();
    }
    ++updates_;
    return q.element->update(elements::Kinematics{u, zero, zero, 0.0, 0.0});
  }

  Faces& model_;
  SleepingPairs sleepers_;
  std::map<int, int> first_;
  std::vector<int> directEq_;
  std::vector<std::vector<DofTerm>> terms_;
  std::vector<char> sleeping_;
  int neq_ = 0;
  long updates_ = 0;
};

TEST(SleepingPairsTest, FarTestPerFaceGivesEachPairsOwnVerdictAndBound) {
  Faces model;
  Harness analysis(model);
  ASSERT_EQ(analysis.sleepingPairs(), static_cast<long>(model.pairs().size()));
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> face(-0.04, 0.04);  // tilts and warps the faces
  std::uniform_real_distribution<double> drift(-0.3, 0.3);   // in-plane drift of a contactor
  // A contactor's height change: from far above to within the search distance of the top corner
  // (at least 0.06 m above the plane, above the faces' corners, which stay below 0.055 m: no
  // force, so a woken pair never asks for the step to be redone).
  std::uniform_real_distribution<double> lift(-0.14, 0.02);
  int far = 0, near = 0;
  for (int trial = 0; trial < 300; ++trial) {
    for (auto& [tag, node] : model.domain().nodes()) {
      const bool contactor = tag % 100 > 10;
      Eigen::Vector3d u = contactor ? Eigen::Vector3d(drift(rng), drift(rng), lift(rng))
                                    : Eigen::Vector3d(face(rng), face(rng), face(rng));
      // now and then a whole face moves up towards its contactors
      if (!contactor && trial % 7 == 3) u.z() += 0.015;
      model.domain().node(tag).disp.head<3>() = u;
    }
    // The pairs' own tests, and what each should get.
    std::vector<char> expectFar;
    std::vector<double> expectBound;
    for (const Pair& p : model.pairs()) {
      double bound = 0.0;
      const bool isFar = model.farTest(p).isFar(model.translations(p), bound);
      expectFar.push_back(isFar);
      expectBound.push_back(bound);
      if (isFar) {
        // A lower bound of the distance, and a far pair is beyond its search distance.
        const double d = model.sampledDistance(p);
        EXPECT_LE(bound, d + 1e-12) << "trial " << trial;
        EXPECT_GT(d, p.search) << "trial " << trial;
      }
    }
    const long updatesBefore = analysis.elementUpdates();
    const auto result = analysis.checkSleepingPairs();
    int woken = 0;
    for (std::size_t i = 0; i < model.pairs().size(); ++i) {
      const Pair& p = model.pairs()[i];
      if (expectFar[i]) {
        ++far;
        // The trial state of a far pair: open, no force, the bound of its own test as its gap.
        EXPECT_EQ(model.trial(p).gap, expectBound[i]) << "trial " << trial << " pair " << i;
        EXPECT_EQ(model.trial(p).status, contact::ContactStatus::Open);
        EXPECT_TRUE(model.trial(p).force.isZero(0.0));
      } else {
        ++near;
        ++woken;
      }
    }
    // Each near pair woken (updated once), each far one not.
    EXPECT_EQ(analysis.elementUpdates() - updatesBefore, woken) << "trial " << trial;
    EXPECT_EQ(result,
              woken > 0 ? SleepingPairs::Check::PatternChange : SleepingPairs::Check::Unchanged)
        << "trial " << trial;
  }
  // Both verdicts were met often (of 14 pairs x 300 configurations).
  EXPECT_GT(far, 3000);
  EXPECT_GT(near, 300);
}

TEST(SleepingPairsTest, ContactorCrossingTheFaceInOneStepIsWokenAndTheStepRedone) {
  Faces model(1);
  Harness analysis(model);
  ASSERT_EQ(analysis.sleepingPairs(), 6);
  // The contactor above the face's middle (node 11, at (0.5, 0.5), 0.2 m above) moves 0.21 m
  // down in one step: 0.01 m into the face. The other contactors and the face stay at rest, far.
  model.domain().node(11).disp.head<3>() = Eigen::Vector3d(0.0, 0.0, -(kHeight + 0.01));
  EXPECT_EQ(analysis.checkSleepingPairs(), SleepingPairs::Check::RedoStep);
  const auto& s = model.trial(model.pairs()[0]);
  EXPECT_NEAR(s.gap, -0.01, 1e-12);
  EXPECT_GT(s.force(0), 0.0);  // in contact: the step missed its force
  // Only down to 0.04 m above the face: within the search distance, no force: woken for the next
  // step, this one stands.
  model.domain().node(11).disp.head<3>() = Eigen::Vector3d(0.0, 0.0, -(kHeight - 0.04));
  EXPECT_EQ(analysis.checkSleepingPairs(), SleepingPairs::Check::PatternChange);
  // The face rising 0.16 m under contactors that stay put, 0.04 m above its plane now: the four
  // over the face are near (one of them with a search distance of 0.1 m, and one that names the
  // face's nodes in another order) and are woken; the two beyond its edges stay sleeping, since the
  // face's bounding sphere (centre (1, 0.5, 0.16), radius sqrt(1.25) = 1.1180 m) is
  // sqrt(1.2^2 + 0.04^2) - 1.1180 = 0.083 m from (2.2, 0.5, 0.2) and
  // sqrt(1.1^2 + 0.4^2 + 0.04^2) - 1.1180 = 0.053 m from (-0.1, 0.9, 0.2), beyond 0.05 m.
  model.domain().node(11).disp.setZero();
  for (int n = 1; n <= 4; ++n) model.domain().node(n).disp.head<3>() = Eigen::Vector3d(0, 0, 0.16);
  const long before = analysis.elementUpdates();
  EXPECT_EQ(analysis.checkSleepingPairs(), SleepingPairs::Check::PatternChange);
  EXPECT_EQ(analysis.elementUpdates() - before, 4);
  const std::array<double, 2> expected{
      std::sqrt(1.2 * 1.2 + 0.04 * 0.04) - std::sqrt(1.25),
      std::sqrt(1.1 * 1.1 + 0.4 * 0.4 + 0.04 * 0.04) - std::sqrt(1.25)};
  EXPECT_NEAR(model.trial(model.pairs()[3]).gap, expected[0], 1e-12);  // node 14
  EXPECT_NEAR(model.trial(model.pairs()[2]).gap, expected[1], 1e-12);  // node 13
}

/// Reads the responses of the elements it names (so the analysis keeps them up to date).
struct ReadingRecorder final : domain::Recorder {
  std::vector<int> tags;
  void record(const domain::Domain& /*domain*/) override {}
  void flush() override {}
  void elementsRead(std::vector<int>& out) const override {
    out.insert(out.end(), tags.begin(), tags.end());
  }
};

TEST(SleepingPairsTest, DeferredFacesWakeAtTheSameChecksWithFewerTests) {
  // Two copies of the model walked alike: in one the faces' tests may be deferred, in the other
  // every sleeper is tested at every check (as when every pair is observed).
  Faces deferring, testedEachStep;
  Harness a(deferring);
  Harness b(testedEachStep);
  a.beginSteps(false);
  b.beginSteps(true);
  const int neq = a.numEquations();
  ASSERT_EQ(neq, b.numEquations());
  std::mt19937 rng(1124);
  std::normal_distribution<double> jitter(0.0, 0.0002);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(neq);
  int wakes = 0, deferred = 0;
  for (int k = 0; k < 600; ++k) {
    // Faces shake a little; contactors shake, sink towards their faces for 150 checks and rise
    // for 150, twice (so pairs wake, go to sleep beyond twice their distance, and are deferred
    // again).
    for (auto& [tag, node] : deferring.domain().nodes()) {
      const bool contactor = tag % 100 > 10;
      for (int d = 0; d < 3; ++d) {
        const int eq = a.equationOf(tag, d);
        ASSERT_EQ(eq, b.equationOf(tag, d));
        double du = jitter(rng);
        if (contactor && d == 2) du += k % 300 < 150 ? -0.001 : 0.001;
        // now and then one contactor dives at its face, 8 mm a check for 5 checks, and comes back:
        // the motion bound's margin over a straight approach (sqrt(3) x 4) is what it relies on
        if (contactor && d == 2 && tag % 100 == 11 + (k / 40) % 4 && k % 40 < 10)
          du += k % 40 < 5 ? -0.008 : 0.008;
        U(eq) += du;
      }
      // a contactor never goes below 0.01 m above its face's plane (no force: no redone steps)
      const int ez = a.equationOf(tag, 2);
      if (contactor) U(ez) = std::max(U(ez), 0.01 - kHeight);
    }
    const auto ra = a.step(U);
    const auto rb = b.step(U);
    ASSERT_EQ(ra, rb) << "check " << k;
    if (ra == SleepingPairs::Check::PatternChange) ++wakes;
    deferred += a.deferredFaces() > 0 ? 1 : 0;
    EXPECT_EQ(b.deferredFaces(), 0u);
    EXPECT_EQ(a.sleepingPairs(), b.sleepingPairs()) << "check " << k;
  }
  a.endSteps();
  b.endSteps();
  EXPECT_EQ(a.elementUpdates(), b.elementUpdates());
  EXPECT_GT(wakes, 4);       // pairs woke and went to sleep again
  EXPECT_GT(deferred, 100);  // and faces were deferred for many checks
  // about half the tests on this restless walk (every node jitters, contactors dive)
  EXPECT_LT(a.farTests(), 0.7 * static_cast<double>(b.farTests()));
  // After the steps every pair reads as with the test of every step, to the bit.
  for (std::size_t i = 0; i < deferring.pairs().size(); ++i) {
    const auto& sa = deferring.trial(deferring.pairs()[i]);
    const auto& sb = testedEachStep.trial(testedEachStep.pairs()[i]);
    EXPECT_EQ(sa.gap, sb.gap) << "pair " << i;
    EXPECT_EQ(sa.status, sb.status) << "pair " << i;
  }
}

TEST(SleepingPairsTest, PairsOfDeferredFacesAreNotCommittedAndRecordedPairsNeverDeferred) {
  Faces model(1);
  auto reader = std::make_unique<ReadingRecorder>();
  reader->tags = {1005};  // the contactor that names its face's nodes in another order: a run
  model.domain().addRecorder(std::move(reader));
  Harness analysis(model);
  analysis.beginSteps(false);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(analysis.numEquations());
  // A face's test is deferred once its pairs are far in both states (its committed state far, after
  // one check and commit).
  analysis.step(U);
  analysis.step(U);
  // Five pairs against the face as given are deferred; the recorded one, alone in its run, does
  // not.
  EXPECT_EQ(analysis.deferredFaces(), 1u);
  const long tests = analysis.farTests();
  const Pair& first = model.pairs()[0];
  auto* pair = dynamic_cast<NodeToSurfaceContact3d<3>*>(first.element);
  ASSERT_NE(pair, nullptr);
  const double committedGap = pair->committedState().gap;
  // The contactors rise 1 mm a check, the face stays: after k checks the motion bound is
  // sqrt(3) k mm, and the deferred run's horizon, its smallest slack (0.2 m high, search distance
  // 0.1 m for one of its pairs) over the far bound's Lipschitz constant 4, is reached at
  // 0.025 / (sqrt(3) 1e-3) = 14.4 checks. Until then only the recorded pair is tested, and the
  // deferred pairs' committed gaps stay as they were although their trial gaps would change.
  const int expectedAlone =
      static_cast<int>(std::ceil((kHeight - 2.0 * kSearch) / 4.0 / (std::sqrt(3.0) * 1e-3))) - 1;
  int checksAlone = 0;
  for (int k = 0; k < 30; ++k) {
    for (const auto& [tag, node] : model.domain().nodes())
      if (tag % 100 > 10) U(analysis.equationOf(tag, 2)) = 0.001 * (k + 1);
    const long before = analysis.farTests();
    analysis.step(U);
    EXPECT_EQ(pair->committedState().gap, committedGap) << "a deferred pair is not committed";
    if (analysis.farTests() - before > 1) {  // the horizon: the run's five pairs and the recorded
      EXPECT_EQ(analysis.farTests() - before, 6);
      break;
    }
    ++checksAlone;  // the recorded pair alone
  }
  EXPECT_EQ(checksAlone, expectedAlone);
  EXPECT_EQ(analysis.deferredFaces(), 1u);  // far still: deferred again
  EXPECT_GT(analysis.farTests(), tests);
  // At the end its gap is its own test's bound at the committed positions.
  analysis.endSteps();
  double bound = 0.0;
  ASSERT_TRUE(model.farTest(first).isFar(model.translations(first), bound));
  EXPECT_EQ(pair->committedState().gap, bound);
  EXPECT_EQ(pair->trialState().gap, bound);
  EXPECT_EQ(analysis.deferredFaces(), 0u);
}

}  // namespace
}  // namespace dabs::analysis
