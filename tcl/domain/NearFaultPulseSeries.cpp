// SPDX-License-Identifier: MIT
#include "tcl/domain/NearFaultPulseSeries.h"

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::domain {

void NearFaultPulseSeries::Params::validate() const {
  if (!(Tp > 0.0) || !std::isfinite(Tp)) throw InputError("-Tp", "must be positive");
  if (!std::isfinite(Vp)) throw InputError("-Vp", "must be a finite number");
  if (!(gamma > 1.0) || !std::isfinite(gamma)) throw InputError("-gamma", "must be greater than 1");
  if (!std::isfinite(nu)) throw InputError("-nu", "must be a finite number");
  if (!(t0 >= 0.5 * gamma * Tp))
    throw InputError("-t0", "must be at least gamma Tp / 2 so the pulse starts at t >= 0");
}

double NearFaultPulseSeries::velocity(double t) const {
  const double s = t - p_.t0;
  if (std::abs(s) > 0.5 * p_.gamma * p_.Tp) return 0.0;
  const double theta = 2.0 * std::numbers::pi * s / p_.Tp;
  return 0.5 * p_.Vp * (1.0 + std::cos(theta / p_.gamma)) * std::cos(theta + p_.nu);
}

double NearFaultPulseSeries::factor(double t) const {
  if (p_.velocity) return p_.factor * velocity(t);
  const double s = t - p_.t0;
  if (std::abs(s) > 0.5 * p_.gamma * p_.Tp) return 0.0;
  // dv/dt of the pulse (Mavroeidis and Papageorgiou 2003, eq. 2).
  const double fp = 1.0 / p_.Tp;
  const double theta = 2.0 * std::numbers::pi * s / p_.Tp;
  const double a = -std::numbers::pi * fp * p_.Vp *
                   (std::sin(theta / p_.gamma) * std::cos(theta + p_.nu) / p_.gamma +
                    (1.0 + std::cos(theta / p_.gamma)) * std::sin(theta + p_.nu));
  return p_.factor * a;
}

std::string NearFaultPulseSeries::describe() const {
  return "NearFaultPulse Tp " + std::to_string(p_.Tp) + " Vp " + std::to_string(p_.Vp) + " gamma " +
         std::to_string(p_.gamma) + " nu " + std::to_string(p_.nu) + " t0 " + std::to_string(p_.t0);
}

}  // namespace dabs::domain
