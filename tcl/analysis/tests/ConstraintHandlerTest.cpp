// SPDX-License-Identifier: MIT
// Which node dofs become equations under each constraint handler, and what the others are made
// of: fixes and pattern supports as prescribed slots, equalDOF (and chains of it) as the retained
// dof's equation, penalty rows alpha (u_c - u_r) under Penalty, and the errors for constraints a
// handler cannot enforce.
#include "tcl/analysis/model/ConstraintHandler.h"

#include <gtest/gtest.h>

#include <memory>

#include "materials/InputError.h"
#include "tcl/domain/ConstantSeries.h"

namespace dabs::analysis {
namespace {

/// Nodes 1..count with ndf dofs each, in tag order, and the node index the handler needs.
struct Model {
  domain::Domain domain;
  std::vector<NodeDofs> nodes;
  std::map<int, int> index;
  Model(int count, int ndf) {
    for (int t = 1; t <= count; ++t) domain.addNode(t, 2, ndf, Eigen::Vector3d::Zero());
  }
  void addEqualDof(int retained, int constrained, int dof) {
    domain.addMP(
        domain::MPConstraint{retained, constrained, {dof}, {dof}, Eigen::MatrixXd::Identity(1, 1)});
  }
  DofMap apply(ConstraintKind kind, double alphaSP = 0.0, double alphaMP = 0.0) {
    nodes.clear();
    index.clear();
    int first = 0;
    for (auto& [tag, node] : domain.nodes()) {
      index[tag] = static_cast<int>(nodes.size());
      nodes.push_back(NodeDofs{&node, first});
      first += node.ndf();
    }
    std::vector<int> order(nodes.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
    return ConstraintHandler(kind, alphaSP, alphaMP).apply(domain, nodes, index, order);
  }
};

TEST(ConstraintHandlerTest, FixedDofsArePrescribedSlotsAndTheRestEquationsInNodeOrder) {
  Model m(3, 2);
  m.domain.addFix(1, 0);
  m.domain.addFix(1, 1);
  m.domain.addFix(3, 1);
  const DofMap map = m.apply(ConstraintKind::Plain);
  EXPECT_EQ(map.numEquations, 3);
  EXPECT_EQ(map.directEq, (std::vector<int>{-1, -1, 0, 1, 2, -1}));
  ASSERT_EQ(map.slots.size(), 3u);
  EXPECT_EQ(map.dofTerms[5].size(), 1u);
  EXPECT_EQ(map.dofTerms[5][0].index, -3);  // slot 2 (the third fix)
  EXPECT_EQ(map.eqDof[2].second, 0);        // equation 2 is node 3, dof 0
  EXPECT_EQ(map.eqDof[2].first, m.nodes[2].node);
  EXPECT_TRUE(map.penalties.empty());
  EXPECT_FALSE(map.imposedMotion);
}

TEST(ConstraintHandlerTest, PatternSupportsFollowTheFixesInPatternOrder) {
  Model m(2, 1);
  m.domain.addFix(1, 0);
  auto p = std::make_unique<domain::PlainPattern>(
      7, std::make_shared<domain::ConstantSeries>(1, 1.0), 1.0);
  p->prescribed.push_back({2, 0, 0.25, false});
  m.domain.addPattern(std::move(p));
  const DofMap map = m.apply(ConstraintKind::Transformation);
  EXPECT_EQ(map.numEquations, 0);
  EXPECT_EQ(map.patternSlots, (std::vector<int>{1}));
  EXPECT_EQ(map.slots[1].node, 2);
}

TEST(ConstraintHandlerTest, TwoSupportsOnOneDofAreRejected) {
  Model m(1, 1);
  m.domain.addFix(1, 0);
  auto p = std::make_unique<domain::PlainPattern>(
      7, std::make_shared<domain::ConstantSeries>(1, 1.0), 1.0);
  p->prescribed.push_back({1, 0, 0.25, false});
  m.domain.addPattern(std::move(p));
  EXPECT_THROW(m.apply(ConstraintKind::Plain), InputError);
}

TEST(ConstraintHandlerTest, EqualDofChainsResolveToTheLastRetainedEquation) {
  // Node 3 dof 0 follows node 2, which follows node 1: both are node 1's equation.
  Model m(3, 2);
  m.addEqualDof(1, 2, 0);
  m.addEqualDof(2, 3, 0);
  const DofMap map = m.apply(ConstraintKind::Transformation);
  EXPECT_EQ(map.numEquations, 4);  // 6 dofs less the 2 constrained
  const int eq = map.directEq[0];
  ASSERT_GE(eq, 0);
  EXPECT_EQ(map.directEq[2], eq);  // node 2 dof 0
  EXPECT_EQ(map.directEq[4], eq);  // node 3 dof 0
}

TEST(ConstraintHandlerTest, RigidLinkCoefficientsCarryIntoTheTerms) {
  // u_2,0 = u_1,0 - 2 u_1,1 (a rotation times an arm, linearised): two terms.
  Model m(2, 2);
  Eigen::MatrixXd C(1, 2);
  C << 1.0, -2.0;
  m.domain.addMP(domain::MPConstraint{1, 2, {0}, {0, 1}, C});
  const DofMap map = m.apply(ConstraintKind::Transformation);
  const auto& terms = map.dofTerms[2];
  ASSERT_EQ(terms.size(), 2u);
  EXPECT_EQ(terms[0].index, map.directEq[0]);
  EXPECT_DOUBLE_EQ(terms[0].coef, 1.0);
  EXPECT_EQ(terms[1].index, map.directEq[1]);
  EXPECT_DOUBLE_EQ(terms[1].coef, -2.0);
  EXPECT_EQ(map.directEq[2], -1);  // a combination, not one equation
}

TEST(ConstraintHandlerTest, ConstraintCycleAndPlainHandlerWithConstraintsAreRejected) {
  Model cycle(2, 1);
  cycle.addEqualDof(1, 2, 0);
  cycle.addEqualDof(2, 1, 0);
  EXPECT_THROW(cycle.apply(ConstraintKind::Transformation), InputError);
  Model plain(2, 1);
  plain.addEqualDof(1, 2, 0);
  EXPECT_THROW(plain.apply(ConstraintKind::Plain), InputError);
}

TEST(ConstraintHandlerTest, PenaltyKeepsEveryDofAndAddsOneRowPerConstraint) {
  Model m(2, 1);
  m.domain.addFix(1, 0);
  m.addEqualDof(1, 2, 0);
  const DofMap map = m.apply(ConstraintKind::Penalty, 1e10, 1e8);
  EXPECT_EQ(map.numEquations, 2);
  ASSERT_EQ(map.penalties.size(), 2u);
  const PenaltyRow& sp = map.penalties[0];  // alpha (u_1 - 0)
  EXPECT_EQ(sp.slot, 0);
  EXPECT_DOUBLE_EQ(sp.alpha, 1e10);
  ASSERT_EQ(sp.eqs.size(), 1u);
  EXPECT_EQ(sp.eqs[0].first, map.directEq[0]);
  const PenaltyRow& mp = map.penalties[1];  // alpha (u_2 - u_1)
  EXPECT_DOUBLE_EQ(mp.alpha, 1e8);
  ASSERT_EQ(mp.eqs.size(), 2u);
  EXPECT_EQ(mp.eqs[0], (std::pair<int, double>{map.directEq[1], 1.0}));
  EXPECT_EQ(mp.eqs[1], (std::pair<int, double>{map.directEq[0], -1.0}));
}

}  // namespace
}  // namespace dabs::analysis
