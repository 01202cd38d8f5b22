// SPDX-License-Identifier: MIT
#include "materials/ElasticPPGap.h"

#include <cassert>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void ElasticPPGap::Params::validate() const {
  if (!std::isfinite(E) || E <= 0.0) throw InputError("E", "must be positive");
  if (!std::isfinite(Fy) || Fy == 0.0) throw InputError("Fy", "must be nonzero");
  if (!std::isfinite(gap)) throw InputError("gap", "must be a finite number");
  if (!std::isfinite(eta) || eta >= 1.0) throw InputError("eta", "must be less than 1");
}

ElasticPPGap::ElasticPPGap(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.E > 0.0 && params.Fy != 0.0 && params.eta < 1.0);
  revertToStart();
}

double ElasticPPGap::getInitialTangent() const {
  const auto& p = params_;
  return ((p.Fy >= 0.0 && p.gap > 0.0) || (p.Fy < 0.0 && p.gap < 0.0)) ? 0.0 : p.E;
}

ElasticPPGap::State ElasticPPGap::initialState() const {
  State s;
  s.minYieldStrain = params_.gap;
  s.maxYieldStrain = params_.Fy / params_.E + params_.gap;
  respond(s, 0.0, s);
  return s;
}

void ElasticPPGap::respond(const State& from, double strain, State& out) const {
  const auto& p = params_;
  // sgn = +1 for a tension gap, -1 for a compression gap; every comparison is mirrored.
  const double sgn = p.Fy >= 0.0 ? 1.0 : -1.0;
  out.strain = strain;
  if (sgn * strain > sgn * from.maxYieldStrain) {
    // hardening line through (gap + Fy/E, Fy) with slope eta*E
    out.stress = p.Fy + (strain - p.gap - p.Fy / p.E) * p.eta * p.E;
    out.tangent = p.eta * p.E;
  } else if (sgn * strain < sgn * from.minYieldStrain) {
    out.stress = 0.0;
    out.tangent = 0.0;
  } else {
    out.stress = p.E * (strain - from.minYieldStrain);
    out.tangent = p.E;
  }
}

Status ElasticPPGap::setTrialStrain(double strain, double /*strainRate*/) {
  const auto& p = params_;
  const double sgn = p.Fy >= 0.0 ? 1.0 : -1.0;
  trial_ = committed_;
  respond(committed_, strain, trial_);
  // The elastic range this trial leaves behind (OpenSees updates it in commitState; here it is
  // part of the trial state so that commit is a plain copy).
  if (sgn * strain > sgn * committed_.maxYieldStrain) {
    // yielding: the gap grows to the strain where elastic unloading reaches zero stress
    trial_.maxYieldStrain = strain;
    trial_.minYieldStrain = strain - trial_.stress / p.E;
  } else if (sgn * strain < sgn * committed_.minYieldStrain && sgn * strain > sgn * p.gap &&
             !p.damage) {
    // the gap re-closes earlier than the widened gap: the yield point moves back onto the
    // hardening line, elastic from the new closing strain
    trial_.maxYieldStrain = (strain - p.eta * p.gap) / (1.0 - p.eta) + p.Fy / p.E;
    trial_.minYieldStrain = strain;
  }
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
