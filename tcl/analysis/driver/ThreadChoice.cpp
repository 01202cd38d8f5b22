// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/ThreadChoice.h"

#include <algorithm>
#include <charconv>

namespace dabs::analysis {

std::optional<int> ThreadChoice::parseCount(std::string_view text) noexcept {
  if (text == "auto") return 0;
  int n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 1 || n > kMaxThreads)
    return std::nullopt;
  return n;
}

ThreadChoice::ThreadChoice(int available) noexcept : available_(std::max(available, 1)) { reset(); }

void ThreadChoice::reset(std::size_t sharedWork) noexcept {
  recorded_ = 0;
  trials_ = 0;
  chosen_ = 1;
  measured_ = false;
  ratio_ = 1.0;
  sinceChoice_ = 0;
  revisitAfter_ = kRevisitAfter;
  revisited_ = 0;
  decisions_ = 0;
  fixed_ = available_ < 2 || sharedWork < 2;
  decided_ = fixed_;
}

int ThreadChoice::next() const noexcept {
  if (decided_) return chosen_;
  const int k = recorded_ - kWarmUp;
  if (k < 0) return 1;
  const int pair = k / 2;
  const bool manyFirst = pair % 2 == 1;
  const bool first = k % 2 == 0;
  return first == manyFirst ? available_ : 1;
}

void ThreadChoice::record(double seconds, int iterations) noexcept {
  if (fixed_) return;
  if (decided_) {
    if (++sinceChoice_ < revisitAfter_) return;
    revisited_ = chosen_;
    decided_ = false;  // measured again: the pairs alone, the choice's steps were the warm-up
    trials_ = 0;
    recorded_ = kWarmUp;
    return;
  }
  const int k = recorded_ - kWarmUp;
  if (k >= 0) {
    const double perIteration = seconds / std::max(iterations, 1);
    (next() == 1 ? one_ : many_)[static_cast<std::size_t>(k / 2)] = perIteration;
  }
  ++recorded_;
  if (recorded_ < kWarmUp + 2 * kPairs) return;
  std::array<double, kPairs> ratio{};
  for (int p = 0; p < kPairs; ++p) {
    const auto i = static_cast<std::size_t>(p);
    ratio[i] = one_[i] > 0.0 ? many_[i] / one_[i] : 1.0;
  }
  const auto middle = ratio.begin() + kPairs / 2;
  std::nth_element(ratio.begin(), middle, ratio.end());
  double median = *middle;
  if (kPairs % 2 == 0) median = 0.5 * (median + *std::max_element(ratio.begin(), middle));
  ratio_ = median;
  measured_ = true;
  ++trials_;
  const bool gain = median <= 1.0 - kMargin;
  if (!gain && median < kRecheckBelow && trials_ < kTrials) {
    recorded_ = kWarmUp;  // the next steps are the next trial's pairs
    return;
  }
  chosen_ = gain ? available_ : 1;
  decided_ = true;
  ++decisions_;
  sinceChoice_ = 0;
  revisitAfter_ =
      revisited_ == chosen_ ? std::min(2 * revisitAfter_, kRevisitAtMost) : kRevisitAfter;
  revisited_ = 0;
}

}  // namespace dabs::analysis
