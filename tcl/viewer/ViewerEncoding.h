// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace dabs::domain {

// How the Viewer page's data block is written: JSON text for the model and descriptors, and the
// time histories as one base64 block of compressed integer series (tcl/viewer/src/data.js reads
// them back).

/// Appends v with `digits` (1 to 17) significant digits as %g writes them (0 for a non-finite
/// value: JSON has no NaN).
void appendNumber(std::string& out, double v, int digits);
/// Appends a JSON string literal; '<' is escaped so no "</script>" can end the data block early.
void appendString(std::string& out, std::string_view s);
/// Standard base64 (RFC 4648 section 4) with padding.
std::string base64(const std::string& bytes);
/// Appends one series (values at data[first + k * stride], k < count) to `bytes` as zigzag LEB128
/// varints of successive differences of round(v / q), and its descriptor [q, offset] to `json`.
/// q = max |value| / levels, or 1 for `integers` (and for a series of zeros).
void appendSeries(std::string& json, std::string& bytes, const std::vector<double>& data,
                  std::size_t first, std::size_t stride, std::size_t count, bool integers,
                  double levels);

}  // namespace dabs::domain
