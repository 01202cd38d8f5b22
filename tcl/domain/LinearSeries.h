// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `timeSeries Linear tag ?-factor f?`: f t.
class LinearSeries final : public TimeSeries {
 public:
  LinearSeries(int tag, double factor) : TimeSeries(tag), factor_(factor) {}
  double factor(double t) const override { return factor_ * t; }
  std::string describe() const override;

 private:
  double factor_;
};

}  // namespace dabs::domain
