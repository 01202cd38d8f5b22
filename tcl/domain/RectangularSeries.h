// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `timeSeries Rectangular tag tStart tEnd ?-factor f?`: f inside [tStart, tEnd], zero outside.
class RectangularSeries final : public TimeSeries {
 public:
  RectangularSeries(int tag, double tStart, double tEnd, double factor)
      : TimeSeries(tag), tStart_(tStart), tEnd_(tEnd), factor_(factor) {}
  double factor(double t) const override { return (t >= tStart_ && t <= tEnd_) ? factor_ : 0.0; }
  double duration() const override { return tEnd_; }
  std::string describe() const override;

 private:
  double tStart_, tEnd_, factor_;
};

}  // namespace dabs::domain
