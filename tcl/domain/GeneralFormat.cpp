// SPDX-License-Identifier: MIT
#include "tcl/domain/GeneralFormat.h"

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace dabs::domain {

namespace {

/// 10^0 .. 10^27, each exact in a 64-bit significand (5^27 < 2^63).
constexpr int kLargestExactPower = 27;
constexpr long double kPowersOfTen[kLargestExactPower + 1] = {
    1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,  1e7L,  1e8L,  1e9L,
    1e10L, 1e11L, 1e12L, 1e13L, 1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L,
    1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};

/// |v| 10^k in long double (one rounding), k within the exact powers.
long double scaled(long double magnitude, int k) {
  return k >= 0 ? magnitude * kPowersOfTen[k] : magnitude / kPowersOfTen[-k];
}

/// "00" to "99".
constexpr char kTwoDigits[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

/// The p decimal digits of n (n < 10^p, leading zeros written) into `digits`, most significant
/// first.
void writeDigits(std::uint64_t n, int p, char* digits) {
  int i = p;
  for (; i >= 2; i -= 2) {
    const auto pair = static_cast<std::size_t>(n % 100) * 2;
    n /= 100;
    digits[i - 2] = kTwoDigits[pair];
    digits[i - 1] = kTwoDigits[pair + 1];
  }
  if (i == 1) digits[0] = static_cast<char>('0' + n);
}

}  // namespace

bool fastGeneralAvailable() {
#if (defined(__x86_64__) || defined(__i386__)) && !defined(__FAST_MATH__)
  // The x87 extended format (a 64-bit significand in the first eight bytes), computed in it now:
  // the precision control is a thread's own and may be set to double (53 bits), where the
  // products below would round to 53 bits. Checked at every call: a volatile addition.
  if constexpr (std::numeric_limits<long double>::digits != 64) {
    return false;
  } else {
    volatile long double one = 1.0L;
    return one + 0x1p-63L != one;
  }
#else
  return false;  // another long double, or a build that lets the compiler reassociate
#endif
}

char* fastGeneral(char* out, double v, int precision) {
  const int p = precision;
  if (p < 1 || p > 17 || !fastGeneralAvailable()) return nullptr;
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  if (biased == 0 || biased == 0x7ff) return nullptr;  // zero, subnormal, infinite, NaN
  // |v| lies in [2^b, 2^(b+1)), b = biased - 1023, so E = floor(log10 |v|) is floor(b log10 2) or
  // one more; floor(b 78913 / 2^18) is floor(b log10 2) for |b| < 1650 (Ryu's log10Pow2: Adams,
  // "Ryu: fast float-to-string conversion", PLDI 2018).
  int exponent = ((biased - 1023) * 78913) >> 18;
  int k = p - 1 - exponent;
  if (k > kLargestExactPower || k < -kLargestExactPower + 1) return nullptr;
  const long double magnitude = std::fabs(static_cast<long double>(v));
  long double s = scaled(magnitude, k);
  // Rounding is monotonic and the powers are exact, so these comparisons are the exact value's.
  if (s >= kPowersOfTen[p]) {
    ++exponent;
    s = scaled(magnitude, --k);
  }
  if (s < kPowersOfTen[p - 1]) return nullptr;  // (the estimate is never above E)
  // s is |v| 10^k rounded once to a 64-bit significand, in which n + 1/2 is exact for every n
  // (s < 10^17 < 2^63): rounding is monotonic, so s and the exact value lie on the same side of
  // every half, and the nearest integer of s is the exact value's, unless s is a half itself (the
  // exact value a tie, or within half an ulp of s from one), which only the exact digits decide.
  // Adding 2^63 rounds s to an integer that the sum's significand holds below its top bit: to the
  // nearest in the default rounding mode, and anything else (a directed mode) is declined too.
  constexpr long double kRoundingShift = 0x1p63L;
  const long double shifted = s + kRoundingShift;
  const long double nearest = shifted - kRoundingShift;
  if (!(std::fabs(s - nearest) < 0.5L)) return nullptr;
  std::uint64_t significand = 0;
  std::memcpy(&significand, &shifted, sizeof significand);
  std::uint64_t n = significand & ~(std::uint64_t{1} << 63);
  if (nearest == kPowersOfTen[p]) {  // rounded up to the next decade
    n /= 10;
    ++exponent;
  }
  char digits[18];
  writeDigits(n, p, digits);
  int last = p;  // %g drops trailing zeros after the point
  while (last > 1 && digits[last - 1] == '0') --last;

  char* o = out;
  if (v < 0.0) *o++ = '-';
  if (exponent >= -4 && exponent < p) {
    // Fixed notation with p - 1 - exponent digits after the point.
    if (exponent >= 0) {
      const int integerDigits = exponent + 1;
      for (int i = 0; i < integerDigits; ++i) *o++ = digits[i];
      if (last > integerDigits) {
        *o++ = '.';
        for (int i = integerDigits; i < last; ++i) *o++ = digits[i];
      }
    } else {
      *o++ = '0';
      *o++ = '.';
      for (int i = exponent + 1; i < 0; ++i) *o++ = '0';
      for (int i = 0; i < last; ++i) *o++ = digits[i];
    }
    return o;
  }
  // Scientific notation: d.ddd, then the exponent's sign and two digits (|E| < 45 in this range).
  *o++ = digits[0];
  if (last > 1) {
    *o++ = '.';
    for (int i = 1; i < last; ++i) *o++ = digits[i];
  }
  *o++ = 'e';
  *o++ = exponent < 0 ? '-' : '+';
  const int e = exponent < 0 ? -exponent : exponent;
  *o++ = static_cast<char>('0' + e / 10);
  *o++ = static_cast<char>('0' + e % 10);
  return o;
}

char* formatGeneral(char* out, double v, int precision) {
  if (precision < 1 || precision > 17)
    throw std::invalid_argument("formatGeneral: precision must be 1 to 17, not " +
                                std::to_string(precision));
  if (char* end = fastGeneral(out, v, precision)) return end;
  // (At most 24 characters for these precisions: -2.2250738585072014e-308.)
  return std::to_chars(out, out + kGeneralFormatMax, v, std::chars_format::general, precision).ptr;
}

}  // namespace dabs::domain
