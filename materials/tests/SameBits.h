// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstddef>
#include <cstdint>

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

}  // namespace dabs::materials::testing
