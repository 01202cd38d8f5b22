// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/algorithms/ConvergenceTest.h"
#include "tcl/analysis/integrators/Integrator.h"
#include "tcl/analysis/system/LinearSystem.h"

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

  /// Iterations after which the statuses of switching elements are held (Element::HeldStatus,
  /// an active-set method): the first iterations follow the elements' own statuses as plain
  /// Newton does, so a step that converges within them is unchanged bit for bit; from then on the
  /// step's equations are smooth, Newton converges on them, and a status that the converged state
  /// contradicts is switched and the iterations go on. Two lets a contact's status settle by itself
  /// in a step whose first iteration crosses one switch (closing, opening, sticking to sliding);
  /// holding later cost more iterations on the plain impact of verification/pounding
  /// (plain-impact.tcl: 11 in an impact step with three, and modified Newton failed with four).
  static constexpr int kHoldAfter = 2;

 protected:
  /// What the iterations do after an iteration's test, once the switching elements' statuses
  /// are held (when due) and, on a converged test, settled.
  enum class Next {
    Converged,  ///< converged, and every held status agrees with the state (or none is held)
    Failed,     ///< the test failed, or an element found no status that agrees
    IterateOn,  ///< not converged yet
    Switched    ///< converged, but a held status switched: the elements were updated at the same
                ///< displacements and the residual formed anew with `c`; iterate on
  };
  /// Holds the statuses when the iterations reach kHoldAfter (heldNow() then says so) and, on a
  /// converged test, checks them (Element::HeldStatus).
  Next afterTest(ConvergenceTest::Result result, LinearSystem& system,
                 const AssemblyCoefficients& c);
  /// True when the last afterTest held some element's status.
  bool heldNow() const noexcept { return heldNow_; }
  /// Counts an iteration.
  void countIteration() noexcept {
    ++iterations_;
    ++totalIterations_;
  }
  int iterations_ = 0;
  long totalIterations_ = 0;

 private:
  bool heldNow_ = false;
};

}  // namespace dabs::analysis
