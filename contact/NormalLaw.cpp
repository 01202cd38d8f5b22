// SPDX-License-Identifier: MIT
#include "contact/NormalLaw.h"

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::contact {

void NormalLaw::Params::validate() const {
  if (!(K > 0.0) || !std::isfinite(K)) throw InputError("K", "must be positive and finite");
  if (!(e >= 0.0 && e <= 1.0)) throw InputError("e", "must be in [0, 1]");
  if (e < 1.0) {
    if (!(M1 > 0.0) || !std::isfinite(M1))
      throw InputError("M1", "must be positive when e < 1 (-masses M1 M2)");
    if (!(M2 > 0.0) || !std::isfinite(M2))
      throw InputError("M2", "must be positive when e < 1 (-masses M1 M2)");
  }
}

double NormalLaw::dampingRatio(double e) {
  if (e <= 0.0) return 1.0;  // limit of the formula as ln e -> -infinity
  const double l = std::log(e);
  return -l / std::sqrt(std::numbers::pi * std::numbers::pi + l * l);
}

double NormalLaw::effectiveRestitution(double xi) {
  // Free damped oscillation of the penetration x(t) = (v0/wd) exp(-xi w t) sin(wd t); the force
  // w^2 x + 2 xi w x' (per unit mass) vanishes when x'' = 0, i.e. tan(wd t) = 2 xi r / (2 xi^2 - 1)
  // with r = sqrt(1 - xi^2), first root in (0, pi); exit velocity ratio -x'(t*)/v0.
  if (xi <= 0.0) return 1.0;
  if (xi >= 1.0) return 0.0;  // (over)critical: the force reaches zero with no rebound speed left
  const double r = std::sqrt(1.0 - xi * xi);
  const double phase = std::numbers::pi - std::atan2(2.0 * xi * r, 1.0 - 2.0 * xi * xi);  // wd t*
  const double wt = phase / r;                                                            // w t*
  return std::exp(-xi * wt) * (xi / r * std::sin(phase) - std::cos(phase));
}

NormalLaw::NormalLaw(const Params& p) : K_(p.K), C_(0.0) {
  if (p.e < 1.0) {
    const double mass = p.M1 * p.M2 / (p.M1 + p.M2);
    C_ = 2.0 * dampingRatio(p.e) * std::sqrt(p.K * mass);
  }
}

}  // namespace dabs::contact
