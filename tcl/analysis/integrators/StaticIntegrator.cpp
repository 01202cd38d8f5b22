// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/StaticIntegrator.h"

#include <algorithm>

#include "tcl/analysis/system/LinearSystem.h"

namespace dabs::analysis {

void StaticIntegrator::domainChanged(LinearSystem& system) {
  Integrator::domainChanged(system);
  V_.setZero();
  A_.setZero();
  Ucommitted_ = U_;
}

AssemblyCoefficients StaticIntegrator::coefficients(StiffnessKind k) const {
  AssemblyCoefficients c;
  c.stiffness = k;
  return c;
}

Status StaticIntegrator::commit(LinearSystem& system) {
  Ucommitted_ = U_;
  return Integrator::commit(system);
}

double StaticIntegrator::adaptStep(double step, double bound1, double bound2) {
  if (iterationsLastStep_ > 0) step *= static_cast<double>(Jd_) / iterationsLastStep_;
  iterationsLastStep_ = 0;
  return std::clamp(step, std::min(bound1, bound2), std::max(bound1, bound2));
}

Eigen::VectorXd StaticIntegrator::referenceLoad(LinearSystem& system, double lambda) {
  AnalysisModel& model = system.model();
  model.applyLoad(lambda + 1.0);
  Eigen::VectorXd phat = Eigen::VectorXd::Zero(model.numEquations());
  if (ok(push(system))) {
    system.formResidual(coefficients(StiffnessKind::Current));
    phat = system.B;
  }
  model.applyLoad(lambda);
  return phat;
}

}  // namespace dabs::analysis
