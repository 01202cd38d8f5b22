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
  Ec0_ = 2.0 * params_.fpc / params_.epsc0;
  descentSlope_ = (params_.fpc - params_.fpcu) / (params_.epsc0 - params_.epsU);
  revertToStart();
}

Concrete01::State Concrete01::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  s.unloadSlope = s.tangent;
  return s;
}

}  // namespace dabs::materials
