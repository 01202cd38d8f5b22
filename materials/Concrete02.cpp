// SPDX-License-Identifier: MIT
#include "materials/Concrete02.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

Concrete02::Params Concrete02::Params::withDefaults(double fpc, double epsc0, double fpcu,
                                                    double epsU) {
  return Params{fpc, epsc0, fpcu, epsU, 0.1, 0.1 * std::fabs(fpc), 0.1 * fpc / epsc0};
}

void Concrete02::Params::validate() const {
  if (!std::isfinite(fpc) || fpc >= 0.0) throw InputError("fpc", "must be negative");
  if (!std::isfinite(epsc0) || epsc0 >= 0.0) throw InputError("epsc0", "must be negative");
  if (!std::isfinite(fpcu) || fpcu > 0.0 || fpcu < fpc)
    throw InputError("fpcu", "must be in [fpc, 0]");
  if (!std::isfinite(epsU) || epsU >= epsc0)
    throw InputError("epsU", "must be more negative than epsc0");
  if (!std::isfinite(lambda) || lambda < 0.0 || lambda >= 1.0)
    throw InputError("lambda", "must be in [0, 1)");
  if (!std::isfinite(ft) || ft < 0.0) throw InputError("ft", "must be >= 0");
  if (!std::isfinite(Ets) || Ets <= 0.0) throw InputError("Ets", "must be positive");
}

Concrete02::Concrete02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.fpc < 0.0 && params.epsc0 < 0.0 && params.Ets > 0.0);
  const auto& p = params_;
  Ec0_ = 2.0 * p.fpc / p.epsc0;
  epsR_ = (p.fpcu - p.lambda * Ec0_ * p.epsU) / (Ec0_ * (1.0 - p.lambda));
  sigR_ = Ec0_ * epsR_;
  epsCrack_ = p.ft / Ec0_;
  epsZero_ = p.ft * (1.0 / p.Ets + 1.0 / Ec0_);
  revertToStart();
}

Concrete02::State Concrete02::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  setMinimumStrain(s, 0.0, 0.0);
  return s;
}

}  // namespace dabs::materials
