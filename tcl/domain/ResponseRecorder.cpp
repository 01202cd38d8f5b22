// SPDX-License-Identifier: MIT
#include "tcl/domain/ResponseRecorder.h"

#include <cmath>
#include <cstdio>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::domain {

namespace {
// Relative tolerance on -dT, so round-off in accumulated time does not skip a record.
constexpr double kDeltaTTolerance = 1e-10;
}  // namespace

ResponseRecorder::ResponseRecorder(RecorderOutput output) : output_(std::move(output)) {
  std::ofstream probe(output_.file, std::ios::trunc);
  if (!probe) throw InputError("-file", "cannot write \"" + output_.file + "\"");
}

ResponseRecorder::~ResponseRecorder() {
  try {
    flush();
  } catch (...) {
    // A destructor must not throw; the data were flushed at the end of the last analyze.
  }
}

void ResponseRecorder::appendNumber(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", output_.precision, v);
  buffer_ += text;
}

void ResponseRecorder::writeRow(double time, const std::vector<double>& row) {
  bool first = true;
  if (output_.time) {
    appendNumber(time);
    first = false;
  }
  for (double v : row) {
    if (!first) buffer_ += ' ';
    appendNumber(v);
    first = false;
  }
  buffer_ += '\n';
}

void ResponseRecorder::record(const Domain& domain) {
  const double t = domain.time();
  if (output_.deltaT > 0.0 && anyRecord_ &&
      t < nextTime_ - kDeltaTTolerance * std::max(1.0, std::abs(nextTime_)))
    return;
  anyRecord_ = true;
  nextTime_ = t + output_.deltaT;
  row_.clear();
  values(domain, row_);
  if (!output_.envelope) {
    writeRow(t, row_);
    return;
  }
  if (min_.size() != row_.size()) {
    min_ = max_ = row_;
    absMax_.resize(row_.size());
    for (std::size_t i = 0; i < row_.size(); ++i) absMax_[i] = std::abs(row_[i]);
    tMin_.assign(row_.size(), t);
    tMax_ = tAbs_ = tMin_;
    return;
  }
  for (std::size_t i = 0; i < row_.size(); ++i) {
    if (row_[i] < min_[i]) {
      min_[i] = row_[i];
      tMin_[i] = t;
    }
    if (row_[i] > max_[i]) {
      max_[i] = row_[i];
      tMax_[i] = t;
    }
    if (std::abs(row_[i]) > absMax_[i]) {
      absMax_[i] = std::abs(row_[i]);
      tAbs_[i] = t;
    }
  }
}

void ResponseRecorder::flush() {
  if (output_.envelope) {
    // Three rows: min, max, max |value|; with -time each value follows the time it occurred.
    if (min_.empty()) return;
    buffer_.clear();
    const std::vector<double>* rows[3] = {&min_, &max_, &absMax_};
    const std::vector<double>* times[3] = {&tMin_, &tMax_, &tAbs_};
    for (int r = 0; r < 3; ++r) {
      bool first = true;
      for (std::size_t i = 0; i < rows[r]->size(); ++i) {
        if (output_.time) {
          if (!first) buffer_ += ' ';
          appendNumber((*times[r])[i]);
          first = false;
        }
        if (!first) buffer_ += ' ';
        appendNumber((*rows[r])[i]);
        first = false;
      }
      buffer_ += '\n';
    }
    std::ofstream out(output_.file, std::ios::trunc);
    out << buffer_;
    buffer_.clear();
    return;
  }
  if (buffer_.empty()) return;
  std::ofstream out(output_.file, std::ios::app);
  out << buffer_;
  buffer_.clear();
}

}  // namespace dabs::domain
