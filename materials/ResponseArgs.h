// SPDX-License-Identifier: MIT
#pragma once

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace dabs {

/// An integer word of a response request (`eleResponse 1 section 2 force`), or nullopt unless the
/// whole word is an integer: "1.5" or "2abc" must not be read as 1 or 2.
inline std::optional<int> responseInteger(const std::string& word) {
  int value = 0;
  const char* end = word.data() + word.size();
  const auto [ptr, ec] = std::from_chars(word.data(), end, value);
  if (ec != std::errc{} || ptr != end || word.empty()) return std::nullopt;
  return value;
}

/// A real-number word of a response request (`fiber y z stress`), or nullopt unless the whole word
/// is a finite number.
inline std::optional<double> responseReal(const std::string& word) {
  if (word.empty()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(word.c_str(), &end);
  if (end != word.c_str() + word.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

}  // namespace dabs
