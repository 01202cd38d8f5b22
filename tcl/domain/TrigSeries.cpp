// SPDX-License-Identifier: MIT
#include "tcl/domain/TrigSeries.h"

#include <cmath>
#include <numbers>

namespace dabs::domain {

double TrigSeries::factor(double t) const {
  if (t < tStart_ || t > tEnd_) return 0.0;
  return factor_ * std::sin(2.0 * std::numbers::pi * (t - tStart_) / period_ + shift_) + zeroShift_;
}

std::string TrigSeries::describe() const {
  return "Trig tStart " + std::to_string(tStart_) + " tEnd " + std::to_string(tEnd_) + " period " +
         std::to_string(period_) + " factor " + std::to_string(factor_);
}

}  // namespace dabs::domain
