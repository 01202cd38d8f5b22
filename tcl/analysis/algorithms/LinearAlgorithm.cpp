// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/LinearAlgorithm.h"

namespace dabs::analysis {

Status LinearAlgorithm::solveCurrentStep(LinearSystem& system, Integrator& integrator,
                                         ConvergenceTest* /*test*/) {
  iterations_ = 0;
  const StiffnessKind kind = initial_ ? StiffnessKind::Initial : StiffnessKind::Current;
  const AssemblyCoefficients c = integrator.coefficients(kind);
  if (!(factorOnce_ && factoredOnce_)) {
    const bool reuse = initial_ || system.model().allLinear();
    const Status s = system.formTangent(c, reuse);
    if (!ok(s)) return s;
    factoredOnce_ = true;
  }
  system.formResidual(c);
  Status s = system.solve();
  if (!ok(s)) return s;
  countIteration();
  return integrator.update(system, system.X);
}

}  // namespace dabs::analysis
