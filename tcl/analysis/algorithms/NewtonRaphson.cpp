// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/NewtonRaphson.h"

#include <limits>

namespace dabs::analysis {

Status NewtonRaphson::solveCurrentStep(LinearSystem& system, Integrator& integrator,
                                       ConvergenceTest* test) {
  if (test == nullptr) return Status::Failed;
  iterations_ = 0;
  const bool linear = system.model().allLinear();
  system.formResidual(integrator.coefficients(StiffnessKind::Current));
  test->start();
  bool formTangent = true;  // modified Newton forms it at the first iteration (and after a switch)
  bool holding = false;     // some element's status is held
  double lastNorm = std::numeric_limits<double>::infinity();
  for (;;) {
    StiffnessKind kind = StiffnessKind::Current;
    if (tangent_ == Tangent::Initial ||
        (tangent_ == Tangent::InitialThenCurrent && iterations_ == 0))
      kind = StiffnessKind::Initial;
    const AssemblyCoefficients c = integrator.coefficients(kind);
    if (!modified_ || formTangent) {
      formTangent = false;
      // A constant matrix (initial stiffness, or a linear model) is factorised only when the
      // step coefficients change; a current tangent at every iteration otherwise.
      const Status s = system.formTangent(c, kind == StiffnessKind::Initial || linear);
      if (!ok(s)) return s;
    }
    Status s = system.solve();
    if (!ok(s)) return s;
    s = integrator.update(system, system.X);
    if (!ok(s)) return s;
    if (!modified_ && kind == StiffnessKind::Current && integrator.additiveUpdate()) {
      // A power-law contact whose deep penetration Newton shrinks only to a third an iteration
      // asks for the step Newton on its force would take (Element::newtonStepScale); the test
      // sees the step taken, as after a line search.
      if (const double scale = system.model().newtonStepScale(); scale != 1.0) {
        extraStep_ = (scale - 1.0) * system.X;
        s = integrator.update(system, extraStep_);
        if (!ok(s)) return s;
        system.X *= scale;
      }
    }
    system.formResidual(c);
    countIteration();
    const Next next = afterTest(test->test(system.X, system.B), system, c);
    // Modified Newton forms its tangent anew when it holds the statuses (its tangent is that of
    // the step's start, which may miss a contact that closed since), after a switch, and while
    // statuses are held whenever the norm grows (a held release force is strongly curved).
    if (heldNow()) {
      holding = true;
      formTangent = true;
    }
    if (holding && test->lastNorm() > lastNorm) formTangent = true;
    lastNorm = test->lastNorm();
    switch (next) {
      case Next::Converged: return Status::Ok;
      case Next::Failed: return Status::NotConverged;
      case Next::Switched: formTangent = true; break;  // a switched status changes the tangent
      case Next::IterateOn: break;
    }
  }
}

}  // namespace dabs::analysis
