// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/ArcLength.h"

#include <cmath>

#include "materials/InputError.h"

namespace dabs::analysis {

void ArcLength::Params::validate() const {
  if (!(arcLength > 0.0) || !std::isfinite(arcLength))
    throw InputError("arcLength", "must be positive");
  // A negative or infinite weight (uRef = 0 in HSConstraint) makes the constraint meaningless.
  if (!(wU >= 0.0) || !std::isfinite(wU)) throw InputError("wU", "must be finite and >= 0");
  if (!(wF >= 0.0) || !std::isfinite(wF)) throw InputError("wF", "must be finite and >= 0");
  if (wU == 0.0 && wF == 0.0) throw InputError("", "wU and wF must not both be zero");
}

ArcLength::ArcLength(const Params& params)
    : StaticIntegrator(1),
      arcLength_(params.arcLength),
      wU_(params.wU),
      wF_(params.wF),
      loadScaled_(params.loadScaled) {
  params.validate();
}

void ArcLength::domainChanged(LinearSystem& system) {
  StaticIntegrator::domainChanged(system);
  AnalysisModel& model = system.model();
  lambda_ = model.domain().committedTime();
  phat_ = referenceLoad(system, lambda_);
  wFEffective_ = loadScaled_ ? wF_ * phat_.squaredNorm() : wF_;
  dUstep_ = Eigen::VectorXd::Zero(phat_.size());
}

Status ArcLength::newStep(LinearSystem& system, double /*dt*/) {
  if (phat_.size() == 0 || phat_.isZero(0.0)) return Status::Failed;
  AnalysisModel& model = system.model();
  lambda_ = model.domain().committedTime();
  const double sign = dLambdaStep_ < 0.0 ? -1.0 : 1.0;
  const Status st = system.formTangent(coefficients(StiffnessKind::Current));
  if (!ok(st)) return st;
  const Status ss = system.solve(phat_, dUhat_);
  if (!ok(ss)) return ss;
  const double norm = wU_ * dUhat_.squaredNorm() + wFEffective_;
  if (!(norm > 0.0) || !std::isfinite(norm)) return Status::Singular;
  const double dLambda = sign * arcLength_ / std::sqrt(norm);
  dLambdaStep_ = dLambda;
  lambda_ += dLambda;
  dUstep_ = dLambda * dUhat_;
  U_ += dUstep_;
  model.applyLoad(lambda_);
  return push(system);
}

Status ArcLength::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  // dx is dUbar, the correction for the unbalance at fixed load; dUhat the one for phat.
  const Status ss = system.solve(phat_, dUhat_);
  if (!ok(ss)) return ss;
  // wU |dUstep + dUbar + d dUhat|^2 + wF (dLambdaStep + d)^2 = s^2, solved for d (Crisfield 1981).
  dU_ = dUstep_ + dx;
  const double a = wU_ * dUhat_.squaredNorm() + wFEffective_;
  const double b = 2.0 * (wU_ * dUhat_.dot(dU_) + wFEffective_ * dLambdaStep_);
  const double c = wU_ * dU_.squaredNorm() + wFEffective_ * dLambdaStep_ * dLambdaStep_ -
                   arcLength_ * arcLength_;
  double d = 0.0;
  if (a == 0.0) {
    if (b == 0.0) return Status::Singular;
    d = -c / b;
  } else {
    const double disc = b * b - 4.0 * a * c;
    // No real root: the constraint circle misses the linearised path (step too large near
    // several instabilities); OpenSees fails the step too.
    if (disc < 0.0 || !std::isfinite(disc)) return Status::Failed;
    const double q = std::sqrt(disc);
    const double d1 = (-b + q) / (2.0 * a), d2 = (-b - q) / (2.0 * a);
    // Keep going the step's way: the root whose new increment points most along the old one.
    const double base = dUstep_.dot(dU_), along = dUstep_.dot(dUhat_);
    d = base + d1 * along >= base + d2 * along ? d1 : d2;
  }
  dU_ = dx + d * dUhat_;
  dUstep_ += dU_;
  dLambdaStep_ += d;
  lambda_ += d;
  U_ += dU_;
  system.model().applyLoad(lambda_);
  system.X = dU_;  // tests see the corrected increment, as in OpenSees
  return push(system);
}

}  // namespace dabs::analysis
