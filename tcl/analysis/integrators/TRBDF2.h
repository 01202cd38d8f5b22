// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/Integrator.h"

namespace dabs::analysis {

/// Bathe's composite scheme as OpenSees runs it (`integrator TRBDF2`; Bathe and Baig 2005,
/// OpenSees/OpenSees:SRC/analysis/integrator/TRBDF2.cpp): successive steps of the same size dt
/// alternate between the trapezoidal rule (Newmark gamma = 1/2, beta = 1/4) and the three-point
/// backward difference over the last two steps,
///   v_{n+1} = (3 u_{n+1} - 4 u_n + u_{n-1}) / (2 dt),  a_{n+1} = (3 v_{n+1} - 4 v_n + v_{n-1}) /
///   (2 dt).
/// A new step size, or a step after a failed one, starts again with the trapezoidal rule. The
/// unknown is the displacement increment; the predictor keeps the displacement.
class TRBDF2 final : public Integrator {
 public:
  bool transient() const override { return true; }
  void domainChanged(LinearSystem& system) override;
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  bool additiveUpdate() const override { return true; }
  AssemblyCoefficients coefficients(StiffnessKind k) const override;
  void revertToLastStep() override;

 private:
  bool backwardDifference_ = true;  ///< the step under way is the BDF2 one (next: trapezoidal)
  double dt_ = 0.0;
  double c2_ = 0.0, c3_ = 0.0;    ///< dv/du and da/du of the step
  Eigen::VectorXd Ut_, Vt_, At_;  ///< committed state at the start of the step
  Eigen::VectorXd Utm1_, Vtm1_;   ///< state one step earlier
};

}  // namespace dabs::analysis
