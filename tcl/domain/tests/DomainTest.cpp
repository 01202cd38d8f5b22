// SPDX-License-Identifier: MIT
// The domain's promise that a rejected change leaves the model exactly as it was: for every
// mutator that can reject its input, each way it rejects leaves the model's observable state (a
// snapshot of what the public interface shows) unchanged, and an accepted call does change the
// part of the snapshot it should, so the snapshot cannot be blind to that change.
#include "tcl/domain/Domain.h"

#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "elements/link/Truss.h"
#include "materials/Elastic.h"
#include "materials/InputError.h"
#include "tcl/domain/LinearSeries.h"

namespace dabs::domain {
namespace {

/// What the domain shows through its public interface, as plain values that compare exactly.
struct Snapshot {
  struct NodeRow {
    int tag = 0, ndm = 0, ndf = 0;
    std::array<double, 3> coords{};
    std::vector<double> mass;
    double alphaM = 0.0;
    bool operator==(const NodeRow&) const = default;
  };
  struct ElementRow {
    int tag = 0;
    std::string type;
    std::vector<int> nodes;
    std::array<double, 4> rayleigh{};
    bool operator==(const ElementRow&) const = default;
  };
  struct MPRow {
    int retained = 0, constrained = 0;
    std::vector<int> constrainedDofs, retainedDofs;
    std::vector<double> Ccr;
    bool operator==(const MPRow&) const = default;
  };
  std::vector<NodeRow> nodes;
  std::vector<ElementRow> elements;
  std::vector<std::pair<int, int>> fixes;
  std::vector<MPRow> mps;
  std::vector<std::pair<int, bool>> patterns;  ///< tag, frozen by loadConst
  std::vector<int> recordedElements;
  double time = 0.0, committedTime = 0.0;
  long modelVersion = 0;
  bool operator==(const Snapshot&) const = default;
};

// A readable summary when a comparison fails, instead of gtest's byte dump.
void PrintTo(const Snapshot& s, std::ostream* os) {
  *os << "{" << s.nodes.size() << " nodes, " << s.elements.size() << " elements, " << s.fixes.size()
      << " fixes, " << s.mps.size() << " mps, " << s.patterns.size() << " patterns, "
      << s.recordedElements.size() << " recorded elements, time " << s.time << ", committed "
      << s.committedTime << ", version " << s.modelVersion << "}";
}

Snapshot snapshot(const Domain& d) {
  Snapshot s;
  for (const auto& [tag, n] : d.nodes()) {
    const Eigen::MatrixXd& m = n.mass();
    s.nodes.push_back({tag,
                       n.ndm(),
                       n.ndf(),
                       {n.coords().x(), n.coords().y(), n.coords().z()},
                       std::vector<double>(m.data(), m.data() + m.size()),
                       d.nodeAlphaM(tag)});
  }
  for (const auto& [tag, e] : d.elements()) {
    const RayleighFactors r = d.elementRayleigh(tag);
    s.elements.push_back(
        {tag, std::string(e->typeName()), e->nodeTags(), {r.alphaM, r.betaK, r.betaK0, r.betaKc}});
  }
  for (const SPConstraint& sp : d.fixes()) s.fixes.emplace_back(sp.node, sp.dof);
  for (const MPConstraint& mp : d.mps())
    s.mps.push_back({mp.retainedNode, mp.constrainedNode, mp.constrainedDofs, mp.retainedDofs,
                     std::vector<double>(mp.Ccr.data(), mp.Ccr.data() + mp.Ccr.size())});
  for (const auto& [tag, p] : d.patterns()) s.patterns.emplace_back(tag, p->isConstant());
  s.recordedElements = d.recordedElements();
  s.time = d.time();
  s.committedTime = d.committedTime();
  s.modelVersion = d.modelVersion();
  return s;
}

/// Reads the responses of some elements; like the element recorders, it refuses unknown tags.
struct ElementReader final : Recorder {
  std::vector<int> tags;
  explicit ElementReader(std::vector<int> t) : tags(std::move(t)) {}
  void initialize(const Domain& d) override {
    for (int t : tags)
      if (d.findElement(t) == nullptr) throw InputError("-ele", std::to_string(t) + " is unknown");
  }
  void record(const Domain& /*domain*/) override {}
  void flush() override {}
  void elementsRead(std::vector<int>& out) const override {
    out.insert(out.end(), tags.begin(), tags.end());
  }
};

std::unique_ptr<elements::Element> truss(int tag, int i, int j) {
  elements::Truss::Params p;
  p.nodes = {i, j};
  p.ndm = 2;
  p.ndf = 2;
  p.area = 1.0;
  p.doRayleigh = true;  // so that the Rayleigh factors show in the snapshot
  materials::Elastic::Params m;
  m.E = 200.0;
  return std::make_unique<elements::Truss>(tag, p, std::make_unique<materials::Elastic>(1, m));
}

MPConstraint equalDof(int retained, int constrained, std::vector<int> dofs) {
  const auto n = static_cast<Eigen::Index>(dofs.size());
  return {retained, constrained, dofs, dofs, Eigen::MatrixXd::Identity(n, n)};
}

std::unique_ptr<PlainPattern> plain(int tag) {
  return std::make_unique<PlainPattern>(tag, std::make_shared<LinearSeries>(1, 1.0), 1.0);
}

/// A small 2D model with something of every kind, each node in a role a rejection checks:
/// 1-2-3 carry trusses 1 and 2, 1 fixed; 4 is tied to 2 by an equalDOF; 5 is loaded by pattern 1
/// and fixed in x; 6 coincides with 1; 7 has 3 dofs (a truss here needs 2), fixed in rotation.
void buildModel(Domain& d) {
  d.addNode(1, 2, 2, {0, 0, 0});
  d.addNode(2, 2, 2, {4, 0, 0});
  d.addNode(3, 2, 2, {4, 3, 0});
  d.addNode(4, 2, 2, {8, 0, 0});
  d.addNode(5, 2, 2, {0, 3, 0});
  d.addNode(6, 2, 2, {0, 0, 0});
  d.addNode(7, 2, 3, {8, 3, 0});
  d.node(2).setMass(Eigen::MatrixXd::Identity(2, 2));
  d.addElement(truss(1, 1, 2));
  d.addElement(truss(2, 2, 3));
  d.addFix(1, 0);
  d.addFix(1, 1);
  d.addFix(5, 0);
  d.addFix(7, 2);
  d.addMP(equalDof(2, 4, {0, 1}));
  auto p = plain(1);
  p->loads.push_back({5, Eigen::Vector2d(0.0, -1.0)});
  d.addPattern(std::move(p));
  d.setRayleigh({0.1, 0.002, 0.0, 0.0});
  d.addRecorder(std::make_unique<ElementReader>(std::vector<int>{1}));
  d.setCommittedTime(0.5);
}

/// Makes the change, which must be rejected with InputError, and checks nothing changed.
template <class Change>
void expectRejected(Domain& d, const char* what, Change change) {
  SCOPED_TRACE(what);
  const Snapshot before = snapshot(d);
  EXPECT_THROW(change(), InputError);
  EXPECT_EQ(snapshot(d), before);
}

/// Makes the change, which must be accepted, and checks it changed `field` of the snapshot.
template <class Change, class Field>
void expectChanges(Domain& d, Field Snapshot::*field, Change change) {
  const Snapshot before = snapshot(d);
  change();
  EXPECT_FALSE(snapshot(d).*field == before.*field);
}

TEST(DomainTest, RejectedAddNodeLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  // A taken tag must not move the node that has it.
  expectRejected(d, "taken tag", [&] { d.addNode(1, 2, 2, {9, 9, 0}); });
  expectRejected(d, "ndf 0", [&] { d.addNode(8, 2, 0, {9, 9, 0}); });
  expectRejected(d, "ndf 7", [&] { d.addNode(8, 2, 7, {9, 9, 0}); });
}

TEST(DomainTest, AcceptedAddNodeChangesTheNodes) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::nodes, [&] { d.addNode(8, 2, 2, {9, 9, 0}); });
}

