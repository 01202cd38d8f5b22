// SPDX-License-Identifier: MIT
// The node order of the numberers: Plain keeps the tag order; reverse Cuthill-McKee numbers a
// path given in scrambled order along the path (band width 1) and each component of a
// disconnected graph as a block.
#include "tcl/analysis/model/DofNumberer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace dabs::analysis {
namespace {

DofNumberer::Graph graphOf(int n, const std::vector<std::pair<int, int>>& edges) {
  DofNumberer::Graph g(static_cast<std::size_t>(n));
  for (auto [a, b] : edges) {
    g[static_cast<std::size_t>(a)].insert(b);
    g[static_cast<std::size_t>(b)].insert(a);
  }
  return g;
}

/// Largest difference of the positions in `order` of two linked nodes.
int bandwidth(const DofNumberer::Graph& g, const std::vector<int>& order) {
  std::vector<int> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    position[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  int band = 0;
  for (std::size_t a = 0; a < g.size(); ++a)
    for (int b : g[a])
      band = std::max(band, std::abs(position[a] - position[static_cast<std::size_t>(b)]));
  return band;
}

TEST(DofNumbererTest, PlainKeepsTheIndexOrder) {
  const auto g = graphOf(4, {{0, 3}, {3, 1}, {1, 2}});
  EXPECT_EQ(DofNumberer(NumbererKind::Plain).order(g), (std::vector<int>{0, 1, 2, 3}));
}

TEST(DofNumbererTest, RcmNumbersAScrambledPathAlongThePath) {
  // The path 4-0-6-2-5-1-3 given with scrambled indices: its band width is 1 in path order and
  // 6 in index order.
  const auto g = graphOf(7, {{4, 0}, {0, 6}, {6, 2}, {2, 5}, {5, 1}, {1, 3}});
  EXPECT_GT(bandwidth(g, DofNumberer(NumbererKind::Plain).order(g)), 1);
  const std::vector<int> order = DofNumberer(NumbererKind::RCM).order(g);
  EXPECT_EQ(bandwidth(g, order), 1);
  // Breadth first from the end of least degree with the lower index (3), then reversed.
  EXPECT_EQ(order, (std::vector<int>{4, 0, 6, 2, 5, 1, 3}));
}

TEST(DofNumbererTest, RcmNumbersEveryNodeOfDisconnectedComponentsOnce) {
  // Two triangles and an isolated node.
  const auto g = graphOf(7, {{0, 2}, {2, 4}, {4, 0}, {1, 3}, {3, 5}, {5, 1}});
  std::vector<int> order = DofNumberer(NumbererKind::RCM).order(g);
  ASSERT_EQ(order.size(), 7u);
  EXPECT_EQ(bandwidth(g, order), 2);  // each triangle's three nodes are consecutive
  std::sort(order.begin(), order.end());
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
}

}  // namespace
}  // namespace dabs::analysis
