// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `timeSeries Path`: values at equal steps dt from startTime (-dt), or at given times (-time),
/// linearly interpolated; zero before the first and after the last point unless -useLast
/// (OpenSees/OpenSees:SRC/domain/pattern/PathSeries.cpp and PathTimeSeries.cpp, including their
/// conventions without -useLast: an equally spaced series is zero from its last sample time on,
/// one with -time gives its last value at the last time and zero after it).
class PathSeries final : public TimeSeries {
 public:
  /// Equally spaced values.
  PathSeries(int tag, double dt, std::vector<double> values, double factor, double startTime,
             bool useLast);
  /// Values at given, strictly increasing times.
  PathSeries(int tag, std::vector<double> times, std::vector<double> values, double factor,
             bool useLast);
  double factor(double t) const override;
  double duration() const override;
  double samplingInterval() const override;
  std::string describe() const override;
  std::size_t size() const noexcept { return values_.size(); }

 private:
  double dt_ = 0.0;  // 0 when times_ are given
  double startTime_ = 0.0;
  std::vector<double> times_;
  std::vector<double> values_;
  double factor_;
  bool useLast_;
};

/// A record read from a file: values and, for PEER .AT2 files, the step found in the header.
struct RecordFile {
  std::vector<double> values;
  double dt = 0.0;  ///< 0 when the file has no header
};

/// Reads a regular file of numbers up to the first token that is not a number, as OpenSees'
/// PathSeries does; recognises PEER NGA and old PEER .AT2 headers (a line with NPTS= and DT= among
/// the first 20 lines) and then takes NPTS values after it. Throws InputError naming the file for
/// what is not a record: not a regular file (a device, a pipe), no numbers, fewer than NPTS.
RecordFile readRecordFile(const std::string& path);

}  // namespace dabs::domain
