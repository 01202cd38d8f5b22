// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/GeneralizedAlpha.h"

#include <cmath>
#include <string>
#include <utility>

#include "materials/InputError.h"

namespace dabs::analysis {

void GeneralizedAlpha::Params::validate() const {
  for (const auto& [name, value] :
       {std::pair{"alphaM", alphaM}, {"alphaF", alphaF}, {"gamma", gamma}, {"beta", beta}})
    if (!std::isfinite(value)) throw InputError(name, "must be a finite number");
  if (!(gamma > 0.0)) throw InputError("gamma", "must be positive");
  if (!(beta > 0.0)) throw InputError("beta", "must be positive");
  // The Tcl parser allows the same round-off below the bounds (values typed with few digits).
  constexpr double kRoundOff = 1e-12;
  if (alphaM == 1.0 && alphaF == 1.0) {
    // Newmark's amplification matrix has a root above 1 for every step when gamma < 1/2.
    if (gamma < 0.5 - kRoundOff)
      throw InputError("gamma", "must be at least 1/2 (below it Newmark's step is unstable)");
    return;
  }
  // Chung & Hulbert (1993) eq. 25 with alpha_m = 1 - alphaM, alpha_f = 1 - alphaF.
  if (!(alphaF >= 0.5 && alphaF <= 1.0 && alphaM >= alphaF && alphaM <= 2.0))
    throw InputError("alphaF",
                     "and alphaM must satisfy 1/2 <= alphaF <= alphaM <= 2 and alphaF <= 1 for "
                     "unconditional stability (Chung & Hulbert 1993)");
  const double d = alphaM - alphaF;
  if (gamma < 0.5 + d - kRoundOff)
    throw InputError("gamma",
                     "must be at least 1/2 + alphaM - alphaF = " + std::to_string(0.5 + d) +
                         " for unconditional stability (Chung & Hulbert 1993)");
  if (beta < 0.25 + 0.5 * d - kRoundOff)
    throw InputError(
        "beta", "must be at least 1/4 + (alphaM - alphaF)/2 = " + std::to_string(0.25 + 0.5 * d) +
                    " for unconditional stability (Chung & Hulbert 1993)");
}

GeneralizedAlpha::GeneralizedAlpha(const Params& params)
    : alphaM_(params.alphaM), alphaF_(params.alphaF), gamma_(params.gamma), beta_(params.beta) {
  params.validate();
}

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
