// SPDX-License-Identifier: MIT
#include "tcl/analysis/LoadControl.h"

#include <algorithm>

namespace dabs::analysis {

LoadControl::LoadControl(double dLambda, int Jd, double minLambda, double maxLambda)
    : dLambda_(dLambda), Jd_(Jd), minLambda_(minLambda), maxLambda_(maxLambda),
      iterationsLastStep_(Jd) {}

void LoadControl::domainChanged(LinearSystem& system) {
  Integrator::domainChanged(system);
  V_.setZero();
  A_.setZero();
  Ucommitted_ = U_;
}

Status LoadControl::newStep(LinearSystem& system, double /*dt*/) {
  if (iterationsLastStep_ > 0) dLambda_ *= static_cast<double>(Jd_) / iterationsLastStep_;
  const double lo = std::min(minLambda_, maxLambda_), hi = std::max(minLambda_, maxLambda_);
  dLambda_ = std::clamp(dLambda_, lo, hi);
  iterationsLastStep_ = 0;
  AnalysisModel& model = system.model();
  model.applyLoad(model.domain().committedTime() + dLambda_);
  return push(system);
}

Status LoadControl::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  U_ += dx;
  ++iterationsLastStep_;
  return push(system);
}

AssemblyCoefficients LoadControl::coefficients(StiffnessKind k) const {
  AssemblyCoefficients c;
  c.stiffness = k;
  return c;
}

Status LoadControl::commit(LinearSystem& system) {
  Ucommitted_ = U_;
  return Integrator::commit(system);
}

void LoadControl::setStepSize(double dLambda) {
  dLambda_ = dLambda;
  iterationsLastStep_ = Jd_;
}

}  // namespace dabs::analysis
