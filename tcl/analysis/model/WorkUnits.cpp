// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/WorkUnits.h"

#include <algorithm>
#include <numeric>

namespace dabs::analysis {

void WorkUnits::form(std::span<const double> costs, int threads) {
  // Buffers are members and the sort is in place, so forming again allocates nothing once the
  // sizes are reached (the analysis allocates nothing per step).
  const auto lists = static_cast<std::size_t>(std::max(threads, 1));
  byCost_.resize(costs.size());
  std::iota(byCost_.begin(), byCost_.end(), 0);
  std::sort(byCost_.begin(), byCost_.end(), [&](int a, int b) {
    const double ca = costs[static_cast<std::size_t>(a)], cb = costs[static_cast<std::size_t>(b)];
    return ca > cb || (ca == cb && a < b);  // equal costs in index order
  });
  load_.assign(lists, 0.0);
  owner_.assign(costs.size(), 0);
  // With one list there is no one to share with; otherwise the pool takes the light items.
  const double light = lists > 1 && !byCost_.empty()
                           ? costs[static_cast<std::size_t>(byCost_.front())] * kLightFraction
                           : 0.0;
  shared_.clear();
  for (const int k : byCost_) {
    if (costs[static_cast<std::size_t>(k)] < light) {
      owner_[static_cast<std::size_t>(k)] = -1;
      continue;
    }
    const auto least = static_cast<std::size_t>(std::min_element(load_.begin(), load_.end()) -
                                                load_.begin());  // the first of equal loads
    load_[least] += costs[static_cast<std::size_t>(k)];
    owner_[static_cast<std::size_t>(k)] = static_cast<int>(least);
  }
  // The lists one after the other, each in ascending order: a counting sort by owner.
  first_.assign(lists + 1, 0);
  for (const int o : owner_)
    if (o >= 0) ++first_[static_cast<std::size_t>(o) + 1];
  for (std::size_t u = 0; u < lists; ++u) first_[u + 1] += first_[u];
  order_.resize(static_cast<std::size_t>(first_.back()));
  next_.assign(first_.begin(), first_.end() - 1);
  for (std::size_t k = 0; k < costs.size(); ++k) {
    if (const int o = owner_[k]; o >= 0)
      order_[static_cast<std::size_t>(next_[static_cast<std::size_t>(o)]++)] = static_cast<int>(k);
    else
      shared_.push_back(static_cast<int>(k));
  }
}

}  // namespace dabs::analysis
