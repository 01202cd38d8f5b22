// SPDX-License-Identifier: MIT
#include "tcl/analysis/ContactStepping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::analysis {

void ContactSteppingParams::validate() const {
  if (!(maxStep > 0.0) || !std::isfinite(maxStep))
    throw InputError("maxStep", "must be a positive step length");
  if (!(lookAhead >= 0.0) || !std::isfinite(lookAhead))
    throw InputError("lookAhead", "must be >= 0");
  if (!(overshoot >= 1.0) || !std::isfinite(overshoot))
    throw InputError("overshoot", "must be >= 1");
  if (perContact < 0 || perContact > 100000)
    throw InputError("perContact", "must be 0 (off) to 100000 steps per contact duration");
}

namespace {

// T_c / perContact of a pair (infinity when perContact is 0 or the pair has no mass).
template <int Ndf>
double contactStep(const contact::NodeToSurfaceContact3d<Ndf>& pair, const domain::Domain& domain,
                   int perContact) {
  if (perContact <= 0) return std::numeric_limits<double>::infinity();
  const contact::NodeToSurfaceParams& p = pair.params();
  double m1 = p.M1, m2 = p.M2;
  if (!(m1 > 0.0 && m2 > 0.0)) {
    // Translational masses of the nodes (the largest of a node's three): the contactor's, and
    // the face's four summed.
    const auto& tags = pair.nodeTags();
    auto nodeMass = [&](int tag) {
      const domain::Node* n = domain.findNode(tag);
      if (n == nullptr) return 0.0;
      const Eigen::MatrixXd& m = n->mass();
      double largest = 0.0;
      for (int d = 0; d < 3 && d < m.rows(); ++d) largest = std::max(largest, m(d, d));
      return largest;
    };
    m1 = nodeMass(tags[0]);
    m2 = 0.0;
    for (std::size_t i = 1; i < tags.size(); ++i) m2 += nodeMass(tags[i]);
  }
  // A face without mass is fixed (the contactor's mass alone); no contactor mass: no limit.
  if (!(m1 > 0.0)) return std::numeric_limits<double>::infinity();
  const double m = m2 > 0.0 ? m1 * m2 / (m1 + m2) : m1;
  return std::numbers::pi * std::sqrt(m / p.K) / perContact;
}

}  // namespace

void ContactStepping::attach(const domain::Domain& domain) {
  states_.clear();
  contactStep_.clear();
  for (const auto& [tag, e] : domain.elements()) {
    if (e->typeName() != "nodeToSurface") continue;
    if (const auto* c3 = dynamic_cast<const contact::NodeToSurfaceContact3d<3>*>(e.get())) {
      states_.push_back(&c3->committedState());
      contactStep_.push_back(contactStep(*c3, domain, params_.perContact));
    } else if (const auto* c6 = dynamic_cast<const contact::NodeToSurfaceContact3d<6>*>(e.get())) {
      states_.push_back(&c6->committedState());
      contactStep_.push_back(contactStep(*c6, domain, params_.perContact));
    }
  }
  reset();
}

void ContactStepping::reset() {
  lastGap_.assign(states_.size(), std::numeric_limits<double>::quiet_NaN());
  lastStep_ = 0.0;
}

double ContactStepping::nextStep(double remaining, double dt) {
  double h = remaining;
  bool near = false;
  const double hMin = 0.01 * params_.maxStep;
  for (std::size_t i = 0; i < states_.size(); ++i) {
    const contact::NodeToSurfaceState& s = *states_[i];
    const double gap = s.gap;
    bool pairNear = gap < 0.0 || s.status != contact::ContactStatus::Open;
    const double last = lastGap_[i];  // NaN before the first step: no prediction
    if (lastStep_ > 0.0 && gap > 0.0 && gap < last) {
      const double tClose = gap * lastStep_ / (last - gap);
      if (tClose <= params_.lookAhead * remaining) pairNear = true;
      // (overshoot x tClose may pass the end of the output step by a fraction of a contact step;
      // the next output step is then that much shorter)
      if (tClose < remaining) h = std::min(h, std::max(params_.overshoot * tClose, hMin));
    }
    lastGap_[i] = gap;
    if (pairNear) {
      near = true;
      h = std::min(h, contactStep_[i]);
    }
  }
  if (near) h = std::min(h, params_.maxStep);
  if (remaining - h < hMin) h = remaining;
  lastStep_ = h;
  if (h < 0.999 * dt) ++contactSteps_;
  return h;
}

}  // namespace dabs::analysis
