// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/DisplacementControl.h"

#include <algorithm>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::analysis {

void DisplacementControl::Params::validate() const {
  if (dof < 0) throw InputError("dof", "must be 1 or more");
  if (!std::isfinite(incr)) throw InputError("incr", "must be a finite number");
  if (Jd < 1) throw InputError("Jd", "must be at least 1");
  if (!std::isfinite(dUmin)) throw InputError("dUmin", "must be a finite number");
  if (!std::isfinite(dUmax)) throw InputError("dUmax", "must be a finite number");
}

DisplacementControl::DisplacementControl(const Params& params)
    : StaticIntegrator(params.Jd),
      node_(params.node),
      dof_(params.dof),
      incr_(params.incr),
      dUmin_(params.dUmin),
      dUmax_(params.dUmax),
      initialTangent_(params.initialTangent) {
  params.validate();
}

void DisplacementControl::domainChanged(LinearSystem& system) {
  StaticIntegrator::domainChanged(system);
  AnalysisModel& model = system.model();
  equation_ = model.equationOf(node_, dof_);
  lambda_ = model.domain().committedTime();
  phat_ = referenceLoad(system, lambda_);
}

Status DisplacementControl::newStep(LinearSystem& system, double /*dt*/) {
  if (equation_ < 0 || phat_.size() == 0 || phat_.isZero(0.0)) return Status::Failed;
  incr_ = adaptStep(incr_, dUmin_, dUmax_);
  AnalysisModel& model = system.model();
  lambda_ = model.domain().committedTime();
  const Status st = system.formTangent(
      coefficients(initialTangent_ ? StiffnessKind::Initial : StiffnessKind::Current));
  if (!ok(st)) return st;
  const Status ss = system.solve(phat_, dUhat_);
  if (!ok(ss)) return ss;
  dUahat_ = dUhat_(equation_);
  if (dUahat_ == 0.0 || !std::isfinite(dUahat_)) return Status::Singular;
  const double dLambda = incr_ / dUahat_;
  lambda_ += dLambda;
  U_ += dLambda * dUhat_;
  model.applyLoad(lambda_);
  return push(system);
}

Status DisplacementControl::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  if (equation_ < 0) return Status::Failed;
  const Status ss = system.solve(phat_, dUhat_);
  if (!ok(ss)) return ss;
  dUahat_ = dUhat_(equation_);
  if (dUahat_ == 0.0 || !std::isfinite(dUahat_)) return Status::Singular;
  const double dLambda = -dx(equation_) / dUahat_;
  deltaU_ = dx + dLambda * dUhat_;
  U_ += deltaU_;
  lambda_ += dLambda;
  system.model().applyLoad(lambda_);
  system.X = deltaU_;  // tests see the corrected increment, as in OpenSees
  countIteration();
  return push(system);
}

void DisplacementControl::setStepSize(double incr) {
  incr_ = incr;
  resetAdaptation();
}

}  // namespace dabs::analysis
