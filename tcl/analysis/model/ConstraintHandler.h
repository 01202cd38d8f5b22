// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <utility>
#include <vector>

#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// How constraints turn node dofs into equations (the `constraints` command).
enum class ConstraintKind { Plain, Transformation, Penalty };

/// One term of a node dof's value: coef times equation `index` (index >= 0) or times prescribed
/// slot -index-1 (index < 0).
struct DofTerm {
  int index;
  double coef;
};
/// A prescribed value (fix, sp, imposed motion) at a node dof, with its current motion.
struct SupportSlot {
  int node = 0, dof = 0;
  double disp = 0.0, vel = 0.0, accel = 0.0;
};
/// A penalty constraint alpha (c . u - g)^2 / 2 over a few equations (Penalty handler).
struct PenaltyRow {
  std::vector<std::pair<int, double>> eqs;  ///< equation, coefficient c
  int slot = -1;                            ///< prescribed value g (or -1 for 0)
  double alpha = 0.0;
  std::vector<int> valueIndex;  ///< matrix value index of eqs[i] x eqs[j], row-major (assembly)
};
/// A node and the index of its dof 0 among all node dofs (nodes in the domain's tag order).
struct NodeDofs {
  domain::Node* node;
  int firstDof;
};
/// What the handler makes of the domain's dofs.
struct DofMap {
  int numEquations = 0;
  std::vector<std::vector<DofTerm>> dofTerms;  ///< per node dof: its value as terms
  std::vector<int> directEq;  ///< per node dof: its equation when it is one (coefficient 1), or -1
  std::vector<SupportSlot> slots;  ///< fixes first, then the patterns' supports
  std::vector<int> patternSlots;   ///< slot of each pattern support, in pattern order
  bool imposedMotion = false;      ///< some support moves with an imposed velocity
  std::vector<std::pair<domain::Node*, int>> eqDof;  ///< node and dof of each equation
  std::vector<PenaltyRow> penalties;
};

/// Turns node dofs into equations under single- and multi-point constraints (OpenSees'
/// ConstraintHandler: OpenSees/OpenSees:SRC/analysis/handler/TransformationConstraintHandler.cpp,
/// PenaltyConstraintHandler.cpp). A dof is either an equation or prescribed. Plain and
/// Transformation prescribe fixed, sp and imposed-motion dofs (support "slots"); Transformation
/// also writes an equalDOF or rigidLink dof as a combination of its retained dofs, following
/// chains of constraints. Penalty keeps every dof an equation and returns one penalty row per
/// constrained dof instead.
class ConstraintHandler {
 public:
  ConstraintHandler(ConstraintKind kind, double alphaSP, double alphaMP)
      : kind_(kind), alphaSP_(alphaSP), alphaMP_(alphaMP) {}
  /// Numbers the equations of `nodes` (indexed by `nodeIndex`, node tag -> index) in the node
  /// order `order`. Throws InputError for constraints this handler cannot enforce: a missing
  /// node or dof, two single-point constraints on one dof, a dof both fixed and constrained, a
  /// cycle of constraints, any multi-point constraint under Plain.
  DofMap apply(const domain::Domain& domain, const std::vector<NodeDofs>& nodes,
               const std::map<int, int>& nodeIndex, const std::vector<int>& order) const;

 private:
  ConstraintKind kind_;
  double alphaSP_, alphaMP_;
};

}  // namespace dabs::analysis
