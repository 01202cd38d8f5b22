// SPDX-License-Identifier: MIT
#include "tcl/domain/DriftRecorder.h"

#include <algorithm>
#include <string>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::domain {

DriftRecorder::DriftRecorder(RecorderOutput output, std::vector<int> iNodes,
                             std::vector<int> jNodes, std::vector<int> dofs,
                             std::vector<int> perpDirns)
    : ResponseRecorder(std::move(output)),
      iNodes_(std::move(iNodes)),
      jNodes_(std::move(jNodes)),
      dofs_(std::move(dofs)),
      perp_(std::move(perpDirns)) {}

void DriftRecorder::initialize(const Domain& domain) {
  const std::size_t n = iNodes_.size();
  if (jNodes_.size() != n) throw InputError("-jNode", "needs as many nodes as -iNode");
  if (dofs_.size() != n && dofs_.size() != 1)
    throw InputError("-dof", "needs one dof or one per node pair");
  if (perp_.size() != n && perp_.size() != 1)
    throw InputError("-perpDirn", "needs one direction or one per node pair");
  lengths_.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const Node& i = domain.node(iNodes_[k]);
    const Node& j = domain.node(jNodes_[k]);
    const int p = perp_[perp_.size() == 1 ? 0 : k];
    if (p < 0 || p > 2) throw InputError("-perpDirn", "must be 1, 2 or 3");
    const int d = dofs_[dofs_.size() == 1 ? 0 : k];
    const int ndf = std::min(i.ndf(), j.ndf());
    if (d < 0 || d >= ndf)
      throw InputError("-dof", "must be 1 to " + std::to_string(ndf) + " for nodes " +
                                   std::to_string(iNodes_[k]) + " and " +
                                   std::to_string(jNodes_[k]) + ", got " + std::to_string(d + 1));
    const double length = j.coords()(p) - i.coords()(p);
    if (length == 0.0)
      throw InputError("-perpDirn", "nodes " + std::to_string(iNodes_[k]) + " and " +
                                        std::to_string(jNodes_[k]) + " have no distance along it");
    lengths_.push_back(length);
  }
}

void DriftRecorder::values(const Domain& domain, std::vector<double>& out) {
  for (std::size_t k = 0; k < iNodes_.size(); ++k) {
    const Node* i = domain.findNode(iNodes_[k]);
    const Node* j = domain.findNode(jNodes_[k]);
    const int d = dofs_[dofs_.size() == 1 ? 0 : k];
    double v = 0.0;
    if (i && j && d < i->ndf() && d < j->ndf()) v = (j->disp(d) - i->disp(d)) / lengths_[k];
    out.push_back(v);
  }
}

}  // namespace dabs::domain
