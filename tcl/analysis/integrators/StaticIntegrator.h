// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/Integrator.h"

namespace dabs::analysis {

/// What load and displacement control share: static coefficients (K only), the committed
/// displacement to revert to, and the step size adapted to the iterations of the last step,
/// step *= Jd / iterations, kept within [min, max] (OpenSees
/// LoadControl/DisplacementControl::newStep).
class StaticIntegrator : public Integrator {
 public:
  explicit StaticIntegrator(int Jd) : Jd_(Jd), iterationsLastStep_(Jd) {}
  bool transient() const final { return false; }
  void domainChanged(LinearSystem& system) override;
  AssemblyCoefficients coefficients(StiffnessKind k) const final;
  Status commit(LinearSystem& system) final;
  void revertToLastStep() final { U_ = Ucommitted_; }

 protected:
  /// Scales `step` by Jd / (iterations of the last step), clamps it, and restarts the count.
  double adaptStep(double step, double bound1, double bound2);
  /// Counts one corrector iteration.
  void countIteration() noexcept { ++iterationsLastStep_; }
  /// Makes the next step use `step` unscaled (OpenSees setDeltaLambda).
  void resetAdaptation() noexcept { iterationsLastStep_ = Jd_; }
  /// Reference load of the path-following integrators: the unbalance at load factor lambda + 1
  /// with the committed state (for an equilibrated state, the load pattern; OpenSees
  /// DisplacementControl::domainChanged), zero when the model cannot be pushed there. The load is
  /// left at lambda.
  Eigen::VectorXd referenceLoad(LinearSystem& system, double lambda);

 private:
  int Jd_;
  int iterationsLastStep_;
  Eigen::VectorXd Ucommitted_;
};

}  // namespace dabs::analysis
