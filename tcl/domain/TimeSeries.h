// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>

namespace dabs::domain {

/// Load factor as a function of (pseudo) time, as OpenSees' timeSeries.
class TimeSeries {
 public:
  explicit TimeSeries(int tag) noexcept : tag_(tag) {}
  virtual ~TimeSeries() = default;
  int tag() const noexcept { return tag_; }
  /// Load factor at time t.
  virtual double factor(double t) const = 0;
  /// Time after which the series no longer changes (infinity when unbounded); used to size the
  /// integration of ground motions.
  virtual double duration() const;
  /// Sampling interval that resolves the series (the record's dt for Path series).
  virtual double samplingInterval() const;
  virtual std::string describe() const = 0;

 private:
  int tag_;
};

}  // namespace dabs::domain
