// SPDX-License-Identifier: MIT
#pragma once

#include <limits>
#include <span>

namespace dabs::elements {

/// What contact stepping (the analysis' event-located step length, ContactStepping) reads of an
/// element that makes and breaks contact (Element::contactPredictor): its committed gap, from
/// which the analysis predicts the instant of the next contact, and the duration of a contact,
/// which bounds the step while the pair is closed. Read between steps, from committed states only.
class ContactPredictor {
 public:
  /// Gap of the last committed state (length; > 0 open, < 0 penetration).
  virtual double committedGap() const = 0;
  /// True when the last committed state is in contact (sticking or sliding), whatever its gap.
  virtual bool committedClosed() const = 0;
  /// True when the last committed state is open but carries a force: the tension a release step
  /// may end with (the trapezoid rule carries it through the next step's average as well).
  virtual bool committedTension() const { return false; }
  /// Duration of the pair's undamped contact (time), m the reduced mass of the two bodies: for a
  /// linear spring K the half period pi sqrt(m / K), whatever the speed; for a power law
  /// N = k delta^n it depends on the impact speed, which the pair takes from its committed
  /// penetration and `gapRate`, the rate of its gap over the last step (length/time).
  /// `nodeMasses` holds each element node's translational mass, in element node order, for a pair
  /// that takes its bodies' masses from its nodes. Infinity when the contactor has no mass or a
  /// power-law pair neither moves nor penetrates (nothing bounds the step).
  virtual double contactDuration(std::span<const double> nodeMasses, double gapRate) const = 0;
  /// Longest step that may hold the first touch (time): a force that jumps at the touch (a
  /// dashpot's C |gdot|) or rises from it with infinite slope is averaged over the step that holds
  /// the touch, an error of first order in that step. `gapRate` is the gap's rate over the last
  /// step (the approach speed, where the error depends on it). Infinity when nothing jumps.
  virtual double touchStep(double gapRate) const {
    (void)gapRate;
    return std::numeric_limits<double>::infinity();
  }

 protected:
  ContactPredictor() = default;
  ContactPredictor(const ContactPredictor&) = default;
  ContactPredictor& operator=(const ContactPredictor&) = default;
  /// Not deleted through this interface: the domain owns the element.
  ~ContactPredictor() = default;
};

}  // namespace dabs::elements
