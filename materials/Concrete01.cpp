// SPDX-License-Identifier: MIT
#include "materials/Concrete01.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void Concrete01::Params::validate() const {
  if (!std::isfinite(fpc) || fpc == 0.0) throw InputError("fpc", "must be nonzero");
  if (!std::isfinite(epsc0) || epsc0 == 0.0) throw InputError("epsc0", "must be nonzero");
  if (!std::isfinite(fpcu) || std::fabs(fpcu) > std::fabs(fpc))
    throw InputError("fpcu", "must not exceed fpc in magnitude");
  if (!std::isfinite(epsU) || std::fabs(epsU) <= std::fabs(epsc0))
    throw InputError("epsU", "must exceed epsc0 in magnitude (crushing after the peak)");
}

Concrete01::Params Concrete01::Params::normalized() const {
  return Params{-std::fabs(fpc), -std::fabs(epsc0), -std::fabs(fpcu), -std::fabs(epsU)};
}

Concrete01::Concrete01(int tag, const Params& params)
    : StatefulUniaxial(tag), params_(params.normalized()) {
  assert(params_.fpc < 0.0 && params_.epsc0 < 0.0 && params_.epsU < params_.epsc0);
  revertToStart();
}

Concrete01::State Concrete01::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  s.unloadSlope = s.tangent;
  return s;
}

// Monotonic envelope (Kent & Park 1971 with the Scott et al. 1982 descending branch).
void Concrete01::envelope(State& s) const {
  const auto& p = params_;
  if (s.strain > p.epsc0) {
    const double eta = s.strain / p.epsc0;
    s.stress = p.fpc * (2.0 * eta - eta * eta);
    s.tangent = 2.0 * p.fpc / p.epsc0 * (1.0 - eta);
  } else if (s.strain > p.epsU) {
    s.tangent = (p.fpc - p.fpcu) / (p.epsc0 - p.epsU);
    s.stress = p.fpc + s.tangent * (s.strain - p.epsc0);
  } else {
    s.stress = p.fpcu;
    s.tangent = 0.0;
  }
}

// Unloading line from the envelope point at minStrain: zero-stress strain from Karsan & Jirsa
// (1969), eps_end/epsc0 = 0.145*eta^2 + 0.13*eta (eta < 2) or 0.707*(eta-2) + 0.834, limited so
// that the line is never stiffer than the initial modulus.
void Concrete01::unload(State& s) const {
  const auto& p = params_;
  const double strainForRatio = s.minStrain < p.epsU ? p.epsU : s.minStrain;
  const double eta = strainForRatio / p.epsc0;
  const double ratio = eta < 2.0 ? 0.145 * eta * eta + 0.13 * eta : 0.707 * (eta - 2.0) + 0.834;
  s.endStrain = ratio * p.epsc0;
  const double span = s.minStrain - s.endStrain;  // negative
  const double Ec0 = getInitialTangent();
  const double elasticSpan = s.stress / Ec0;
  if (span > -DBL_EPSILON) {
    s.unloadSlope = Ec0;
  } else if (span <= elasticSpan) {
    s.endStrain = s.minStrain - span;
    s.unloadSlope = s.stress / span;
  } else {
    s.endStrain = s.minStrain - elasticSpan;
    s.unloadSlope = Ec0;
  }
}

void Concrete01::reload(State& s) const {
  if (s.strain <= s.minStrain) {
    s.minStrain = s.strain;
    envelope(s);
    unload(s);
  } else if (s.strain <= s.endStrain) {
    s.tangent = s.unloadSlope;
    s.stress = s.tangent * (s.strain - s.endStrain);
  } else {
    s.stress = 0.0;
    s.tangent = 0.0;
  }
}

Status Concrete01::setTrialStrain(double strain, double /*strainRate*/) {
  trial_ = committed_;
  if (std::fabs(strain - committed_.strain) < DBL_EPSILON) return Status::Ok;
  trial_.strain = strain;
  if (strain > 0.0) {  // no tensile strength
    trial_.stress = 0.0;
    trial_.tangent = 0.0;
    return Status::Ok;
  }
  // Line through the committed point with the committed unloading slope. It meets the
  // envelope exactly where a reloading line rejoins it, so the evaluation order decides ties;
  // it is kept as in OpenSees (sig_c + k*eps - k*eps_c) to reproduce its branch choice.
  const double linear = committed_.stress + committed_.unloadSlope * strain -
                        committed_.unloadSlope * committed_.strain;
  if (strain < committed_.strain) {
    reload(trial_);
    if (linear > trial_.stress) {
      trial_.stress = linear;
      trial_.tangent = trial_.unloadSlope;
    }
  } else if (linear <= 0.0) {
    trial_.stress = linear;
    trial_.tangent = committed_.unloadSlope;
  } else {
    trial_.stress = 0.0;
    trial_.tangent = 0.0;
  }
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

std::unique_ptr<UniaxialMaterial> Concrete01::clone() const {
  return std::make_unique<Concrete01>(*this);
}

}  // namespace dabs::materials
