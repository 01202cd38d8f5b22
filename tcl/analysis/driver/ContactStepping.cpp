// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/ContactStepping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "elements/ContactPredictor.h"
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

// Translational masses of an element's nodes (the largest of a node's three), for a pair that
// takes its bodies' masses from its nodes.
std::vector<double> nodeMasses(const elements::Element& e, const domain::Domain& domain) {
  std::vector<double> masses;
  for (int tag : e.nodeTags()) {
    const domain::Node* n = domain.findNode(tag);
    double largest = 0.0;
    if (n != nullptr) {
      const Eigen::MatrixXd& m = n->mass();
      for (int d = 0; d < 3 && d < m.rows(); ++d) largest = std::max(largest, m(d, d));
    }
    masses.push_back(largest);
  }
  return masses;
}

}  // namespace

void ContactStepping::attach(const domain::Domain& domain) {
  pairs_.clear();
  nodeMasses_.clear();
  for (const auto& [tag, e] : domain.elements()) {
    const elements::ContactPredictor* pair = e->contactPredictor();
    if (pair == nullptr) continue;
    pairs_.push_back(pair);
    if (params_.perContact > 0) nodeMasses_.push_back(nodeMasses(*e, domain));
  }
  reset();
}

void ContactStepping::reset() {
  lastGap_.assign(pairs_.size(), std::numeric_limits<double>::quiet_NaN());
  lastRate_.assign(pairs_.size(), std::numeric_limits<double>::quiet_NaN());
  touchRate_.assign(pairs_.size(), std::numeric_limits<double>::quiet_NaN());
  closedFor_.assign(pairs_.size(), 0.0);
  lastStep_ = 0.0;
  lastTaken_ = true;
  previousStep_ = 0.0;
}

double ContactStepping::nextStep(double remaining, double dt) {
  double h = remaining;
  const double hMin = 0.01 * params_.maxStep;
  double shortestNear = hMin;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const elements::ContactPredictor& pair = *pairs_[i];
    const double gap = pair.committedGap();
    bool pairNear = gap < 0.0 || pair.committedClosed();
    // The tension a release step ended with acts through the next step's trapezoid average too
    // (Newmark keeps the step's end acceleration): a step no longer than the release step keeps
    // that impulse of the release step's order. A longer one pulled the bodies together again:
    // k_h 1.3e15 with -perContact 20, a 0.11 us release step followed by one of 1.3 ms, took the
    // bodies back into contact at every output step.
    if (pair.committedTension() && lastStep_ > 0.0) {
      pairNear = true;
      h = std::min(h, lastStep_);
    }
    closedFor_[i] = pair.committedClosed() ? closedFor_[i] + (lastTaken_ ? lastStep_ : 0.0) : 0.0;
    const double last = lastGap_[i];  // NaN before the first step: no prediction
    const double rate = lastStep_ > 0.0 && std::isfinite(last) && std::isfinite(gap)
                            ? (gap - last) / lastStep_
                            : std::numeric_limits<double>::quiet_NaN();
    double tClose = std::numeric_limits<double>::infinity();
    if (lastStep_ > 0.0 && gap > 0.0 && gap < last) tClose = gap * lastStep_ / (last - gap);
    if (!(tClose < remaining) && gap > 0.0 && std::isfinite(rate) && std::isfinite(lastRate_[i]) &&
        previousStep_ > 0.0) {
      // Quadratic: the rate's change over the two steps' mid-points gives the acceleration a;
      // from the end of the last step g(t) = g + v t + a t^2 / 2, v = rate + a h_last / 2.
      const double a = (rate - lastRate_[i]) / (0.5 * (lastStep_ + previousStep_));
      const double v = rate + 0.5 * a * lastStep_;
      const double disc = v * v - 2.0 * a * gap;
      if (a < 0.0 && disc >= 0.0) {
        const double root = (v + std::sqrt(disc)) / -a;  // the positive root (g > 0, a < 0)
        if (root < tClose) tClose = root;
      }
    }
    if (tClose <= params_.lookAhead * remaining) pairNear = true;
    lastGap_[i] = gap;
    lastRate_[i] = rate;
    if (!(tClose < remaining) && !pairNear) continue;
    // The pair's contact step: maxStep, and T_c / perContact from the gap rate over the last step
    // (none before the first: a power law's pair then takes its speed from its penetration
    // alone). The shortest cut is hMin, or a twentieth of the contact step for a contact shorter
    // than 20 hMin steps.
    const double knownRate = std::isfinite(rate) ? rate : 0.0;
    double contactStep = params_.maxStep;
    if (params_.perContact > 0)
      contactStep = std::min(contactStep,
                             pair.contactDuration(nodeMasses_[i], knownRate) / params_.perContact);
    const double shortest = std::min(hMin, 0.05 * contactStep);
    // (overshoot x tClose may pass the end of the output step by a fraction of a contact step;
    // the next output step is then that much shorter)
    if (tClose < remaining) {
      // A touch whose force jumps (a dashpot) or rises steeply (Jankowski) is taken in a step of
      // at most touchStep when that is shorter than the contact step: the step arrives half of it
      // before the predicted touch, and the next one, cut at overshoot x the rest, holds the
      // touch.
      const double touch = pair.touchStep(knownRate);
      touchRate_[i] = knownRate;
      if (touch < contactStep && touch >= shortest && tClose > touch)
        h = std::min(h, std::max(tClose - 0.5 * touch, shortest));
      else
        h = std::min(h, std::max(params_.overshoot * tClose, shortest));
    }
    if (pairNear) {
      h = std::min(h, contactStep);
      shortestNear = std::min(shortestNear, shortest);
      // After a short touch step (a jump or a steep rise of the damping force), a step in
      // contact is no longer than the pair's age in contact (from the start of the step that
      // closed it), or the touch step: graded from the touch, each at most doubling that age.
      // Jankowski's delta^(1/4) rise lasts beyond the touch step, and a step of T_c / 20 right
      // after it left its onset's error of first order (e = 0.1: 6 % low at T_c / 34; graded 1.2 %
      // high). Grading on the contact's age, not on the last step, keeps a step cut short by the
      // end of an output step from restarting the growth: three Jankowski impacts at 0.07 to 0.3
      // m/s under a 10 ms output step were 1.1 % high in e that way (hard-impact suite), 0.9 %
      // graded.
      if (pair.committedClosed() && std::isfinite(touchRate_[i])) {
        const double touch = pair.touchStep(touchRate_[i]);
        if (touch < contactStep) h = std::min(h, std::max(touch, closedFor_[i]));
      }
    }
  }
  // A remainder shorter than the shortest cut is taken with this step (a stiff contact's steps
  // may be far shorter than hMin: its remainder must be too, or it lands inside the contact).
  if (remaining - h < shortestNear) h = remaining;
  previousStep_ = lastStep_;
  lastStep_ = h;
  lastTaken_ = true;
  if (h < 0.999 * dt) ++contactSteps_;
  return h;
}

}  // namespace dabs::analysis
