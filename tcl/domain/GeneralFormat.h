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

/// The common case of formatGeneral without the C++ library: a precision p of 1 to 17 and
/// 10^(p-27) <= |v| < 10^(p+26) (the powers of ten exact in the format below). The decimal scaling
/// is one product (or quotient) rounded to the x87 extended format's 64-bit significand, in which
/// every half integer below 2^62 is exact: rounding is monotonic, so the scaled value rounds to the
/// same integer as the exact one unless it fell on a half itself, and there it declines. Returns
/// nullptr where it declines (also on targets without that format, or where the x87 precision is
/// set lower).
char* fastGeneral(char* out, double v, int precision);

}  // namespace dabs::domain
