// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

namespace dabs::domain {

/// Characters formatGeneral writes at most (sign, 17 digits, point, "e-308": 24; with margin).
inline constexpr std::size_t kGeneralFormatMax = 32;

/// Writes `v` as printf's "%.*g" writes it with `precision` significant digits (1 to 17, the
/// recorders' range; the C library's correctly rounded decimal value, trailing zeros dropped),
/// from `out`, and returns one past the last character; `out` has room for kGeneralFormatMax
/// characters. The same characters as std::to_chars(out, ..., v, std::chars_format::general,
/// precision), which it calls where its own arithmetic cannot decide the rounding (fastGeneral
/// declines).
char* formatGeneral(char* out, double v, int precision);

/// The common case of formatGeneral without the C++ library: a finite nonzero `v` between about
/// 1e-15 and 1e27 and a precision of 1 to 17. The decimal scaling is one rounded product (or
/// quotient) in the x87 extended format's 64-bit significand, so the scaled value's error is below
/// 2^-63 of it; the digits are then those of the exact value unless the scaled value lies within
/// that error of a rounding boundary (half an integer), and there it declines. Returns nullptr
/// where it declines (also on targets whose long double is not the 64-bit-significand format).
char* fastGeneral(char* out, double v, int precision);

}  // namespace dabs::domain
