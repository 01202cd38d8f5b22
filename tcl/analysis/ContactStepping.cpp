// SPDX-License-Identifier: MIT
#include "tcl/analysis/ContactStepping.h"

#include <algorithm>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::analysis {

void ContactSteppingParams::validate() const {
  if (!(maxStep > 0.0) || !std::isfinite(maxStep))
    throw InputError("maxStep", "must be a positive step length");
  if (!(lookAhead >= 0.0) || !std::isfinite(lookAhead))
    throw InputError("lookAhead", "must be >= 0");
  if (!(overshoot >= 1.0) || !std::isfinite(overshoot))
    throw InputError("overshoot", "must be >= 1");
}

void ContactStepping::attach(const domain::Domain& domain) {
  states_.clear();
  for (const auto& [tag, e] : domain.elements()) {
    if (e->typeName() != "nodeToSurface") continue;
    if (const auto* c3 = dynamic_cast<const contact::NodeToSurfaceContact3d<3>*>(e.get()))
      states_.push_back(&c3->committedState());
    else if (const auto* c6 = dynamic_cast<const contact::NodeToSurfaceContact3d<6>*>(e.get()))
      states_.push_back(&c6->committedState());
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
    if (gap < 0.0 || s.status != contact::ContactStatus::Open) near = true;
    const double last = lastGap_[i];  // NaN before the first step: no prediction
    if (lastStep_ > 0.0 && gap > 0.0 && gap < last) {
      const double tClose = gap * lastStep_ / (last - gap);
      if (tClose <= params_.lookAhead * remaining) near = true;
      // (overshoot x tClose may pass the end of the output step by a fraction of a contact step;
      // the next output step is then that much shorter)
      if (tClose < remaining) h = std::min(h, std::max(params_.overshoot * tClose, hMin));
    }
    lastGap_[i] = gap;
  }
  if (near) h = std::min(h, params_.maxStep);
  if (remaining - h < hMin) h = remaining;
  lastStep_ = h;
  if (h < 0.999 * dt) ++contactSteps_;
  return h;
}

}  // namespace dabs::analysis
