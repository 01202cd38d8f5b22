// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `timeSeries Constant tag ?-factor f?`: f at every time.
class ConstantSeries final : public TimeSeries {
 public:
  ConstantSeries(int tag, double factor) : TimeSeries(tag), factor_(factor) {}
  double factor(double /*t*/) const override { return factor_; }
  std::string describe() const override;

 private:
  double factor_;
};

}  // namespace dabs::domain
