// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "tcl/analysis/model/AnalysisModel.h"
#include "tcl/analysis/system/LinearSystem.h"

namespace dabs::analysis {

/// Advances the state over one step and turns a solved increment into a new trial state
/// (OpenSees' IncrementalIntegrator family). The unknowns live in equation space: U, V, A.
class Integrator {
 public:
  virtual ~Integrator() = default;
  /// True for time-stepping (Newmark, ...); false for static load or displacement control.
  virtual bool transient() const = 0;
  /// Re-reads the committed state after the equations were (re)numbered.
  virtual void domainChanged(LinearSystem& system);
  /// Predictor: sets the time, loads and trial state of a new step of size dt.
  [[nodiscard]] virtual Status newStep(LinearSystem& system, double dt) = 0;
  /// Corrector: applies the solution dx of A dx = B.
  [[nodiscard]] virtual Status update(LinearSystem& system, const Eigen::VectorXd& dx) = 0;
  /// True when update() is linear in dx and leaves the system alone, so that two updates with
  /// dx1 and dx2 give the state of one with dx1 + dx2 (the time-stepping integrators; the static
  /// ones count iterations or re-solve a constraint in update()).
  virtual bool additiveUpdate() const { return false; }
  /// Tangent and residual coefficients of the current step.
  virtual AssemblyCoefficients coefficients(StiffnessKind k) const = 0;
  /// Commits the converged step (domain commit, which lets recorders record).
  [[nodiscard]] virtual Status commit(LinearSystem& system);
  /// Forgets the trial step (after a failure).
  virtual void revertToLastStep() {}
  /// Step size the integrator would like next (static integrators adapt it); 0 when unused.
  virtual void setStepSize(double /*dt*/) {}
  /// True when the nodes hold the displacements the step commits while the step is checked (the
  /// sleeping contact pairs' test); false when they hold weighted ones (HHT, generalized alpha).
  virtual bool checksCommittedDisplacements() const { return true; }

 protected:
  /// Writes U, V, A to the nodes and updates the elements.
  [[nodiscard]] Status push(LinearSystem& system);
  Eigen::VectorXd U_, V_, A_;
};

}  // namespace dabs::analysis
