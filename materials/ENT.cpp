// SPDX-License-Identifier: MIT
#include "materials/ENT.h"

#include <cassert>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void ENT::Params::validate() const {
  if (!std::isfinite(E) || E <= 0.0) throw InputError("E", "must be positive");
}

ENT::ENT(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.E > 0.0);
  revertToStart();
}

Status ENT::setTrialStrain(double strain, double /*strainRate*/) {
  trial_.strain = strain;
  trial_.stress = strain < 0.0 ? params_.E * strain : 0.0;
  trial_.tangent = strain <= 0.0 ? params_.E : 0.0;
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
