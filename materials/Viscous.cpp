// SPDX-License-Identifier: MIT
#include "materials/Viscous.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void Viscous::Params::validate() const {
  if (!std::isfinite(C) || C < 0.0) throw InputError("C", "must be >= 0");
  if (!std::isfinite(alpha) || alpha <= 0.0) throw InputError("alpha", "must be positive");
  if (!std::isfinite(minVel) || minVel <= 0.0) throw InputError("minVel", "must be positive");
}

Viscous::Viscous(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.alpha > 0.0 && params.minVel > 0.0);
  revertToStart();
}

double Viscous::dampTangentAt(double rate) const {
  const double v = std::max(std::fabs(rate), params_.minVel);
  return params_.alpha * params_.C * std::pow(v, params_.alpha - 1.0);
}

Viscous::State Viscous::initialState() const { return State{0.0, 0.0, 0.0, dampTangentAt(0.0)}; }

Status Viscous::setTrialStrain(double strain, double strainRate) {
  trial_.strain = strain;
  trial_.strainRate = strainRate;
  const double magnitude = params_.C * std::pow(std::fabs(strainRate), params_.alpha);
  trial_.stress = strainRate < 0.0 ? -magnitude : magnitude;
  trial_.dampTangent = dampTangentAt(strainRate);
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
