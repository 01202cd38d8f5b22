// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/TRBDF2.h"

namespace dabs::analysis {

void TRBDF2::domainChanged(LinearSystem& system) {
  Integrator::domainChanged(system);
  Ut_ = Utm1_ = U_;
  Vt_ = Vtm1_ = V_;
  At_ = A_;
}

Status TRBDF2::newStep(LinearSystem& system, double dt) {
  if (!(dt > 0.0)) return Status::Failed;
  backwardDifference_ = !(dt != dt_ || backwardDifference_);
  dt_ = dt;
  Utm1_ = Ut_;
  Vtm1_ = Vt_;
  Ut_ = U_;
  Vt_ = V_;
  At_ = A_;
  if (!backwardDifference_) {
    // Trapezoidal rule with u_{n+1} = u_n: v = 2/dt du - v_n, a = 4/dt^2 du - 4/dt v_n - a_n.
    c2_ = 2.0 / dt;
    c3_ = 4.0 / (dt * dt);
    V_ = -Vt_;
    A_ = (-4.0 / dt) * Vt_ - At_;
  } else {
    // Three-point backward difference with u_{n+1} = u_n.
    c2_ = 1.5 / dt;
    c3_ = 2.25 / (dt * dt);
    V_ = (Utm1_ - Ut_) / (2.0 * dt);
    A_ = (Vtm1_ - 4.0 * Vt_ + 3.0 * V_) / (2.0 * dt);
  }
  AnalysisModel& model = system.model();
  model.applyLoad(model.domain().committedTime() + dt);
  return push(system);
}

Status TRBDF2::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  U_ += dx;
  V_ += c2_ * dx;
  A_ += c3_ * dx;
  return push(system);
}

AssemblyCoefficients TRBDF2::coefficients(StiffnessKind k) const {
  AssemblyCoefficients c;
  c.cK = 1.0;
  c.cC = c2_;
  c.cM = c3_;
  c.stiffness = k;
  c.dynamic = true;
  return c;
}

void TRBDF2::revertToLastStep() {
  if (Ut_.size() == U_.size()) {
    U_ = Ut_;
    V_ = Vt_;
    A_ = At_;
  }
  backwardDifference_ = true;  // the next step restarts with the trapezoidal rule
}

}  // namespace dabs::analysis
