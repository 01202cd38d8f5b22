// SPDX-License-Identifier: MIT
#include "tcl/domain/ResponseRecorder.h"

#include <cmath>
#include <cstdio>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/GeneralFormat.h"

namespace dabs::domain {

namespace {
// Relative tolerance on -dT, so round-off in accumulated time does not skip a record.
constexpr double kDeltaTTolerance = 1e-10;
}  // namespace

ResponseRecorder::ResponseRecorder(RecorderOutput output)
    : output_(std::move(output)), file_(output_.file) {}

void ResponseRecorder::appendNumber(double v) {
  // printf's %.*g (OpenSees' streams write the same digits), by formatGeneral: std::to_chars's
  // characters in about half its time.
  char text[kGeneralFormatMax];
  file_.buffer().append(text, formatGeneral(text, v, output_.precision));
}

void ResponseRecorder::writeRow(double time, const std::vector<double>& row) {
  bool first = true;
  if (output_.time) {
    appendNumber(time);
    first = false;
  }
  for (double v : row) {
    if (!first) file_.buffer() += ' ';
    appendNumber(v);
    first = false;
  }
  file_.buffer() += '\n';
  file_.flush();
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
    writeEnvelope();
    return;
  }
  bool changed = false;
  for (std::size_t i = 0; i < row_.size(); ++i) {
    if (row_[i] < min_[i]) {
      min_[i] = row_[i];
      tMin_[i] = t;
      changed = true;
    }
    if (row_[i] > max_[i]) {
      max_[i] = row_[i];
      tMax_[i] = t;
      changed = true;
    }
    if (std::abs(row_[i]) > absMax_[i]) {
      absMax_[i] = std::abs(row_[i]);
      tAbs_[i] = t;
      changed = true;
    }
  }
  if (changed) writeEnvelope();
}

void ResponseRecorder::writeEnvelope() {
  // Three rows: min, max, max |value|; with -time each value follows the time it occurred.
  const std::vector<double>* rows[3] = {&min_, &max_, &absMax_};
  const std::vector<double>* times[3] = {&tMin_, &tMax_, &tAbs_};
  for (int r = 0; r < 3; ++r) {
    bool first = true;
    for (std::size_t i = 0; i < rows[r]->size(); ++i) {
      if (output_.time) {
        if (!first) file_.buffer() += ' ';
        appendNumber((*times[r])[i]);
        first = false;
      }
      if (!first) file_.buffer() += ' ';
      appendNumber((*rows[r])[i]);
      first = false;
    }
    file_.buffer() += '\n';
  }
  file_.rewrite();
}

void ResponseRecorder::flush() { file_.flush(); }

}  // namespace dabs::domain
