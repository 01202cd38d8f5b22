// SPDX-License-Identifier: MIT
#include "materials/Steel02.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void Steel02::Params::validate() const {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0) throw InputError(name, "must be positive");
  };
  auto nonNegative = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0) throw InputError(name, "must be >= 0");
  };
  positive(Fy, "Fy");
  positive(E, "E");
  if (!std::isfinite(b) || b < 0.0 || b >= 1.0) throw InputError("b", "must be in [0, 1)");
  positive(R0, "R0");
  if (!std::isfinite(cR1) || cR1 < 0.0 || cR1 >= 1.0) throw InputError("cR1", "must be in [0, 1)");
  positive(cR2, "cR2");
  nonNegative(a1, "a1");
  positive(a2, "a2");
  nonNegative(a3, "a3");
  positive(a4, "a4");
  if (!std::isfinite(sigInit) || std::fabs(sigInit) >= Fy)
    throw InputError("sigInit", "must be smaller than Fy in magnitude");
}

Steel02::Steel02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.Fy > 0.0 && params.E > 0.0 && params.b < 1.0);
  epsy_ = params.Fy / params.E;
  Esh_ = params.b * params.E;
  epsIni_ = params.sigInit / params.E;
  revertToStart();
}

Steel02::State Steel02::initialState() const {
  State s;
  s.stress = params_.sigInit;
  s.tangent = params_.E;
  s.epsMax = params_.Fy / params_.E;
  s.epsMin = -s.epsMax;
  return s;
}

}  // namespace dabs::materials
