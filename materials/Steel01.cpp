// SPDX-License-Identifier: MIT
#include "materials/Steel01.h"

#include <algorithm>
#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void Steel01::Params::validate() const {
  if (!std::isfinite(Fy) || Fy <= 0.0) throw InputError("Fy", "must be positive");
  if (!std::isfinite(E0) || E0 <= 0.0) throw InputError("E0", "must be positive");
  // A negative b (softening after yield) is accepted, as OpenSees does; b >= 1 leaves no yield.
  if (!std::isfinite(b) || b >= 1.0) throw InputError("b", "must be below 1");
  if (!std::isfinite(a1) || a1 < 0.0) throw InputError("a1", "must be >= 0");
  if (!std::isfinite(a2) || a2 <= 0.0) throw InputError("a2", "must be positive");
  if (!std::isfinite(a3) || a3 < 0.0) throw InputError("a3", "must be >= 0");
  if (!std::isfinite(a4) || a4 <= 0.0) throw InputError("a4", "must be positive");
}

Steel01::Steel01(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.Fy > 0.0 && params.E0 > 0.0);
  revertToStart();
}

Steel01::State Steel01::initialState() const {
  State s;
  s.tangent = params_.E0;
  return s;
}

Status Steel01::setTrialStrain(double strain, double /*strainRate*/) {
  const auto& p = params_;
  trial_ = committed_;
  const double dStrain = strain - committed_.strain;
  // Below round-off the committed state stands (OpenSees compares with DBL_EPSILON).
  if (std::fabs(dStrain) <= DBL_EPSILON) return Status::Ok;

  trial_.strain = strain;
  const double Esh = p.b * p.E0;
  const double epsy = p.Fy / p.E0;
  // Elastic predictor bounded by the two hardening asymptotes Esh*eps -/+ shift*Fy*(1-b).
  const double elastic = committed_.stress + p.E0 * dStrain;
  const double upper = Esh * strain + trial_.shiftP * p.Fy * (1.0 - p.b);
  const double lower = Esh * strain - trial_.shiftN * p.Fy * (1.0 - p.b);
  trial_.stress = std::max(lower, std::min(upper, elastic));
  trial_.tangent = std::fabs(trial_.stress - elastic) < DBL_EPSILON ? p.E0 : Esh;

  // Load reversals update the extreme strains and the isotropic shifts used by the next
  // trial (Filippou et al. 1983).
  if (trial_.loading == 0) trial_.loading = dStrain > 0.0 ? 1 : -1;
  if (trial_.loading == 1 && dStrain < 0.0) {
    trial_.loading = -1;
    trial_.maxStrain = std::max(trial_.maxStrain, committed_.strain);
    trial_.shiftN =
        1.0 + p.a1 * std::pow((trial_.maxStrain - trial_.minStrain) / (2.0 * p.a2 * epsy), 0.8);
  }
  if (trial_.loading == -1 && dStrain > 0.0) {
    trial_.loading = 1;
    trial_.minStrain = std::min(trial_.minStrain, committed_.strain);
    trial_.shiftP =
        1.0 + p.a3 * std::pow((trial_.maxStrain - trial_.minStrain) / (2.0 * p.a4 * epsy), 0.8);
  }
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

}  // namespace dabs::materials
