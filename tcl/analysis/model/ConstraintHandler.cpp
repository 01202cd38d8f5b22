// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/ConstraintHandler.h"

#include <functional>
#include <string>

#include "materials/InputError.h"

namespace dabs::analysis {

namespace {
constexpr int kMaxConstraintChain = 16;  // equalDOF chains longer than this are a cycle
}

DofMap ConstraintHandler::apply(const domain::Domain& domain, const std::vector<NodeDofs>& nodes,
                                const std::map<int, int>& nodeIndex,
                                const std::vector<int>& order) const {
  DofMap out;
  int ndofTotal = 0;
  for (const NodeDofs& nd : nodes) ndofTotal += nd.node->ndf();
  auto dofIndex = [&](int nodeTag, int dof) {
    return nodes[static_cast<std::size_t>(nodeIndex.at(nodeTag))].firstDof + dof;
  };
  // --- single-point constraints: fixes, pattern sp, imposed motions -------------------------
  std::vector<int> slotOf(static_cast<std::size_t>(ndofTotal), -1);
  auto addSlot = [&](int nodeTag, int dof, const char* source) {
    const domain::Node* n = domain.findNode(nodeTag);
    if (n == nullptr)
      throw InputError(source,
                       "refers to node " + std::to_string(nodeTag) + " which does not exist");
    if (dof < 0 || dof >= n->ndf())
      throw InputError(source, "dof " + std::to_string(dof + 1) + " is outside 1.." +
                                   std::to_string(n->ndf()) + " of node " +
                                   std::to_string(nodeTag));
    const int g = dofIndex(nodeTag, dof);
    if (slotOf[static_cast<std::size_t>(g)] >= 0)
      throw InputError(source,
                       "node " + std::to_string(nodeTag) + " dof " + std::to_string(dof + 1) +
                           " has more than one single-point constraint (fix, sp or imposedMotion)");
    slotOf[static_cast<std::size_t>(g)] = static_cast<int>(out.slots.size());
    out.slots.push_back(SupportSlot{nodeTag, dof});
  };
  for (const auto& sp : domain.fixes()) addSlot(sp.node, sp.dof, "fix");
  for (const auto& [ptag, p] : domain.patterns()) {
    for (const domain::SupportDof& s : p->supportDofs()) {
      out.patternSlots.push_back(static_cast<int>(out.slots.size()));
      addSlot(s.node, s.dof, s.source);
      out.imposedMotion = out.imposedMotion || s.imposedMotion;
    }
  }

  // --- multi-point constraints -------------------------------------------------------------
  if (kind_ == ConstraintKind::Plain && !domain.mps().empty())
    throw InputError(
        "constraints Plain",
        "cannot enforce equalDOF or rigidLink constraints; use constraints Transformation");
  std::vector<int> mpOf(static_cast<std::size_t>(ndofTotal), -1);  // index into mps, row encoded
  std::vector<int> mpRow(static_cast<std::size_t>(ndofTotal), -1);
  const auto& mps = domain.mps();
  for (std::size_t m = 0; m < mps.size(); ++m) {
    for (std::size_t r = 0; r < mps[m].constrainedDofs.size(); ++r) {
      const int g = dofIndex(mps[m].constrainedNode, mps[m].constrainedDofs[r]);
      if (slotOf[static_cast<std::size_t>(g)] >= 0 && kind_ != ConstraintKind::Penalty)
        throw InputError("equalDOF", "node " + std::to_string(mps[m].constrainedNode) + " dof " +
                                         std::to_string(mps[m].constrainedDofs[r] + 1) +
                                         " is both constrained and fixed");
      mpOf[static_cast<std::size_t>(g)] = static_cast<int>(m);
      mpRow[static_cast<std::size_t>(g)] = static_cast<int>(r);
    }
  }

  // --- equations --------------------------------------------------------------------------
  out.dofTerms.assign(static_cast<std::size_t>(ndofTotal), {});
  std::vector<int> eqOf(static_cast<std::size_t>(ndofTotal), -1);
  int& neq = out.numEquations;
  neq = 0;
  for (int ni : order) {
    const NodeDofs& nl = nodes[static_cast<std::size_t>(ni)];
    for (int d = 0; d < nl.node->ndf(); ++d) {
      const auto g = static_cast<std::size_t>(nl.firstDof + d);
      const bool prescribed = kind_ != ConstraintKind::Penalty && (slotOf[g] >= 0 || mpOf[g] >= 0);
      if (!prescribed) eqOf[g] = neq++;
    }
  }
  // Terms of a dof, resolving chains of multi-point constraints.
  std::function<std::vector<DofTerm>(int, int)> resolve = [&](int g,
                                                              int depth) -> std::vector<DofTerm> {
    const auto gi = static_cast<std::size_t>(g);
    if (eqOf[gi] >= 0) return {DofTerm{eqOf[gi], 1.0}};
    if (slotOf[gi] >= 0) return {DofTerm{-slotOf[gi] - 1, 1.0}};
    if (depth > kMaxConstraintChain)
      throw InputError("equalDOF", "constraints form a cycle or a chain longer than 16 nodes");
    const auto& mp = mps[static_cast<std::size_t>(mpOf[gi])];
    const int r = mpRow[gi];
    std::vector<DofTerm> terms;
    for (std::size_t k = 0; k < mp.retainedDofs.size(); ++k) {
      const double c = mp.Ccr(r, static_cast<Eigen::Index>(k));
      if (c == 0.0) continue;
      for (const DofTerm& t : resolve(dofIndex(mp.retainedNode, mp.retainedDofs[k]), depth + 1))
        terms.push_back(DofTerm{t.index, c * t.coef});
    }
    return terms;
  };
  for (int g = 0; g < ndofTotal; ++g) out.dofTerms[static_cast<std::size_t>(g)] = resolve(g, 0);
  out.directEq.assign(static_cast<std::size_t>(ndofTotal), -1);
  for (std::size_t g = 0; g < out.dofTerms.size(); ++g) {
    const auto& terms = out.dofTerms[g];
    if (terms.size() == 1 && terms[0].index >= 0 && terms[0].coef == 1.0)
      out.directEq[g] = terms[0].index;
  }
  out.eqDof.assign(static_cast<std::size_t>(neq), {nullptr, 0});
  for (const NodeDofs& nl : nodes)
    for (int d = 0; d < nl.node->ndf(); ++d) {
      const int eq = eqOf[static_cast<std::size_t>(nl.firstDof + d)];
      if (eq >= 0) out.eqDof[static_cast<std::size_t>(eq)] = {nl.node, d};
    }

  // --- penalty rows ------------------------------------------------------------------------
  if (kind_ == ConstraintKind::Penalty) {
    for (int g = 0; g < ndofTotal; ++g) {
      if (slotOf[static_cast<std::size_t>(g)] >= 0) {
        PenaltyRow row;
        row.eqs = {{eqOf[static_cast<std::size_t>(g)], 1.0}};
        row.slot = slotOf[static_cast<std::size_t>(g)];
        row.alpha = alphaSP_;
        out.penalties.push_back(row);
      }
    }
    for (const auto& mp : mps) {
      for (std::size_t r = 0; r < mp.constrainedDofs.size(); ++r) {
        PenaltyRow row;
        row.eqs.push_back(
            {eqOf[static_cast<std::size_t>(dofIndex(mp.constrainedNode, mp.constrainedDofs[r]))],
             1.0});
        for (std::size_t k = 0; k < mp.retainedDofs.size(); ++k) {
          const double c = mp.Ccr(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(k));
          if (c != 0.0)
            row.eqs.push_back(
                {eqOf[static_cast<std::size_t>(dofIndex(mp.retainedNode, mp.retainedDofs[k]))],
                 -c});
        }
        row.alpha = alphaMP_;
        out.penalties.push_back(row);
      }
    }
  }
  return out;
}

}  // namespace dabs::analysis
