// SPDX-License-Identifier: MIT
#include "materials/Elastic.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void Elastic::Params::validate() const {
  if (!std::isfinite(E)) throw InputError("E", "must be a finite number");
  if (!std::isfinite(eta) || eta < 0.0) throw InputError("eta", "must be >= 0");
  if (Eneg && !std::isfinite(*Eneg)) throw InputError("Eneg", "must be a finite number");
}

Elastic::Elastic(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(std::isfinite(params.E));
  revertToStart();
}

double Elastic::getInitialTangent() const {
  return std::max(params_.E, params_.compressionModulus());
}

Elastic::State Elastic::initialState() const { return State{0.0, 0.0, 0.0, getInitialTangent()}; }

Status Elastic::setTrialStrain(double strain, double strainRate) {
  const double eNeg = params_.compressionModulus();
  trial_.strain = strain;
  trial_.strainRate = strainRate;
  const double elastic = (strain >= 0.0 ? params_.E : eNeg) * strain;
  // Without a dashpot the rate adds nothing, not even the sign of a zero stress (0 * a negative
  // rate is -0): the stress is then a function of the strain alone (keepsStateAtSameStrain).
  trial_.stress = params_.eta != 0.0 ? elastic + params_.eta * strainRate : elastic;
  // At eps = 0 the stiffer side is reported, as OpenSees does.
  trial_.tangent = strain > 0.0 ? params_.E : (strain < 0.0 ? eNeg : getInitialTangent());
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
