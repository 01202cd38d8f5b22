// SPDX-License-Identifier: MIT
#include "tcl/domain/PathSeries.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "materials/InputError.h"

namespace dabs::domain {

PathSeries::PathSeries(int tag, double dt, std::vector<double> values, double factor,
                       double startTime, bool useLast)
    : TimeSeries(tag), dt_(dt), startTime_(startTime), values_(std::move(values)), factor_(factor),
      useLast_(useLast) {}

PathSeries::PathSeries(int tag, std::vector<double> times, std::vector<double> values,
                       double factor, bool useLast)
    : TimeSeries(tag), times_(std::move(times)), values_(std::move(values)), factor_(factor),
      useLast_(useLast) {}

double PathSeries::factor(double t) const {
  if (values_.empty()) return 0.0;
  if (dt_ > 0.0) {
    if (t < startTime_) return 0.0;
    const double x = (t - startTime_) / dt_;
    const auto i1 = static_cast<std::size_t>(std::floor(x));
    const std::size_t i2 = i1 + 1;
    if (i2 >= values_.size()) return useLast_ ? factor_ * values_.back() : 0.0;
    const double frac = x - static_cast<double>(i1);
    return factor_ * (values_[i1] + (values_[i2] - values_[i1]) * frac);
  }
  if (t < times_.front()) return 0.0;
  if (t == times_.back()) return factor_ * values_.back();  // PathTimeSeries interpolates here
  if (t > times_.back()) return useLast_ ? factor_ * values_.back() : 0.0;
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  const auto i2 = static_cast<std::size_t>(it - times_.begin());
  const std::size_t i1 = i2 - 1;
  const double frac = (t - times_[i1]) / (times_[i2] - times_[i1]);
  return factor_ * (values_[i1] + (values_[i2] - values_[i1]) * frac);
}

double PathSeries::duration() const {
  if (values_.empty()) return 0.0;
  if (dt_ > 0.0) return startTime_ + dt_ * static_cast<double>(values_.size() - 1);
  return times_.back();
}

double PathSeries::samplingInterval() const {
  if (dt_ > 0.0) return dt_;
  double smallest = duration();
  for (std::size_t i = 1; i < times_.size(); ++i) smallest = std::min(smallest, times_[i] - times_[i - 1]);
  return smallest > 0.0 ? smallest : 0.01;
}

std::string PathSeries::describe() const {
  std::ostringstream out;
  out << "Path " << values_.size() << " points";
  if (dt_ > 0.0) out << " dt " << dt_;
  out << " factor " << factor_;
  return out.str();
}

RecordFile readRecordFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("-filePath", "cannot open \"" + path + "\"");
  RecordFile out;
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  // PEER header: a line with NPTS= and DT= (NGA files add a trailing comma after SEC).
  static const std::regex kHeader(R"(NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.eE+-]+))",
                                  std::regex::icase);
  std::size_t first = 0;
  long npts = -1;
  for (std::size_t i = 0; i < lines.size() && i < 20; ++i) {
    std::smatch m;
    if (std::regex_search(lines[i], m, kHeader)) {
      npts = std::stol(m[1].str());
      out.dt = std::stod(m[2].str());
      first = i + 1;
      break;
    }
  }
  // With a header, exactly NPTS values are read and any trailer (e.g. "*** End Data ***") ignored.
  for (std::size_t i = first; i < lines.size(); ++i) {
    if (npts >= 0 && static_cast<long>(out.values.size()) >= npts) break;
    std::istringstream tokens(lines[i]);
    for (std::string tok; tokens >> tok;) {
      if (npts >= 0 && static_cast<long>(out.values.size()) >= npts) break;
      char* end = nullptr;
      const double v = std::strtod(tok.c_str(), &end);
      if (end == tok.c_str() || *end != '\0' || !std::isfinite(v)) {
        throw InputError("-filePath", "\"" + path + "\" line " + std::to_string(i + 1) +
                                          ": expected a number, got \"" + tok + "\"");
      }
      out.values.push_back(v);
    }
  }
  if (npts >= 0) {
    if (static_cast<long>(out.values.size()) < npts)
      throw InputError("-filePath", "\"" + path + "\" announces NPTS=" + std::to_string(npts) +
                                        " but holds " + std::to_string(out.values.size()) + " values");
    out.values.resize(static_cast<std::size_t>(npts));
  }
  if (out.values.empty()) throw InputError("-filePath", "\"" + path + "\" holds no values");
  return out;
}

}  // namespace dabs::domain
