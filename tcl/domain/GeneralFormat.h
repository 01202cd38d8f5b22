// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

namespace dabs::domain {

/// Characters formatGeneral writes at most (sign, 17 digits, point, "e-308": 24; with margin).
inline constexpr std::size_t kGeneralFormatMax = 32;

/// Writes `v` as printf's "%.*g" writes it with `precision` significant digits (the C library's
/// correctly rounded decimal value, trailing zeros dropped), from `out`, and returns one past the
/// last character; `out` has room for kGeneralFormatMax characters. The same characters as
/// std::to_chars(out, ..., v, std::chars_format::general, precision), which it calls where its
/// own arithmetic cannot decide the rounding (fastGeneral declines). A precision outside 1 to 17
/// (the recorders' range) throws std::invalid_argument.
char* formatGeneral(char* out, double v, int precision);

/// The common case of formatGeneral without the C++ library: a precision p of 1 to 17 and
/// 10^(p-27) <= |v| < 10^(p+26) (the powers of ten exact in the format below). The decimal scaling
/// is one product (or quotient) rounded to the x87 extended format's 64-bit significand, in which
/// every half integer below 2^63 is exact: rounding is monotonic, so the scaled value rounds to the
/// same integer as the exact one unless it fell on a half itself, and there it declines (a tie,
/// or a value within half an ulp of the scaled one from a tie: none in two million values of 1e-8
/// to 1e6 at 13 digits or fewer, 0.003 % at 15, 0.3 % at 17). Returns nullptr where it declines
/// and wherever fastGeneralAvailable() is false.
char* fastGeneral(char* out, double v, int precision);

/// Whether fastGeneral can answer here and now: an x86 build (without -ffast-math) whose long
/// double is the x87 extended format, computing with the 64-bit significand in this thread (its
/// precision control not set lower; valgrind, for one, computes long double in double).
bool fastGeneralAvailable();

}  // namespace dabs::domain
