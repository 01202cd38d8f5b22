// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `timeSeries Trig tag tStart tEnd period ?-factor f? ?-shift phi? ?-zeroShift z?`:
/// f sin(2 pi (t - tStart)/period + phi) + z inside [tStart, tEnd], zero outside
/// (OpenSees/OpenSees:SRC/domain/pattern/TrigSeries.cpp).
class TrigSeries final : public TimeSeries {
 public:
  TrigSeries(int tag, double tStart, double tEnd, double period, double factor, double shift,
             double zeroShift)
      : TimeSeries(tag),
        tStart_(tStart),
        tEnd_(tEnd),
        period_(period),
        factor_(factor),
        shift_(shift),
        zeroShift_(zeroShift) {}
  double factor(double t) const override;
  double duration() const override { return tEnd_; }
  double samplingInterval() const override { return period_ / 200.0; }
  std::string describe() const override;

 private:
  double tStart_, tEnd_, period_, factor_, shift_, zeroShift_;
};

}  // namespace dabs::domain
