// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <set>
#include <vector>

#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// Equation ordering (the `numberer` command). The sparse solvers reorder again (AMD/COLAMD), so
/// the choice changes only the equation numbers, never the results.
enum class NumbererKind { Plain, RCM };

/// The order in which nodes receive their equation numbers (OpenSees' DOF_Numberer with its
/// graph numberers, OpenSees/OpenSees:SRC/graph/numberer/RCM.cpp): Plain keeps the domain's tag
/// order, RCM the reverse Cuthill-McKee order of the node graph (Cuthill & McKee 1969; George
/// 1971), which keeps coupled nodes' numbers close.
class DofNumberer {
 public:
  /// Node graph: for node index i, the indices of the nodes it is coupled to (no self links).
  using Graph = std::vector<std::set<int>>;

  explicit DofNumberer(NumbererKind kind) : kind_(kind) {}
  /// Node indices 0..n-1 of `graph` in numbering order.
  std::vector<int> order(const Graph& graph) const;
  /// The numbering order of a domain's nodes (indices from `nodeIndex`, node tag -> index); the
  /// graph is formed only when the order needs it.
  std::vector<int> order(const domain::Domain& domain, const std::map<int, int>& nodeIndex) const;
  /// The node graph of a domain: nodes coupled by an element or a multi-point constraint, with
  /// node indices from `nodeIndex` (node tag -> index).
  static Graph nodeGraph(const domain::Domain& domain, const std::map<int, int>& nodeIndex);
  /// Reverse Cuthill-McKee: each component breadth-first from a node of least degree, neighbours
  /// in increasing degree, the whole sequence reversed.
  static std::vector<int> reverseCuthillMcKee(const Graph& graph);

 private:
  NumbererKind kind_;
};

}  // namespace dabs::analysis
