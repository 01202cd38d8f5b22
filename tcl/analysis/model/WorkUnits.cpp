// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/WorkUnits.h"

#include <algorithm>
#include <numeric>

namespace dabs::analysis {

void WorkUnits::form(std::span<const double> costs, int threads) {
  const auto lists = static_cast<std::size_t>(std::max(threads, 1));
  std::vector<int> byCost(costs.size());
  std::iota(byCost.begin(), byCost.end(), 0);
  std::stable_sort(byCost.begin(), byCost.end(), [&](int a, int b) {
    return costs[static_cast<std::size_t>(a)] > costs[static_cast<std::size_t>(b)];
  });
  std::vector<double> load(lists, 0.0);
  std::vector<int> owner(costs.size(), 0);
  for (const int k : byCost) {
    const auto least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) -
                                                load.begin());  // the first of equal loads
    load[least] += costs[static_cast<std::size_t>(k)];
    owner[static_cast<std::size_t>(k)] = static_cast<int>(least);
  }
  // The lists one after the other, each in ascending order: a counting sort by owner.
  first_.assign(lists + 1, 0);
  for (const int o : owner) ++first_[static_cast<std::size_t>(o) + 1];
  for (std::size_t u = 0; u < lists; ++u) first_[u + 1] += first_[u];
  order_.assign(costs.size(), 0);
  std::vector<int> next(first_.begin(), first_.end() - 1);
  for (std::size_t k = 0; k < costs.size(); ++k)
    order_[static_cast<std::size_t>(next[static_cast<std::size_t>(owner[k])]++)] =
        static_cast<int>(k);
}

}  // namespace dabs::analysis
