// SPDX-License-Identifier: MIT
// The motion bound of contact faces whose test is deferred: for nodes whose translations are
// combinations of equations and support slots (a free dof, an equalDOF, a rigid link's lever arms,
// an imposed support motion), the bound is never below how far a node actually moved since the
// snapshot (the displacement formed from the terms directly, on random changes), it is sqrt(3)
// times the change for a node that moves along one free dof, a non-finite change gives no bound,
// and a snapshot is carried over a rebuild only when the terms are the same.
#include "tcl/analysis/model/MotionBound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace dabs::analysis {
namespace {

/// A node's three translations, each a list of terms.
using NodeTerms = std::vector<std::vector<DofTerm>>;

Eigen::Vector3d translation(const NodeTerms& node, const Eigen::VectorXd& U,
                            const std::vector<SupportSlot>& slots) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int d = 0; d < 3; ++d)
    for (const DofTerm& t : node[static_cast<std::size_t>(d)])
      x(d) +=
          t.coef * (t.index >= 0 ? U(t.index) : slots[static_cast<std::size_t>(-t.index - 1)].disp);
  return x;
}

TEST(MotionBoundTest, BoundIsNeverBelowTheMotionOfAnyNode) {
  // Equations 0..8: a centre node's translations (0..2) and rotations (3..5), a free node (6..8).
  // Slot 0: an imposed support motion.
  std::vector<NodeTerms> nodes;
  nodes.push_back({{{6, 1.0}}, {{7, 1.0}}, {{8, 1.0}}});  // free node
  // rigid link at lever r = (2, -7.5, 1) from the centre: u + theta x r
  nodes.push_back({{{0, 1.0}, {4, 1.0}, {5, 7.5}},                   // ux + ty rz - tz ry
                   {{1, 1.0}, {5, 2.0}, {3, -1.0}},                  // uy + tz rx - tx rz
                   {{2, 1.0}, {3, -7.5}, {4, -2.0}}});               // uz + tx ry - ty rx
  nodes.push_back({{{0, 1.0}}, {{1, 1.0}}, {{-1, 1.0}, {2, 0.5}}});  // equalDOF, a support
  MotionBound watch;
  watch.beginGroup();
  for (const NodeTerms& n : nodes)
    for (const auto& t : n) watch.addTranslation(t);
  watch.endGroup();
  std::mt19937 rng(7);
  std::normal_distribution<double> change(0.0, 0.01);
  Eigen::VectorXd U = Eigen::VectorXd::Zero(9);
  std::vector<SupportSlot> slots(1);
  watch.snapshot(0, U, slots);
  std::vector<Eigen::Vector3d> at;
  for (const NodeTerms& n : nodes) at.push_back(translation(n, U, slots));
  double tightest = 0.0;
  for (int k = 0; k < 1000; ++k) {
    for (int i = 0; i < 9; ++i) U(i) += change(rng);
    slots[0].disp += change(rng);
    double actual = 0.0;
    for (std::size_t j = 0; j < nodes.size(); ++j)
      actual = std::max(actual, (translation(nodes[j], U, slots) - at[j]).norm());
    const double bound = watch.moved(0, U, slots);
    ASSERT_GE(bound, actual) << "step " << k;
    tightest = std::max(tightest, actual / bound);
    if (k % 100 == 99) {  // a new snapshot now and then
      watch.snapshot(0, U, slots);
      for (std::size_t j = 0; j < nodes.size(); ++j) at[j] = translation(nodes[j], U, slots);
    }
  }
  EXPECT_GT(tightest, 0.05);  // and not a useless bound
}

TEST(MotionBoundTest, OneFreeDofGivesSqrtThreeTimesItsChangeAndNonFiniteGivesNoBound) {
  MotionBound watch;
  watch.beginGroup();
  for (int eq = 0; eq < 3; ++eq) watch.addEquation(eq);
  watch.endGroup();
  Eigen::VectorXd U = Eigen::VectorXd::Zero(3);
  const std::vector<SupportSlot> slots;
  watch.snapshot(0, U, slots);
  U(1) = -0.004;
  // (less than 1e-9 above: the margin for the round-off of the sums)
  EXPECT_NEAR(watch.moved(0, U, slots), std::sqrt(3.0) * 0.004, 1e-11);
  U(2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(watch.moved(0, U, slots), std::numeric_limits<double>::infinity());
}

TEST(MotionBoundTest, SnapshotCarriedOnlyToTheSameTerms) {
  MotionBound watch;
  watch.beginGroup();
  watch.addEquation(4);
  watch.addEquation(2);
  watch.endGroup();
  Eigen::VectorXd U = Eigen::VectorXd::Constant(6, 1.0);
  const std::vector<SupportSlot> slots;
  watch.snapshot(0, U, slots);
  const MotionBound::Saved saved = watch.save(0);
  MotionBound same;
  same.beginGroup();
  same.addEquation(2);
  same.addEquation(4);
  same.endGroup();
  ASSERT_TRUE(same.restore(0, saved));
  U(4) = 1.5;
  EXPECT_NEAR(same.moved(0, U, slots), std::sqrt(3.0) * 0.5, 1e-9);
  MotionBound other;
  other.beginGroup();
  other.addEquation(3);
  other.endGroup();
  EXPECT_FALSE(other.restore(0, saved));
}

}  // namespace
}  // namespace dabs::analysis
