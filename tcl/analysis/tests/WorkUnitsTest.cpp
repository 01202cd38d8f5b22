// SPDX-License-Identifier: MIT
// The threads' lists of element updates: every item in exactly one list, each list in ascending
// order, heavy items dealt out first (the longest-processing-time rule), and on the 10-span
// benchmark bridge's costs (11 fiber piers among 80 light elements, in the model's order: girders
// first) the longest of two lists within one light element of the even split, where chunks of
// four elements in the model's order taken first come, first served leave seven piers to one
// thread.
#include "tcl/analysis/model/WorkUnits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

namespace dabs::analysis {
namespace {

/// Finish time of a list schedule: each unit, in order, goes to the thread free first (what
/// OpenMP's dynamic schedule does when unit costs are the times).
double finishTime(const std::vector<std::vector<int>>& units, const std::vector<double>& costs,
                  int threads) {
  std::vector<double> busy(static_cast<std::size_t>(threads), 0.0);
  for (const auto& u : units) {
    double cost = 0.0;
    for (int k : u) cost += costs[static_cast<std::size_t>(k)];
    *std::min_element(busy.begin(), busy.end()) += cost;
  }
  return *std::max_element(busy.begin(), busy.end());
}

std::vector<std::vector<int>> unitsOf(const WorkUnits& w) {
  std::vector<std::vector<int>> units;
  for (int u = 0; u < w.size(); ++u) units.emplace_back(w.unit(u).begin(), w.unit(u).end());
  return units;
}

/// The 10-span bridge's elements in tag order: 40 girder elements, 11 piers, 29 bearings and gaps.
std::vector<double> bridgeCosts(double pier, double light) {
  std::vector<double> costs(40, light);
  costs.insert(costs.end(), 11, pier);
  costs.insert(costs.end(), 29, light);
  return costs;
}

TEST(WorkUnitsTest, EveryItemIsInExactlyOneListInAscendingOrder) {
  const std::vector<double> costs = {3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0, 5.0, 3.0, 5.0};
  for (int threads : {1, 2, 3, 8, 20}) {
    WorkUnits w;
    w.form(costs, threads);
    ASSERT_EQ(w.size(), threads);
    std::vector<int> seen;
    for (const auto& u : unitsOf(w)) {
      EXPECT_TRUE(std::is_sorted(u.begin(), u.end()));
      seen.insert(seen.end(), u.begin(), u.end());
    }
    std::sort(seen.begin(), seen.end());
    std::vector<int> all(costs.size());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(seen, all) << threads << " threads";
  }
}

TEST(WorkUnitsTest, HeaviestItemsAreDealtOutInTurn) {
  // The longest-processing-time rule worked by hand: items by cost (equal costs by index)
  // 5(9) 7(6) 4(5) 8(5) 10(5) 2(4) 0(3) 9(3) 6(2) 1(1) 3(1), each to the list with the least
  // load (the first of equal loads); loads 9|0, 9|6, 9|11, 14|11, 14|16, 18|16, 18|19, 21|19,
  // 21|21, 22|21, 22|22.
  const std::vector<double> costs = {3.0, 1.0, 4.0, 1.0, 5.0, 9.0, 2.0, 6.0, 5.0, 3.0, 5.0};
  WorkUnits w;
  w.form(costs, 2);
  EXPECT_EQ(unitsOf(w)[0], (std::vector<int>{1, 2, 5, 8, 9}));
  EXPECT_EQ(unitsOf(w)[1], (std::vector<int>{0, 3, 4, 6, 7, 10}));
}

TEST(WorkUnitsTest, TwoThreadsShareTheBridgeWithinOneLightElementOfTheEvenSplit) {
  const std::vector<double> costs = bridgeCosts(1700.0, 25.0);
  const double total = std::accumulate(costs.begin(), costs.end(), 0.0);
  WorkUnits w;
  w.form(costs, 2);
  const auto lists = unitsOf(w);
  ASSERT_EQ(lists.size(), 2u);
  // The piers alternate: 6 and 5.
  auto piers = [](const std::vector<int>& l) {
    return std::count_if(l.begin(), l.end(), [](int k) { return k >= 40 && k < 51; });
  };
  EXPECT_EQ(piers(lists[0]), 6);
  EXPECT_EQ(piers(lists[1]), 5);
  // Each list's total: the list with 6 piers (10,200) below half the total (10,350), the other
  // filled with light elements to within one of it.
  EXPECT_LE(finishTime({lists[0]}, costs, 1), total / 2.0 + 25.0);
  EXPECT_LE(finishTime({lists[1]}, costs, 1), total / 2.0 + 25.0);
  // Chunks of four in the model's order, first come, first served: one thread takes two chunks of
  // piers (8 x 1700 less the light element sharing the third chunk, so 7 piers), far past it.
  std::vector<std::vector<int>> chunks;
  for (int k = 0; k < static_cast<int>(costs.size()); k += 4)
    chunks.push_back({k, k + 1, k + 2, k + 3});
  EXPECT_GE(finishTime(chunks, costs, 2), 7 * 1700.0);
}

TEST(WorkUnitsTest, NoItemsGiveEmptyLists) {
  WorkUnits w;
  EXPECT_EQ(w.size(), 0);
  w.form({}, 2);
  ASSERT_EQ(w.size(), 2);
  EXPECT_TRUE(w.unit(0).empty());
  EXPECT_TRUE(w.unit(1).empty());
}

}  // namespace
}  // namespace dabs::analysis