TEST(DomainTest, RejectedAddElementLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "no element", [&] { d.addElement(nullptr); });
  expectRejected(d, "taken tag", [&] { d.addElement(truss(1, 2, 3)); });
  expectRejected(d, "missing node", [&] { d.addElement(truss(3, 1, 99)); });
  expectRejected(d, "ndf mismatch", [&] { d.addElement(truss(3, 3, 7)); });
  // The geometry is checked last (Element::initialize), after every other check passed.
  expectRejected(d, "zero length", [&] { d.addElement(truss(3, 1, 6)); });
}

TEST(DomainTest, AcceptedAddElementChangesTheElements) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::elements, [&] { d.addElement(truss(3, 1, 3)); });
}

TEST(DomainTest, RejectedRemoveElementLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown tag", [&] { d.removeElement(99); });
  auto p = plain(2);
  p->memberLoads.push_back({1, elements::BeamLoad{}});
  d.addPattern(std::move(p));
  // Its Rayleigh factors in particular must survive: they are erased with the element.
  expectRejected(d, "loaded by a pattern", [&] { d.removeElement(1); });
}

TEST(DomainTest, AcceptedRemoveElementChangesTheElements) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::elements, [&] { d.removeElement(2); });
}

TEST(DomainTest, RejectedRemoveNodeLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown tag", [&] { d.removeNode(99); });
  expectRejected(d, "used by an element", [&] { d.removeNode(1); });
  expectRejected(d, "used by an equalDOF", [&] { d.removeNode(4); });
  // Node 5 is fixed too: its fix goes with it only when the removal is accepted.
  expectRejected(d, "loaded by a pattern", [&] { d.removeNode(5); });
  // The fix kept is a real one, not just a row: fixing the dof again is still refused.
  EXPECT_THROW(d.addFix(5, 0), InputError);
}

