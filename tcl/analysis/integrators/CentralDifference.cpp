// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/CentralDifference.h"

namespace dabs::analysis {

void CentralDifference::domainChanged(LinearSystem& system) {
  Integrator::domainChanged(system);
  Un_ = Uprev_ = U_;
  Vn_ = V_;
  An_ = A_;
}

Status CentralDifference::newStep(LinearSystem& system, double dt) {
  if (dt <= 0.0) return Status::Failed;
  dt_ = dt;
  updates_ = 0;
  UprevSaved_ = Uprev_;
  UnSaved_ = Un_;
  VnSaved_ = Vn_;
  AnSaved_ = An_;
  const double c2 = 0.5 / dt, c3 = 1.0 / (dt * dt);
  // Velocity and acceleration chosen so the residual P - R(u_n) - C v - M a is the right-hand side
  // of the central-difference equation (OpenSees CentralDifference::newStep).
  U_ = Un_;
  V_ = -c2 * Uprev_;
  A_ = -2.0 * c3 * Un_ + c3 * Uprev_;
  AnalysisModel& model = system.model();
  model.applyLoad(model.domain().committedTime());
  return push(system);
}

Status CentralDifference::update(LinearSystem& system, const Eigen::VectorXd& x) {
  if (++updates_ > 1) return Status::Failed;  // needs algorithm Linear: one solve per step
  // Backward differences at t_{n+1}, as OpenSees reports them.
  U_ = x;
  V_ = (3.0 * x - 4.0 * Un_ + Uprev_) / (2.0 * dt_);
  A_ = (V_ - Vn_) / dt_;
  Uprev_ = Un_;
  Un_ = x;
  Vn_ = V_;
  An_ = A_;
  system.model().applyLoad(system.model().domain().committedTime() + dt_);
  return push(system);
}

AssemblyCoefficients CentralDifference::coefficients(StiffnessKind k) const {
  AssemblyCoefficients c;
  c.cK = 0.0;
  c.cC = 0.5 / dt_;
  c.cM = 1.0 / (dt_ * dt_);
  c.stiffness = k;
  c.dynamic = true;
  return c;
}

Status CentralDifference::commit(LinearSystem& system) { return Integrator::commit(system); }

void CentralDifference::revertToLastStep() {
  if (UprevSaved_.size() == Uprev_.size()) {
    Uprev_ = UprevSaved_;
    Un_ = UnSaved_;
    Vn_ = VnSaved_;
    An_ = AnSaved_;
  }
}

}  // namespace dabs::analysis
