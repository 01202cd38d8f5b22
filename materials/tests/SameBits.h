// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials::testing {

/// Expects `got` to be the stress and tangent of `trial` to the bit (a NaN equals the same NaN).
template <class State>
void expectSameBits(const StressTangent& got, const State& trial, std::size_t fiber,
                    double strain) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.stress), std::bit_cast<std::uint64_t>(trial.stress))
      << "fiber " << fiber << " strain " << strain;
  EXPECT_EQ(std::bit_cast<std::uint64_t>(got.tangent), std::bit_cast<std::uint64_t>(trial.tangent))
      << "fiber " << fiber << " strain " << strain;
}

/// Expects law.computeTrials over the first n fibers to give each fiber computeTrial's stress
/// and tangent to the bit.
template <class Law>
void expectEachFibersOwnUpdate(const Law& law, const std::vector<typename Law::State>& committed,
                               const std::vector<double>& strains, std::size_t n) {
  std::vector<StressTangent> out(n);
  law.computeTrials(committed.data(), strains.data(), out.data(), n);
  for (std::size_t i = 0; i < n; ++i) {
    typename Law::State trial;
    static_cast<void>(law.computeTrial(committed[i], trial, strains[i]));
    SCOPED_TRACE(::testing::Message() << "group of " << n);
    expectSameBits(out[i], trial, i, strains[i]);
  }
}

}  // namespace dabs::materials::testing
