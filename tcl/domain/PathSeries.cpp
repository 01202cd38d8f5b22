// SPDX-License-Identifier: MIT
#include "tcl/domain/PathSeries.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "materials/InputError.h"

namespace dabs::domain {

PathSeries::PathSeries(int tag, double dt, std::vector<double> values, double factor,
                       double startTime, bool useLast)
    : TimeSeries(tag),
      dt_(dt),
      startTime_(startTime),
      values_(std::move(values)),
      factor_(factor),
      useLast_(useLast) {}

PathSeries::PathSeries(int tag, std::vector<double> times, std::vector<double> values,
                       double factor, bool useLast)
    : TimeSeries(tag),
      times_(std::move(times)),
      values_(std::move(values)),
      factor_(factor),
      useLast_(useLast) {}

double PathSeries::factor(double t) const {
  if (values_.empty()) return 0.0;
  if (dt_ > 0.0) {
    if (t < startTime_) return 0.0;
    const double x = (t - startTime_) / dt_;
    // Compared as doubles before the cast: with a tiny dt, x can exceed any index (1e20).
    if (!(x < static_cast<double>(values_.size() - 1)))
      return useLast_ ? factor_ * values_.back() : 0.0;
    const auto i1 = static_cast<std::size_t>(std::floor(x));
    const std::size_t i2 = i1 + 1;
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
  for (std::size_t i = 1; i < times_.size(); ++i)
    smallest = std::min(smallest, times_[i] - times_[i - 1]);
  return smallest > 0.0 ? smallest : 0.01;
}

std::string PathSeries::describe() const {
  std::ostringstream out;
  out << "Path " << values_.size() << " points";
  if (dt_ > 0.0) out << " dt " << dt_;
  out << " factor " << factor_;
  return out.str();
}

namespace {

// Longest line looked at for a header, and longest token taken for a number: a record's numbers
// are short, so anything longer is not a record (a binary file need not hold a newline at all).
constexpr std::size_t kMaxHeaderLine = 4096;
constexpr std::size_t kMaxToken = 64;
constexpr std::size_t kHeaderLines = 20;

// Reads one line of at most kMaxHeaderLine characters (the rest of a longer line is skipped).
bool readLine(std::istream& in, std::string& line) {
  line.clear();
  int c = 0;
  bool any = false;
  while ((c = in.get()) != EOF) {
    any = true;
    if (c == '\n') break;
    if (line.size() < kMaxHeaderLine) line += static_cast<char>(c);
  }
  return any;
}

// Length of the number at the start of `token` as `std::istream >> double` reads it (libstdc++):
// optional sign, digits with an optional point, an optional exponent; 0 when the token does not
// start with a number, or when an exponent marker has no digits ("2e", which the stream takes in
// and then rejects). "inf", "nan" and hexadecimal are not numbers.
std::size_t numberPrefix(std::string_view token) {
  std::size_t i = 0;
  auto digits = [&](std::size_t from) {
    std::size_t j = from;
    while (j < token.size() && std::isdigit(static_cast<unsigned char>(token[j])) != 0) ++j;
    return j;
  };
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  std::size_t j = digits(i);
  bool any = j > i;
  if (j < token.size() && token[j] == '.') {
    const std::size_t k = digits(j + 1);
    any = any || k > j + 1;
    j = k;
  }
  if (!any) return 0;
  if (j < token.size() && (token[j] == 'e' || token[j] == 'E')) {
    std::size_t k = j + 1;
    if (k < token.size() && (token[k] == '+' || token[k] == '-')) ++k;
    const std::size_t m = digits(k);
    if (m == k) return 0;
    j = m;
  }
  return j;
}

// Appends the numbers of `text` to `values` until the first that is not a number, which ends the
// record; false then. As OpenSees' PathSeries reads `file >> value` until it fails, a number needs
// no space after it: "0.2***" gives 0.2 and the record ends at "***"; "1.5-3" gives 1.5 and -3.
bool takeNumbers(std::string_view text, std::vector<double>& values, long limit) {
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
    std::size_t j = i;
    while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j])) == 0) ++j;
    if (j == i) break;
    if (limit >= 0 && static_cast<long>(values.size()) >= limit) return false;
    const std::size_t n = numberPrefix(text.substr(i, std::min(j - i, kMaxToken + 1)));
    if (n == 0 || n > kMaxToken) return false;
    const std::string token(text.substr(i, n));
    const double v = std::strtod(token.c_str(), nullptr);
    if (!std::isfinite(v)) return false;
    values.push_back(v);
    i += n;
  }
  return true;
}

}  // namespace

RecordFile readRecordFile(const std::string& path) {
  // Only regular files: a device such as /dev/urandom or /dev/zero, or a pipe, never ends.
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status))
    throw InputError("-filePath", "cannot open \"" + path + "\": no such file");
  if (!std::filesystem::is_regular_file(status))
    throw InputError("-filePath",
                     "\"" + path + "\" is not a regular file; a record is a text file of numbers");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("-filePath", "cannot open \"" + path + "\"");
  RecordFile out;
  // PEER header: a line with NPTS= and DT= (NGA files add a trailing comma after SEC) among the
  // first lines; the numbers start on the next line.
  static const std::regex kHeader(R"(NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.eE+-]+))",
                                  std::regex::icase);
  std::vector<std::string> head;
  std::size_t first = 0;
  long npts = -1;
  for (std::string line; head.size() < kHeaderLines && readLine(in, line);) {
    head.push_back(line);
    std::smatch m;
    if (std::regex_search(line, m, kHeader)) {
      try {
        npts = std::stol(m[1].str());
        out.dt = std::stod(m[2].str());
      } catch (const std::exception&) {
        throw InputError("-filePath", "\"" + path + "\" has an unreadable NPTS/DT header: " + line);
      }
      first = head.size();
      break;
    }
  }
  // Numbers until the first non-number (a trailer such as "*** End Data ***" ends the record);
  // with a header, exactly NPTS values.
  bool more = true;
  for (std::size_t i = first; more && i < head.size(); ++i)
    more = takeNumbers(head[i], out.values, npts);
  constexpr std::size_t kChunk = 1 << 16;
  std::string pending;
  char buffer[kChunk];
  while (more && in) {
    in.read(buffer, kChunk);
    const auto got = static_cast<std::size_t>(in.gcount());
    if (got == 0) break;
    pending.append(buffer, got);
    // Keep a token cut at the chunk's end for the next round.
    std::size_t cut = pending.size();
    while (cut > 0 && std::isspace(static_cast<unsigned char>(pending[cut - 1])) == 0) --cut;
    if (pending.size() - cut > kMaxToken) break;
    more = takeNumbers(std::string_view(pending).substr(0, cut), out.values, npts);
    pending.erase(0, cut);
  }
  if (more && !pending.empty()) takeNumbers(pending, out.values, npts);
  if (npts >= 0) {
    if (static_cast<long>(out.values.size()) < npts)
      throw InputError("-filePath", "\"" + path + "\" announces NPTS=" + std::to_string(npts) +
                                        " but holds " + std::to_string(out.values.size()) +
                                        " values");
    out.values.resize(static_cast<std::size_t>(npts));
  }
  if (out.values.empty())
    throw InputError("-filePath", "\"" + path +
                                      "\" holds no numbers; a record is a text file of numbers "
                                      "(optionally after a PEER header with NPTS= and DT=)");
  return out;
}

}  // namespace dabs::domain
