// SPDX-License-Identifier: MIT
#pragma once

#include <span>
#include <vector>

namespace dabs::analysis {

/// The element updates of an iteration shared among threads: one list of items per thread, by the
/// longest-processing-time-first rule of list scheduling (Graham 1969, "Bounds on multiprocessing
/// timing anomalies", SIAM J. Appl. Math. 17(2)): items by estimated cost, heaviest first, each to
/// the list with the least cost so far; the longest list is at most 4/3 of the best split's. The
/// lists stay the same from iteration to iteration, so each thread updates the same elements every
/// time and their states (a fiber pier's are tens of kilobytes) stay in the cache of the core it
/// runs on, while the system keeps it there; a first-come schedule moves elements between cores.
/// Elements share nothing, so the lists change the time only, never a result.
class WorkUnits {
 public:
  /// Shares items 0 .. costs.size()-1 among `threads` lists (equal costs: the lower index first),
  /// each list in ascending item order (the order of the elements' data in memory).
  void form(std::span<const double> costs, int threads);
  /// Number of lists (the thread count of the last form, or 0 before it).
  int size() const noexcept { return first_.empty() ? 0 : static_cast<int>(first_.size()) - 1; }
  /// The items of list u, in the order to run them.
  std::span<const int> unit(int u) const noexcept {
    const auto b = static_cast<std::size_t>(first_[static_cast<std::size_t>(u)]);
    const auto e = static_cast<std::size_t>(first_[static_cast<std::size_t>(u) + 1]);
    return std::span<const int>(order_).subspan(b, e - b);
  }

 private:
  std::vector<int> order_;  ///< the lists one after the other
  std::vector<int> first_;  ///< list u is order_[first_[u] .. first_[u+1])
  // Work buffers of form: items by cost, each list's cost, each item's list, next free place.
  std::vector<int> byCost_, owner_, next_;
  std::vector<double> load_;
};

}  // namespace dabs::analysis
