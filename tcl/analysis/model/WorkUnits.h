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
/// (A thread done with its own list takes what is left of the others', one item at a time:
/// AnalysisModel::updateElements.) Elements share nothing, so the lists change the time only,
/// never a result.
///
/// The costs are averages, and a force-based element's varies from iteration to iteration with
/// its local iterations, so lists that balance on average leave one thread waiting for the other
/// in most iterations. The light items (below 1/16 of the heaviest: girders, bearings, gaps
/// beside fiber piers) are therefore kept out of the lists in a shared pool that the threads
/// take from, a few at a time, once their own lists are done: the thread that finished first does
/// more of them. Their states are small, so moving them between cores costs little.
class WorkUnits {
 public:
  /// Items lighter than this fraction of the heaviest go to the shared pool.
  static constexpr double kLightFraction = 1.0 / 16.0;
  /// Pool items a thread takes at a time (one atomic add each).
  static constexpr int kSharedChunk = 4;
  /// Shares items 0 .. costs.size()-1 among `threads` lists (equal costs: the lower index first)
  /// and, with more than one list, the shared pool; each in ascending item order (the order of
  /// the elements' data in memory).
  void form(std::span<const double> costs, int threads);
  /// Number of lists (the thread count of the last form, or 0 before it).
  int size() const noexcept { return first_.empty() ? 0 : static_cast<int>(first_.size()) - 1; }
  /// The items of list u, in the order to run them.
  std::span<const int> unit(int u) const noexcept {
    const auto b = static_cast<std::size_t>(first_[static_cast<std::size_t>(u)]);
    const auto e = static_cast<std::size_t>(first_[static_cast<std::size_t>(u) + 1]);
    return std::span<const int>(order_).subspan(b, e - b);
  }
  /// The light items, taken by whichever thread is free (empty with one list).
  std::span<const int> shared() const noexcept { return shared_; }

 private:
  std::vector<int> order_;   ///< the lists one after the other
  std::vector<int> first_;   ///< list u is order_[first_[u] .. first_[u+1])
  std::vector<int> shared_;  ///< the pool of light items
  // Work buffers of form: items by cost, each list's cost, each item's list, next free place.
  std::vector<int> byCost_, owner_, next_;
  std::vector<double> load_;
};

}  // namespace dabs::analysis
