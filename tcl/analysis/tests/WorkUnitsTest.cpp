// SPDX-License-Identifier: MIT
// The threads' lists of element updates: every item in exactly one list or in the shared pool,
// each in ascending order, heavy items dealt out first (the longest-processing-time rule), light
// ones pooled. On the 10-span benchmark bridge's costs (11 fiber piers among 69 light elements, in
// the model's order: girders first) the piers alternate and the pool brings the two threads
// within a chunk of light elements of the even split, also in an iteration whose costs are not
// the averages the lists were formed on; chunks of four elements in the model's order taken first
// come, first served leave seven piers to one thread.
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

/// Finish time of a run: each thread its own list, then the pool's chunks in order, each to the
/// thread free first (what updateElements does when the costs are the times).
double pooledFinishTime(const WorkUnits& w, const std::vector<double>& costs) {
  std::vector<double> busy(static_cast<std::size_t>(w.size()), 0.0);
  for (int u = 0; u < w.size(); ++u)
    for (int k : w.unit(u)) busy[static_cast<std::size_t>(u)] += costs[static_cast<std::size_t>(k)];
  const auto pool = w.shared();
  for (std::size_t b = 0; b < pool.size(); b += WorkUnits::kSharedChunk) {
    double chunk = 0.0;
    for (std::size_t i = b; i < std::min(b + WorkUnits::kSharedChunk, pool.size()); ++i)
      chunk += costs[static_cast<std::size_t>(pool[i])];
    *std::min_element(busy.begin(), busy.end()) += chunk;
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

TEST(WorkUnitsTest, EveryItemIsInExactlyOneListOrThePoolInAscendingOrder) {
  // 1 is below 1/16 of the heaviest (20): pooled when there is more than one list.
  const std::vector<double> costs = {3.0, 1.0, 4.0, 1.0, 5.0, 20.0, 2.0, 6.0, 5.0, 3.0, 5.0};
  for (int threads : {1, 2, 3, 8, 20}) {
    WorkUnits w;
    w.form(costs, threads);
    ASSERT_EQ(w.size(), threads);
    std::vector<int> seen;
    for (const auto& u : unitsOf(w)) {
      EXPECT_TRUE(std::is_sorted(u.begin(), u.end()));
      seen.insert(seen.end(), u.begin(), u.end());
    }
    const std::vector<int> pool(w.shared().begin(), w.shared().end());
    EXPECT_EQ(pool, threads == 1 ? std::vector<int>{} : (std::vector<int>{1, 3})) << threads;
    seen.insert(seen.end(), pool.begin(), pool.end());
    std::sort(seen.begin(), seen.end());
    std::vector<int> all(costs.size());
    std::iota(all.begin(), all.end(), 0);
    EXPECT_EQ(seen, all) << threads << " threads";
  }
}

TEST(WorkUnitsTest, EqualCostsPoolNothing) {
  const std::vector<double> costs(10, 25.0);
  WorkUnits w;
  w.form(costs, 2);
  EXPECT_TRUE(w.shared().empty());
  EXPECT_EQ(w.unit(0).size() + w.unit(1).size(), 10u);
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

TEST(WorkUnitsTest, TwoThreadsShareTheBridgeWithinAChunkOfTheEvenSplit) {
  const std::vector<double> costs = bridgeCosts(1700.0, 25.0);
  WorkUnits w;
  w.form(costs, 2);
  const auto lists = unitsOf(w);
  ASSERT_EQ(lists.size(), 2u);
  // The lists hold the piers, alternating: 6 and 5; the 69 light elements are pooled.
  auto isPier = [](int k) { return k >= 40 && k < 51; };
  EXPECT_EQ(std::count_if(lists[0].begin(), lists[0].end(), isPier), 6);
  EXPECT_EQ(std::count_if(lists[1].begin(), lists[1].end(), isPier), 5);
  EXPECT_EQ(lists[0].size() + lists[1].size(), 11u);
  EXPECT_EQ(w.shared().size(), 69u);
  const double chunk = WorkUnits::kSharedChunk * 25.0;
  const double total = std::accumulate(costs.begin(), costs.end(), 0.0);
  EXPECT_LE(pooledFinishTime(w, costs), total / 2.0 + chunk);
  // An iteration in which a pier of the second list needs a second local iteration (twice its
  // average cost): the lists formed on the averages stay, and the first thread takes most of
  // the pool. The split is within a chunk of this iteration's even split (11,062.5), where the
  // longest-processing-time lists of every element (no pool: the first list's 6 piers and one
  // light element, the second's 5 piers and 68) leave one thread at 11,900.
  std::vector<double> now = costs;
  now[static_cast<std::size_t>(lists[1][0])] *= 2.0;
  const double totalNow = std::accumulate(now.begin(), now.end(), 0.0);
  EXPECT_LE(pooledFinishTime(w, now), totalNow / 2.0 + chunk);
  std::vector<int> all0 = lists[0], all1 = lists[1];
  for (std::size_t i = 0; i < w.shared().size(); ++i)
    (i == 0 ? all0 : all1).push_back(w.shared()[i]);
  EXPECT_GE(std::max(finishTime({all0}, now, 1), finishTime({all1}, now, 1)),
            totalNow / 2.0 + 800.0);
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
