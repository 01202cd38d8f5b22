// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/algorithms/SolutionAlgorithm.h"

namespace dabs::analysis {

/// Newton-Raphson (`algorithm Newton ?-initial|-initialThenCurrent?`) and modified Newton
/// (`algorithm ModifiedNewton ?-initial?`, tangent formed once per step). With -initial the
/// initial stiffness is factorised once and reused while the step coefficients stay the same.
/// Newton (current tangent) lengthens a step when an element asks for it
/// (Element::newtonStepScale: a power-law contact leaving a deep penetration) and the
/// integrator's update is additive (Integrator::additiveUpdate: the time-stepping ones).
class NewtonRaphson final : public SolutionAlgorithm {
 public:
  enum class Tangent { Current, Initial, InitialThenCurrent };
  NewtonRaphson(Tangent tangent, bool modified) : tangent_(tangent), modified_(modified) {}
  Status solveCurrentStep(LinearSystem& system, Integrator& integrator,
                          ConvergenceTest* test) override;

 private:
  Tangent tangent_;
  bool modified_;
  Eigen::VectorXd extraStep_;  ///< the part of a lengthened step added after the first update
};

}  // namespace dabs::analysis
