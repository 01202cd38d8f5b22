// SPDX-License-Identifier: MIT
#pragma once

#include <limits>
#include <vector>

#include "elements/ContactPredictor.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// Parameters of event-located contact stepping (the `contactStepping` command).
struct ContactSteppingParams {
  double maxStep = 0.0005;  ///< longest step while a pair is closed or about to close, s (> 0)
  double lookAhead =
      2.0;  ///< a pair "about to close" closes within lookAhead x the rest of the step (>= 0)
  double overshoot =
      1.2;  ///< a step cut at a predicted first contact ends at overshoot x that time (>= 1)
  /// Steps per contact duration while a pair is closed or about to close (0: no such limit): the
  /// step is at most T_c / perContact, T_c the duration of the pair's undamped contact
  /// (ContactPredictor::contactDuration: pi sqrt(m / K) for kelvin; for a power law from the
  /// impact speed, which the pair takes from its penetration and its gap rate over the last
  /// step), m = M1 M2 / (M1 + M2) from its -masses (pairs without masses: the translational
  /// masses of its contactor node and of its four face nodes). 20 by default: a contact in 20
  /// steps gives its restitution and energy within 2 % for every law of the hard-impact suite
  /// (verification/pounding/hard-impacts.md), whatever its stiffness, where maxStep alone left
  /// contacts shorter than 20 maxStep (10 ms) to one or a few steps.
  int perContact = 20;
  /// Throws InputError{field, reason} (fields maxStep, lookAhead, overshoot, perContact).
  void validate() const;
};

/// Length of the next transient step for models with contact pairs (elements that offer
/// Element::contactPredictor, such as nodeToSurface). Impacts last a few
/// hundredths of a second and start with a jump of the dashpot force, so:
/// - while a pair is closed (or open but predicted, from its gap and gap rate over the last
///   step, to close within lookAhead x the rest of the output step) the step is at most maxStep;
/// - a step in which a pair is predicted to close is cut to end at overshoot x that instant, so
///   the jump falls on a step boundary (event location: without it the impact's error is of the
///   order of the step whatever the step).
/// The prediction is linear in time: t_close = g h_last / (g_last - g) for a gap g that shrank
/// from g_last over the last step h_last. Where it predicts no closing within the rest of the
/// output step, a quadratic one from the last three gaps (their rate and its change) may: a pair
/// near the top of a bounce, whose gap hardly changed over the last step, closes again within
/// the step when it decelerates towards the face (the smallest positive root of
/// g + v t + a t^2 / 2, v the rate at the end of the last step). Every pair's cut counts (the
/// shortest wins).
/// - with perContact n, a pair closed or about to close makes the step at most T_c / n, so that
///   the impact is resolved whatever its stiffness (a step longer than the impact integrates it
///   in one or two steps of the trapezoid rule, whose release force then acts through the next
///   step's average and can throw the bodies apart faster than they met).
/// - a touch whose force jumps or rises with infinite slope (ContactPredictor::touchStep: a
///   dashpot, Jankowski's damping) is held by a step of at most touchStep where that is shorter
///   than the contact step (maxStep, T_c / perContact): the step before ends half a touch step
///   before the predicted touch (the trapezoid rule credits the step holding the touch with half
///   its end force, an error of first order in that step), and while such a pair is closed a
///   step is no longer than the pair's age in contact, the committed time since the start of the
///   step that closed it (steps graded from the touch; a step not committed adds nothing);
/// - the shortest cut is 0.01 maxStep, or a twentieth of the contact step where that is shorter,
///   and a remainder of the output step shorter than it is taken with the step before;
/// - the step after a release step that ended in tension (ContactPredictor::committedTension) is
///   no longer than the release step: the trapezoid rule carries that force through it as well.
///
/// The pairs are read from their committed states (between steps), one pass over the pairs per
/// step; the class owns the gaps of the last step.
class ContactStepping {
 public:
  explicit ContactStepping(const ContactSteppingParams& params) : params_(params) {}

  const ContactSteppingParams& params() const noexcept { return params_; }
  /// Finds the domain's contact pairs (Element::contactPredictor) and forgets the gap history (a
  /// new model or a new analysis).
  void attach(const domain::Domain& domain);
  /// Forgets the gap history (the next step predicts nothing).
  void reset();
  std::size_t pairs() const noexcept { return pairs_.size(); }

  /// Length of the next step, at most `remaining` (the rest of the output step) unless a cut at a
  /// predicted contact ends just past it; `dt` is the output step, to count contact steps.
  double nextStep(double remaining, double dt);
  /// The step nextStep chose last was not committed (the analysis stopped in it): it adds
  /// nothing to a pair's age in contact.
  void stepNotTaken() noexcept { lastTaken_ = false; }
  /// Steps shorter than the output step that this object chose (for statistics).
  long contactSteps() const noexcept { return contactSteps_; }

 private:
  ContactSteppingParams params_;
  std::vector<const elements::ContactPredictor*> pairs_;  ///< the pairs (Element::contactPredictor)
  std::vector<double> lastGap_;
  std::vector<double> lastRate_;   ///< per pair: the gap's rate over the step before the last
  std::vector<double> touchRate_;  ///< per pair: the approach rate when its touch was predicted
  /// per pair: the committed steps since the start of the one at whose end it was first closed
  std::vector<double> closedFor_;
  double previousStep_ = 0.0;                    ///< the step before the last
  std::vector<std::vector<double>> nodeMasses_;  ///< per pair (perContact > 0): its nodes' masses
  double lastStep_ = 0.0;
  bool lastTaken_ = true;  ///< lastStep_ was committed (stepNotTaken)
  long contactSteps_ = 0;
};

}  // namespace dabs::analysis
