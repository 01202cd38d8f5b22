// SPDX-License-Identifier: MIT
#include "tcl/analysis/DisplacementControl.h"

#include <algorithm>
#include <cmath>

namespace dabs::analysis {

DisplacementControl::DisplacementControl(int node, int dof, double incr, int Jd, double dUmin,
                                         double dUmax, bool initialTangent)
    : StaticIntegrator(Jd),
      node_(node),
      dof_(dof),
      incr_(incr),
      dUmin_(dUmin),
      dUmax_(dUmax),
      initialTangent_(initialTangent) {}

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