TEST(DomainTest, AcceptedRemoveNodeChangesTheNodesAndDropsItsFixes) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::nodes, [&] { d.removeNode(7); });
  EXPECT_EQ(snapshot(d).fixes, (std::vector<std::pair<int, int>>{{1, 0}, {1, 1}, {5, 0}}));
}

TEST(DomainTest, RejectedAddFixLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown node", [&] { d.addFix(99, 0); });
  expectRejected(d, "dof below range", [&] { d.addFix(3, -1); });
  expectRejected(d, "dof above range", [&] { d.addFix(3, 2); });
  expectRejected(d, "already fixed", [&] { d.addFix(1, 0); });
  expectRejected(d, "constrained by an equalDOF", [&] { d.addFix(4, 0); });
}

TEST(DomainTest, AcceptedAddFixChangesTheFixes) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::fixes, [&] { d.addFix(3, 1); });
}

TEST(DomainTest, RejectedAddMPLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown retained node", [&] { d.addMP(equalDof(99, 3, {0})); });
  expectRejected(d, "unknown constrained node", [&] { d.addMP(equalDof(3, 99, {0})); });
  expectRejected(d, "same node", [&] { d.addMP(equalDof(3, 3, {0})); });
  expectRejected(d, "matrix does not match the dofs", [&] {
    MPConstraint mp = equalDof(2, 3, {0, 1});
    mp.Ccr = Eigen::MatrixXd::Identity(1, 2);
    d.addMP(std::move(mp));
  });
  // The valid first dof comes before the bad one: it must not be held as constrained either.
  expectRejected(d, "constrained dof out of range", [&] { d.addMP(equalDof(2, 3, {1, 2})); });
  expectRejected(d, "constrained dof fixed", [&] { d.addMP(equalDof(2, 5, {1, 0})); });
  expectRejected(d, "constrained dof already constrained", [&] { d.addMP(equalDof(2, 4, {0})); });
  expectRejected(d, "retained dof out of range", [&] {
    MPConstraint mp = equalDof(2, 3, {1});
    mp.retainedDofs = {5};
    d.addMP(std::move(mp));
  });
  // None of the rejected constraints holds its constrained dofs: they can still be fixed.
  EXPECT_NO_THROW(d.addFix(3, 1));
  EXPECT_NO_THROW(d.addFix(5, 1));
}

TEST(DomainTest, AcceptedAddMPChangesTheMPs) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::mps, [&] { d.addMP(equalDof(3, 6, {0})); });
}

TEST(DomainTest, RemoveFixThatMatchesNoFixReturnsZeroAndLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  const Snapshot before = snapshot(d);
  EXPECT_EQ(d.removeFix(99, -1), 0);  // unknown node
  EXPECT_EQ(d.removeFix(3, -1), 0);   // a node without fixes
  EXPECT_EQ(d.removeFix(5, 1), 0);    // a free dof of a fixed node
  // Not even the model version moves, so the analysis keeps its numbering.
  EXPECT_EQ(snapshot(d), before);
}

