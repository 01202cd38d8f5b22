// SPDX-License-Identifier: MIT
// formatGeneral against the C++ library's std::to_chars (general, with a precision: printf's %.*g)
// over random doubles of every magnitude, values of typical analyses, decimal ties and the edges
// of each notation; fastGeneral must answer for nearly all of the typical ones.
#include "tcl/domain/GeneralFormat.h"

#include <gtest/gtest.h>

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GLIBC__)
#include <fpu_control.h>
#endif

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dabs::domain {
namespace {

std::string library(double v, int precision) {
  char text[64];
  const auto r = std::to_chars(text, text + sizeof text, v, std::chars_format::general, precision);
  return {text, r.ptr};
}

std::string ours(double v, int precision) {
  char text[kGeneralFormatMax];
  return {text, formatGeneral(text, v, precision)};
}

/// Whether fastGeneral answered, and, when it did, that it wrote the library's characters.
bool expectFastAgrees(double v, int precision) {
  char text[kGeneralFormatMax];
  char* end = fastGeneral(text, v, precision);
  if (end == nullptr) return false;
  const std::string expected = library(v, precision);
  EXPECT_EQ(std::string(text, end), expected)
      << "v = " << std::hexfloat << v << std::defaultfloat << ", precision " << precision;
  return std::string(text, end) == expected;
}

std::mt19937_64 seeded() {
  return std::mt19937_64(static_cast<std::uint64_t>(::testing::GTEST_FLAG(random_seed)) +
                         20261129U);
}

TEST(GeneralFormatTest, RandomBitPatternsOfEveryMagnitudeAgreeWithTheLibrary) {
  auto rng = seeded();
  int answered = 0;
  for (int i = 0; i < 200000; ++i) {
    const double v = std::bit_cast<double>(rng());
    const int precision = 1 + static_cast<int>(rng() % 17);
    ASSERT_EQ(ours(v, precision), library(v, precision))
        << std::hexfloat << v << " p " << precision;
    answered += expectFastAgrees(v, precision) ? 1 : 0;
  }
  if (fastGeneralAvailable())
    EXPECT_GT(answered, 0);
  else
    EXPECT_EQ(answered, 0);
}

TEST(GeneralFormatTest, BothEndsOfEveryBinaryExponentAgree) {
  // The decimal exponent is estimated from the binary one: 2^b and the double below 2^(b+1) for
  // every b, where the estimate is furthest from log10 |v|.
  for (int b = -1074; b <= 1023; ++b) {
    const double low = std::ldexp(1.0, b);
    const double high = b == 1023 ? std::numeric_limits<double>::max()
                                  : std::nextafter(std::ldexp(1.0, b + 1), 0.0);
    for (int precision = 1; precision <= 17; ++precision)
      for (const double v : {low, high, -low, -high})
        ASSERT_EQ(ours(v, precision), library(v, precision))
            << std::hexfloat << v << " p " << precision;
  }
}

TEST(GeneralFormatTest, ValuesOfAnAnalysisTakeTheFastPathAndAgree) {
  // Displacements, forces, times: magnitudes 1e-12 to 1e9 with both signs, at the recorders'
  // common precisions.
  auto rng = seeded();
  std::uniform_real_distribution<double> decade(-12.0, 9.0);
  for (const int precision : {6, 8, 10, 12, 15, 16, 17}) {
    int answered = 0, inRange = 0;
    const double smallest = std::pow(10.0, precision - 27);  // fastGeneral's range
    for (int i = 0; i < 100000; ++i) {
      double v = std::pow(10.0, decade(rng));
      if (rng() & 1U) v = -v;
      ASSERT_EQ(ours(v, precision), library(v, precision)) << std::hexfloat << v;
      const bool fast = expectFastAgrees(v, precision);
      if (std::fabs(v) >= smallest) {
        ++inRange;
        answered += fast ? 1 : 0;
      }
    }
    // In its range it declines only where the scaled value rounded onto a half: at most one value
    // in an ulp of the largest scaled value, 2^(floor(log2 10^p) - 63) (none in two million at 13
    // digits or fewer, 0.3 % at 17, measured).
    if (!fastGeneralAvailable()) {
      EXPECT_EQ(answered, 0);
      continue;
    }
    const double declineAtMost =
        std::ldexp(1.0, static_cast<int>(std::floor(precision * std::log2(10.0))) - 63);
    EXPECT_LE(inRange - answered, inRange * declineAtMost + 3.0) << "precision " << precision;
  }
}

TEST(GeneralFormatTest, ExactDecimalTiesAreLeftToTheLibrary) {
  // Doubles whose exact value is n + 1/2 units of the last kept digit, for every precision and
  // scale the fast path takes: above the kept digits (a quotient by 10^j: (2n + 1) 10^j / 2, exact
  // while (2n + 1) 5^j < 2^53) and below them (a product by 10^k: m / 2^(k+1) with m an odd
  // multiple of 5^k). The library rounds them half to even; the fast path must not decide them,
  // nor their neighbours wrongly (a quotient by a rounded reciprocal would, in either direction).
  auto rng = seeded();
  int ties = 0;
  char text[kGeneralFormatMax];
  for (int p = 1; p <= 17; ++p) {
    const double low = std::pow(10.0, p - 1), high = std::pow(10.0, p);
    std::uniform_real_distribution<double> digits(low, high);
    for (int j = 1; j <= 26; ++j) {
      const double fives = std::pow(5.0, j);
      for (int t = 0; t < 20; ++t) {
        const double n = std::floor(digits(rng));
        if ((2.0 * n + 1.0) * fives >= 0x1p53) break;
        const double v = std::ldexp((2.0 * n + 1.0) * fives, j - 1);  // (2n + 1) 10^j / 2
        ++ties;
        EXPECT_EQ(fastGeneral(text, v, p), nullptr) << std::hexfloat << v << " p " << p;
        for (const double w : {v, std::nextafter(v, 0.0), std::nextafter(v, 1e300), -v})
          ASSERT_EQ(ours(w, p), library(w, p)) << std::hexfloat << w << " p " << p;
      }
    }
    for (int k = 0; k <= 26; ++k) {
      const double fives = std::pow(5.0, k);
      // m 5^k = 2n + 1 with n of p digits: m odd, 2 10^(p-1) <= m 5^k < 2 10^p, m < 2^53.
      const double mLow = std::ceil(2.0 * low / fives),
                   mHigh = std::min(2.0 * high / fives, 0x1p53);
      if (mLow >= mHigh) continue;
      std::uniform_real_distribution<double> odd(mLow, mHigh);
      for (int t = 0; t < 20; ++t) {
        double m = std::floor(odd(rng));
        if (std::fmod(m, 2.0) == 0.0) m += 1.0;
        if (m >= mHigh || m * fives >= 2.0 * high || m * fives < 2.0 * low) continue;
        const double v = std::ldexp(m, -(k + 1));  // (n + 1/2) / 10^k
        ++ties;
        EXPECT_EQ(fastGeneral(text, v, p), nullptr) << std::hexfloat << v << " p " << p;
        for (const double w : {v, std::nextafter(v, 0.0), std::nextafter(v, 1e300), -v})
          ASSERT_EQ(ours(w, p), library(w, p)) << std::hexfloat << w << " p " << p;
      }
    }
  }
  EXPECT_GT(ties, 2000);
  EXPECT_EQ(ours(6500000.0, 1), "6e+06");
  EXPECT_EQ(ours(7500000.0, 1), "8e+06");
}

#if (defined(__x86_64__) || defined(__i386__)) && defined(__GLIBC__)
TEST(GeneralFormatTest, AThreadWithDoublePrecisionX87GetsTheLibrarysDigits) {
  // The x87 precision control is a thread's own: set to double (53 bits), the extended products
  // would be rounded to 53 bits and the digits wrong; the fast path must see it at the call.
  fpu_control_t saved = 0;
  _FPU_GETCW(saved);
  const fpu_control_t doublePrecision = (saved & ~_FPU_EXTENDED) | _FPU_DOUBLE;
  _FPU_SETCW(doublePrecision);
  const bool available = fastGeneralAvailable();
  auto rng = seeded();
  std::uniform_real_distribution<double> decade(-8.0, 6.0);
  std::vector<std::pair<std::string, std::string>> written;
  for (int i = 0; i < 20000; ++i) {
    const double v = std::pow(10.0, decade(rng));
    const int precision = 1 + static_cast<int>(rng() % 17);
    written.emplace_back(ours(v, precision), library(v, precision));
  }
  _FPU_SETCW(saved);
  EXPECT_FALSE(available);
  for (const auto& [got, expected] : written) ASSERT_EQ(got, expected);
}
#endif

TEST(GeneralFormatTest, PrecisionOutsideOneToSeventeenIsRefused) {
  char text[kGeneralFormatMax];
  EXPECT_THROW(formatGeneral(text, 1.0, 0), std::invalid_argument);
  EXPECT_THROW(formatGeneral(text, -1e-5, 18), std::invalid_argument);
  EXPECT_EQ(fastGeneral(text, 1.0, 0), nullptr);
  EXPECT_EQ(fastGeneral(text, 1.0, 18), nullptr);
}

TEST(GeneralFormatTest, TimesOfAConstantStepAgree) {
  // A recorder's -time column: n dt accumulated, as an analysis forms it.
  for (const double dt : {0.01, 0.005, 0.02, 0.001, 1.0 / 3.0}) {
    double t = 0.0;
    for (int i = 0; i < 5000; ++i) {
      t += dt;
      for (const int precision : {6, 12})
        ASSERT_EQ(ours(t, precision), library(t, precision)) << std::hexfloat << t;
    }
  }
}

TEST(GeneralFormatTest, DecimalTiesRoundAsTheLibraryDoes) {
  // Exact halves of the last kept digit (round half to even on the exact binary value) and the
  // doubles next to them; integers and binary fractions with one digit more than kept.
  std::vector<double> values;
  for (double base : {0.5, 1.5, 2.5, 12.5, 0.125, 0.375, 1234567890125.0, 1234567890135.0,
                      9999999999995.0, 0.000244140625, 1e15 + 5.0, 4503599627370497.0}) {
    values.push_back(base);
    values.push_back(std::nextafter(base, 0.0));
    values.push_back(std::nextafter(base, 1e300));
    values.push_back(-base);
  }
  for (const double v : values)
    for (int precision = 1; precision <= 17; ++precision)
      ASSERT_EQ(ours(v, precision), library(v, precision))
          << std::hexfloat << v << " p " << precision;
  // Doubles whose scaled value is within half an ulp of its 64-bit rounding (about 2^-64 of it)
  // from a half without being one (found with exact rational arithmetic): the extended product
  // rounds onto the half, so the fast path declines, and the library's exact digits decide.
  char hard[kGeneralFormatMax];
  for (const auto& [v, precision] :
       std::vector<std::pair<double, int>>{{0x1.a050bdb9468f8p+24, 17},
                                           {0x1.144604388877cp+29, 17},
                                           {0x1.9a0f143bc88f5p-5, 17},
                                           {0x1.b29d441413f27p-1, 17},
                                           {0x1.3df79aa948fbfp-8, 16},
                                           {0x1.e5a96abb31e45p-9, 16},
                                           {0x1.2d7580e215f96p+3, 16},
                                           {0x1.86f7dbc555d06p+29, 16},
                                           {0x1.125143da1801bp+13, 15},
                                           {0x1.75e3e841b8083p+16, 15},
                                           {0x1.8209de6878544p-21, 15},
                                           {0x1.7e49560f03de8p-21, 15}}) {
    EXPECT_EQ(fastGeneral(hard, v, precision), nullptr) << std::hexfloat << v;
    EXPECT_EQ(ours(v, precision), library(v, precision)) << std::hexfloat << v;
  }
  // A tie must never be decided by the fast path's arithmetic: 2.5 to one digit is "2".
  char text[kGeneralFormatMax];
  EXPECT_EQ(fastGeneral(text, 2.5, 1), nullptr);
  EXPECT_EQ(ours(2.5, 1), "2");
  EXPECT_EQ(ours(3.5, 1), "4");
  EXPECT_EQ(ours(1234567890125.0, 12), "1.23456789012e+12");
}

TEST(GeneralFormatTest, EdgesOfEachNotationAgree) {
  // Where %g changes notation (exponent -5 and -4, p - 1 and p), where rounding carries into the
  // next decade, zeros, signs, infinities, NaN, subnormals and the largest and smallest doubles.
  std::vector<double> values = {0.0,
                                -0.0,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN(),
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::max(),
                                1.0,
                                -1.0,
                                100.0,
                                123456.0,
                                1e-5,
                                1e-4,
                                0.99999999999999989,
                                9.9999999999995e-5,
                                9.99999999999949e-5,
                                999999999999.5,
                                99999.95,
                                0.1,
                                0.2,
                                0.3};
  for (int e = -30; e <= 30; ++e) {
    const double power = std::pow(10.0, e);
    values.push_back(power);
    values.push_back(std::nextafter(power, 0.0));
    values.push_back(std::nextafter(power, 1e300));
    values.push_back(power * 9.99999999999999);
  }
  for (const double v : values)
    for (int precision = 1; precision <= 17; ++precision) {
      ASSERT_EQ(ours(v, precision), library(v, precision))
          << std::hexfloat << v << " p " << precision;
      ASSERT_EQ(ours(-v, precision), library(-v, precision)) << std::hexfloat << -v;
    }
  EXPECT_EQ(ours(1e-5, 6), "1e-05");
  EXPECT_EQ(ours(0.0001, 6), "0.0001");
  EXPECT_EQ(ours(123456.0, 6), "123456");
  EXPECT_EQ(ours(1234567.0, 6), "1.23457e+06");
  EXPECT_EQ(ours(999999.5, 6), "1e+06");
  EXPECT_EQ(ours(-0.1, 12), "-0.1");
}

TEST(GeneralFormatTest, AgreesWithPrintf) {
  // The recorders' promise is printf's %.*g (OpenSees writes through a C++ stream, the same
  // digits): checked here against the C library too, on values whose digits the fast path forms.
  auto rng = seeded();
  std::uniform_real_distribution<double> decade(-10.0, 8.0);
  for (int i = 0; i < 20000; ++i) {
    const double v = std::pow(10.0, decade(rng)) * ((rng() & 1U) ? -1.0 : 1.0);
    const int precision = 1 + static_cast<int>(rng() % 17);
    char expected[64];
    std::snprintf(expected, sizeof expected, "%.*g", precision, v);
    ASSERT_EQ(ours(v, precision), std::string(expected)) << std::hexfloat << v;
  }
}

}  // namespace
}  // namespace dabs::domain
