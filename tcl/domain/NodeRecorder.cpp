// SPDX-License-Identifier: MIT
#include "tcl/domain/NodeRecorder.h"

#include <string>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::domain {

NodeRecorder::NodeRecorder(RecorderOutput output, std::vector<int> nodes, std::vector<int> dofs,
                           Response response, int mode,
                           std::vector<std::shared_ptr<const TimeSeries>> series)
    : ResponseRecorder(std::move(output)),
      nodes_(std::move(nodes)),
      dofs_(std::move(dofs)),
      response_(response),
      mode_(mode),
      series_(std::move(series)) {}

void NodeRecorder::initialize(const Domain& domain) {
  for (int d : dofs_)
    if (d < 0) throw InputError("-dof", "dofs start at 1, got " + std::to_string(d + 1));
  for (int tag : nodes_) {
    const Node& n = domain.node(tag);  // throws for an unknown node
    for (int d : dofs_)
      if (d >= n.ndf())
        throw InputError("-dof", "node " + std::to_string(tag) + " has " + std::to_string(n.ndf()) +
                                     " dofs, got dof " + std::to_string(d + 1));
  }
  if (!series_.empty() && series_.size() != dofs_.size())
    throw InputError("-timeSeries", "needs one series per dof");
}

void NodeRecorder::values(const Domain& domain, std::vector<double>& out) {
  const double t = domain.time();
  std::size_t k = 0;
  const bool incr = response_ == Response::IncrDisp;
  if (incr && lastDisp_.empty()) lastDisp_.assign(nodes_.size() * dofs_.size(), 0.0);
  for (int tag : nodes_) {
    const Node* n = domain.findNode(tag);
    for (std::size_t j = 0; j < dofs_.size(); ++j, ++k) {
      const int d = dofs_[j];
      double v = 0.0;
      if (n != nullptr && d < n->ndf()) {
        switch (response_) {
          case Response::Disp: v = n->disp(d); break;
          case Response::Vel: v = n->vel(d); break;
          case Response::Accel: v = n->accel(d); break;
          case Response::IncrDisp:
            v = n->disp(d) - lastDisp_[k];
            lastDisp_[k] = n->disp(d);
            break;
          case Response::Reaction: v = n->reaction(d); break;
          case Response::Eigen:
            if (mode_ >= 1 && n->eigenvectors.cols() >= mode_) v = n->eigenvectors(d, mode_ - 1);
            break;
        }
      }
      if (!series_.empty() && series_[j]) v += series_[j]->factor(t);
      out.push_back(v);
    }
  }
}

}  // namespace dabs::domain
