// SPDX-License-Identifier: MIT
#include "tcl/viewer/ViewerEncoding.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tcl/domain/GeneralFormat.h"

namespace dabs::domain {

void appendNumber(std::string& out, double v, int digits) {
  if (!std::isfinite(v)) v = 0.0;  // JSON has no NaN or infinity
  char text[kGeneralFormatMax];    // printf's %.*g
  out.append(text, formatGeneral(text, v, digits));
}

void appendString(std::string& out, std::string_view s) {
  out += '"';
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == '<') {
      char text[8];
      std::snprintf(text, sizeof text, "\\u%04x", c);
      out += text;
    } else {
      out += ch;
    }
  }
  out += '"';
}

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 |
                       static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += kAlphabet[v >> 6 & 63];
    out += kAlphabet[v & 63];
  }
  const std::size_t rest = bytes.size() - i;
  if (rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[v >> 18 & 63];
    out += kAlphabet[v >> 12 & 63];
    out += rest == 2 ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

void appendSeries(std::string& json, std::string& bytes, const std::vector<double>& data,
                  std::size_t first, std::size_t stride, std::size_t count, bool integers,
                  double levels) {
  double peak = 0.0;
  for (std::size_t k = 0; k < count; ++k) {
    const double v = data[first + k * stride];
    if (std::isfinite(v)) peak = std::max(peak, std::abs(v));
  }
  const double q = integers || peak == 0.0 ? 1.0 : peak / levels;
  json += '[';
  appendNumber(json, q, 17);
  json += ',';
  json += std::to_string(bytes.size());
  json += ']';
  long long previous = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double v = data[first + k * stride];
    const long long level = std::isfinite(v) ? std::llround(v / q) : 0;
    const long long delta = level - previous;
    previous = level;
    auto zigzag = delta >= 0 ? static_cast<unsigned long long>(delta) * 2
                             : static_cast<unsigned long long>(-delta) * 2 - 1;
    do {
      unsigned char b = zigzag & 0x7f;
      zigzag >>= 7;
      if (zigzag != 0) b |= 0x80;
      bytes += static_cast<char>(b);
    } while (zigzag != 0);
  }
}

}  // namespace dabs::domain
