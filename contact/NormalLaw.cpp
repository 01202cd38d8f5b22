// SPDX-License-Identifier: MIT
#include "contact/NormalLaw.h"

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::contact {

namespace {

void requirePositiveMass(double M, const char* field, const char* when) {
  if (!(M > 0.0) || !std::isfinite(M))
    throw InputError(field, std::string("must be positive ") + when + " (-masses M1 M2)");
}

}  // namespace

void NormalLaw::Params::validate() const {
  if (!(K > 0.0) || !std::isfinite(K)) throw InputError("K", "must be positive and finite");
  switch (law) {
    case ImpactLaw::Kelvin:
      if (!(e >= 0.0 && e <= 1.0)) throw InputError("e", "must be in [0, 1]");
      if (e < 1.0) {
        requirePositiveMass(M1, "M1", "when e < 1");
        requirePositiveMass(M2, "M2", "when e < 1");
      }
      break;
    case ImpactLaw::Hertz:
      if (!(n > 0.0) || !std::isfinite(n)) throw InputError("n", "must be positive and finite");
      if (e != 1.0)
        throw InputError("e", "must be 1: the hertz law has no damping (use -law hertzdamp)");
      break;
    case ImpactLaw::HertzDamp:
      if (!(n > 0.0) || !std::isfinite(n)) throw InputError("n", "must be positive and finite");
      if (!(e > 0.0 && e <= 1.0)) throw InputError("e", "must be in (0, 1] for hertzdamp");
      if (!(v0 > 0.0) || !std::isfinite(v0))
        throw InputError("v0", "must be positive and finite (the approach speed, -v0 v0)");
      break;
    case ImpactLaw::Jankowski:
      if (n != 1.5) throw InputError("n", "is 1.5 in the jankowski law");
      if (!(e > 0.0 && e <= 1.0)) throw InputError("e", "must be in (0, 1] for jankowski");
      requirePositiveMass(M1, "M1", "for the jankowski law");
      requirePositiveMass(M2, "M2", "for the jankowski law");
      break;
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

double NormalLaw::jankowskiDampingRatio(double e) {
  // Jankowski (2006, EESD 35:517, eq. 17).
  const double pi = std::numbers::pi;
  return 9.0 * std::sqrt(5.0) * (1.0 - e * e) / (2.0 * e * (e * (9.0 * pi - 16.0) + 16.0));
}

double NormalLaw::hysteresisDamping(double k, double e, double v0) {
  // Lankarani and Nikravesh (1990, eq. 25), as used by Muthukumar and DesRoches (2006).
  return 3.0 * k * (1.0 - e * e) / (4.0 * v0);
}

const char* NormalLaw::name(ImpactLaw law) noexcept {
  switch (law) {
    case ImpactLaw::Kelvin: return "kelvin";
    case ImpactLaw::Hertz: return "hertz";
    case ImpactLaw::HertzDamp: return "hertzdamp";
    case ImpactLaw::Jankowski: return "jankowski";
  }
  return "?";
}

NormalLaw::NormalLaw(const Params& p) : law_(p.law), K_(p.K), C_(0.0), n_(1.0) {
  switch (p.law) {
    case ImpactLaw::Kelvin:
      if (p.e < 1.0) {
        const double mass = p.M1 * p.M2 / (p.M1 + p.M2);
        C_ = 2.0 * dampingRatio(p.e) * std::sqrt(p.K * mass);
      }
      break;
    case ImpactLaw::Hertz: n_ = p.n; break;
    case ImpactLaw::HertzDamp:
      n_ = p.n;
      C_ = hysteresisDamping(p.K, p.e, p.v0);
      break;
    case ImpactLaw::Jankowski: {
      n_ = 1.5;
      const double mass = p.M1 * p.M2 / (p.M1 + p.M2);
      // c(t) = 2 xi sqrt(beta sqrt(delta) m) = C delta^(1/4) (Jankowski 2005)
      C_ = 2.0 * jankowskiDampingRatio(p.e) * std::sqrt(p.K * mass);
      break;
    }
  }
}

}  // namespace dabs::contact
