// SPDX-License-Identifier: MIT
#include "materials/ElasticPP.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void ElasticPP::Params::validate() const {
  if (!std::isfinite(E) || E <= 0.0) throw InputError("E", "must be positive");
  if (!std::isfinite(epsyP) || epsyP <= 0.0) throw InputError("epsyP", "must be positive");
  if (epsyN && (!std::isfinite(*epsyN) || *epsyN >= 0.0))
    throw InputError("epsyN", "must be negative");
  if (!std::isfinite(eps0)) throw InputError("eps0", "must be a finite number");
}

ElasticPP::ElasticPP(int tag, const Params& params)
    : StatefulUniaxial(tag),
      params_(params),
      fyP_(params.E * params.epsyP),
      fyN_(params.E * params.compressionYieldStrain()) {
  assert(params.E > 0.0 && fyP_ > 0.0 && fyN_ < 0.0);
  revertToStart();
}

Status ElasticPP::setTrialStrain(double strain, double /*strainRate*/) {
  const double E = params_.E;
  trial_ = committed_;
  trial_.strain = strain;
  // Elastic predictor and yield function f = |sig| - fy (return map of a 1D perfectly plastic
  // material, Simo & Hughes 1998, Sec. 1.2). OpenSees treats f > -E*DBL_EPSILON as yielding.
  const double sigTrial = E * (strain - params_.eps0 - committed_.plasticStrain);
  const double f = sigTrial >= 0.0 ? sigTrial - fyP_ : -sigTrial + fyN_;
  if (f <= -E * DBL_EPSILON) {
    trial_.stress = sigTrial;
    trial_.tangent = E;
  } else {
    trial_.stress = sigTrial > 0.0 ? fyP_ : fyN_;
    trial_.tangent = 0.0;
    trial_.plasticStrain += (sigTrial > 0.0 ? f : -f) / E;
  }
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
