// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/DofNumberer.h"

#include <algorithm>
#include <deque>
#include <numeric>

namespace dabs::analysis {

std::vector<int> DofNumberer::order(const Graph& graph) const {
  if (kind_ == NumbererKind::RCM && !graph.empty()) return reverseCuthillMcKee(graph);
  std::vector<int> plain(graph.size());
  std::iota(plain.begin(), plain.end(), 0);
  return plain;
}

std::vector<int> DofNumberer::order(const domain::Domain& domain,
                                    const std::map<int, int>& nodeIndex) const {
  if (kind_ == NumbererKind::RCM) return order(nodeGraph(domain, nodeIndex));
  return order(Graph(nodeIndex.size()));
}

DofNumberer::Graph DofNumberer::nodeGraph(const domain::Domain& domain,
                                          const std::map<int, int>& nodeIndex) {
  Graph adj(nodeIndex.size());
  auto link = [&](int a, int b) {
    if (a != b) {
      adj[static_cast<std::size_t>(a)].insert(b);
      adj[static_cast<std::size_t>(b)].insert(a);
    }
  };
  for (const auto& [etag, e] : domain.elements()) {
    const auto& nt = e->nodeTags();
    for (std::size_t i = 0; i < nt.size(); ++i)
      for (std::size_t j = i + 1; j < nt.size(); ++j)
        link(nodeIndex.at(nt[i]), nodeIndex.at(nt[j]));
  }
  for (const auto& mp : domain.mps())
    link(nodeIndex.at(mp.retainedNode), nodeIndex.at(mp.constrainedNode));
  return adj;
}

std::vector<int> DofNumberer::reverseCuthillMcKee(const Graph& adj) {
  const std::size_t n = adj.size();
  std::vector<bool> seen(n, false);
  std::vector<int> cm;
  cm.reserve(n);
  while (cm.size() < n) {
    int start = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (!seen[i] && (start < 0 || adj[i].size() < adj[static_cast<std::size_t>(start)].size()))
        start = static_cast<int>(i);
    }
    std::deque<int> queue{start};
    seen[static_cast<std::size_t>(start)] = true;
    while (!queue.empty()) {
      const int k = queue.front();
      queue.pop_front();
      cm.push_back(k);
      std::vector<int> next;
      for (int m : adj[static_cast<std::size_t>(k)])
        if (!seen[static_cast<std::size_t>(m)]) next.push_back(m);
      std::sort(next.begin(), next.end(), [&](int a, int b) {
        return adj[static_cast<std::size_t>(a)].size() < adj[static_cast<std::size_t>(b)].size();
      });
      for (int m : next) {
        seen[static_cast<std::size_t>(m)] = true;
        queue.push_back(m);
      }
    }
  }
  return {cm.rbegin(), cm.rend()};
}

}  // namespace dabs::analysis
