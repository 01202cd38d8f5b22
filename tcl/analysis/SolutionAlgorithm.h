// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/ConvergenceTest.h"
#include "tcl/analysis/Integrator.h"
#include "tcl/analysis/LinearSystem.h"

namespace dabs::analysis {

/// Solves the equations of one step (OpenSees' EquiSolnAlgo family): iterates
/// form tangent -> solve -> integrator update -> form residual -> test.
class SolutionAlgorithm {
 public:
  virtual ~SolutionAlgorithm() = default;
  /// Solves the current step; the integrator's predictor has already run. `test` may be null
  /// only for algorithms that need none (Linear).
  [[nodiscard]] virtual Status solveCurrentStep(LinearSystem& system, Integrator& integrator,
                                                ConvergenceTest* test) = 0;
  /// True when the algorithm needs a convergence test.
  virtual bool needsTest() const { return true; }
  /// Iterations of the last step.
  int iterations() const noexcept { return iterations_; }
  /// Total iterations since creation (for benchmarks).
  long totalIterations() const noexcept { return totalIterations_; }

 protected:
  /// Counts an iteration.
  void countIteration() noexcept {
    ++iterations_;
    ++totalIterations_;
  }
  int iterations_ = 0;
  long totalIterations_ = 0;
};

}  // namespace dabs::analysis
