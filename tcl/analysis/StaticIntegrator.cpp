// SPDX-License-Identifier: MIT
#include "tcl/analysis/StaticIntegrator.h"

#include <algorithm>

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

}  // namespace dabs::analysis
