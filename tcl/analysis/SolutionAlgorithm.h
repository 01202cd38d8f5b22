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
  /// What a converged test means once the switching elements' statuses are settled.
  enum class Settled {
    Converged,  ///< every held status agrees with the converged state (or none is held)
    IterateOn,  ///< a status switched: the elements were updated and the residual formed anew
    Failed      ///< an element found no status that agrees (Element::HeldStatus::Conflict)
  };
  /// Holds the switching elements' statuses once the iterations of the step reach kHoldAfter
  /// (call after each iteration's test). Returns true when it held some element's status.
  bool holdStatusesIfDue(LinearSystem& system);
  /// To call when the test says converged: checks the held statuses and, when one switched,
  /// updates the elements at the same displacements and forms the residual with `c`.
  Settled settleStatuses(LinearSystem& system, const AssemblyCoefficients& c);
  /// Counts an iteration.
  void countIteration() noexcept {
    ++iterations_;
    ++totalIterations_;
  }
  int iterations_ = 0;
  long totalIterations_ = 0;
};

}  // namespace dabs::analysis