TEST(DomainTest, AcceptedRemoveFixChangesTheFixes) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::fixes, [&] { EXPECT_EQ(d.removeFix(1, -1), 2); });
}

TEST(DomainTest, RejectedAddPatternLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  // The rejected pattern loads node 3; pattern 1, which has the tag, must keep loading node 5.
  auto p = plain(1);
  p->loads.push_back({3, Eigen::Vector2d(1.0, 0.0)});
  expectRejected(d, "taken tag", [&] { d.addPattern(std::move(p)); });
  EXPECT_TRUE(d.nodalLoad(3).isZero());
  EXPECT_EQ(d.nodalLoad(5)(1), -0.5);  // factor t = 0.5
}

TEST(DomainTest, AcceptedAddPatternChangesThePatterns) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::patterns, [&] { d.addPattern(plain(2)); });
}

TEST(DomainTest, RejectedRemovePatternLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown tag", [&] { d.removePattern(99); });
}

TEST(DomainTest, AcceptedRemovePatternChangesThePatterns) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::patterns, [&] { d.removePattern(1); });
}

TEST(DomainTest, RejectedAddRecorderLeavesTheModelUnchangedAndTakesNoTag) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown element", [&] {
    d.addRecorder(std::make_unique<ElementReader>(std::vector<int>{2, 99}));
  });
  // Tags follow the order of addition: the rejected recorder must not have used up tag 1.
  EXPECT_EQ(d.addRecorder(std::make_unique<ElementReader>(std::vector<int>{})), 1);
}

TEST(DomainTest, AcceptedAddRecorderChangesTheRecordedElements) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::recordedElements,
                [&] { d.addRecorder(std::make_unique<ElementReader>(std::vector<int>{2})); });
}

TEST(DomainTest, RejectedRemoveRecorderLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  expectRejected(d, "unknown tag", [&] { d.removeRecorder(99); });
}

TEST(DomainTest, AcceptedRemoveRecorderChangesTheRecordedElements) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::recordedElements, [&] { d.removeRecorder(0); });
}

/// Adds a pattern with a member load on truss 1, which takes none: applying the patterns' member
/// loads (setTime and the reverts) then throws. The eleLoad command refuses such a load, so only
/// C++ code that fills a pattern itself can build this.
void loadTrussWithAMemberLoad(Domain& d) {
  auto p = plain(2);
  p->memberLoads.push_back({1, elements::BeamLoad{}});
  d.addPattern(std::move(p));
}

TEST(DomainTest, RejectedSetTimeLeavesTheModelUnchanged) {
  // setTime applies the patterns' member loads at the new time before it takes the time, and an
  // element that refuses its load leaves the loads as they were and the time at 0.5.
  Domain d;
  buildModel(d);
  loadTrussWithAMemberLoad(d);
  expectRejected(d, "element takes no member loads", [&] { d.setTime(2.0); });
}

TEST(DomainTest, RejectedSetCommittedTimeLeavesTheModelUnchanged) {
  // The same for setCommittedTime: time() and committedTime() both stay.
  Domain d;
  buildModel(d);
  loadTrussWithAMemberLoad(d);
  expectRejected(d, "element takes no member loads", [&] { d.setCommittedTime(2.0); });
}

TEST(DomainTest, AcceptedSetTimeChangesTheTime) {
  Domain d;
  buildModel(d);
  expectChanges(d, &Snapshot::time, [&] { d.setTime(2.0); });
  expectChanges(d, &Snapshot::committedTime, [&] { d.setCommittedTime(3.0); });
}

TEST(DomainTest, RejectedRevertLeavesTheModelUnchanged) {
  Domain d;
  buildModel(d);
  loadTrussWithAMemberLoad(d);
  // The reverts apply the member loads first, before they touch the time or the nodes.
  expectRejected(d, "revertToLastCommit", [&] { d.revertToLastCommit(); });
  expectRejected(d, "revertToStart", [&] { d.revertToStart(); });
}

TEST(DomainTest, AcceptedRevertChangesTheTime) {
  Domain d;
  buildModel(d);
  d.setTime(2.0);
  expectChanges(d, &Snapshot::time, [&] { d.revertToLastCommit(); });
  expectChanges(d, &Snapshot::committedTime, [&] { d.revertToStart(); });
}

}  // namespace
}  // namespace dabs::domain
