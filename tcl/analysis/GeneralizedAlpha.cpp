// SPDX-License-Identifier: MIT
#include "tcl/analysis/GeneralizedAlpha.h"

namespace dabs::analysis {

GeneralizedAlpha::GeneralizedAlpha(double alphaM, double alphaF, double gamma, double beta)
    : alphaM_(alphaM), alphaF_(alphaF), gamma_(gamma), beta_(beta) {}

void GeneralizedAlpha::domainChanged(LinearSystem& system) {
  Integrator::domainChanged(system);
  Ut_ = U_;
  Vt_ = V_;
  At_ = A_;
}

Status GeneralizedAlpha::newStep(LinearSystem& system, double dt) {
  if (dt <= 0.0 || beta_ == 0.0 || gamma_ == 0.0) return Status::Failed;
  dt_ = dt;
  c2_ = gamma_ / (beta_ * dt);
  c3_ = 1.0 / (beta_ * dt * dt);
  Ut_ = U_;
  Vt_ = V_;
  At_ = A_;
  // Newmark predictor with an unchanged displacement (OpenSees Newmark::newStep, displacement
  // form).
  V_ = (1.0 - gamma_ / beta_) * Vt_ + dt * (1.0 - 0.5 * gamma_ / beta_) * At_;
  A_ = (-1.0 / (beta_ * dt)) * Vt_ + (1.0 - 0.5 / beta_) * At_;
  AnalysisModel& model = system.model();
  tn_ = model.domain().committedTime();
  model.applyLoad(tn_ + alphaF_ * dt);
  return pushWeighted(system);
}

Status GeneralizedAlpha::pushWeighted(LinearSystem& system) {
  if (alphaF_ == 1.0 && alphaM_ == 1.0) return push(system);
  Ua_ = (1.0 - alphaF_) * Ut_ + alphaF_ * U_;
  Va_ = (1.0 - alphaF_) * Vt_ + alphaF_ * V_;
  Aa_ = (1.0 - alphaM_) * At_ + alphaM_ * A_;
  if (!Ua_.allFinite() || !Va_.allFinite() || !Aa_.allFinite()) return Status::NonFinite;
  system.model().setResponse(Ua_, Va_, Aa_);
  return system.model().updateElements();
}

Status GeneralizedAlpha::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  U_ += dx;
  V_ += c2_ * dx;
  A_ += c3_ * dx;
  return pushWeighted(system);
}

AssemblyCoefficients GeneralizedAlpha::coefficients(StiffnessKind k) const {
  AssemblyCoefficients c;
  c.cK = alphaF_;
  c.cC = alphaF_ * c2_;
  c.cM = alphaM_ * c3_;
  c.stiffness = k;
  c.dynamic = true;
  return c;
}

Status GeneralizedAlpha::commit(LinearSystem& system) {
  if (alphaF_ != 1.0 || alphaM_ != 1.0) {
    // Elements are brought to the state at t_{n+1} before committing (OpenSees HHT::commit).
    system.model().applyLoad(tn_ + dt_);
    const Status s = push(system);
    if (!ok(s)) return s;
  }
  return Integrator::commit(system);
}

void GeneralizedAlpha::revertToLastStep() {
  if (Ut_.size() == U_.size()) {
    U_ = Ut_;
    V_ = Vt_;
    A_ = At_;
  }
}

}  // namespace dabs::analysis
