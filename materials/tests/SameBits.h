// SPDX-License-Identifier: MIT
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "materials/FourLanes.h"
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

/// A fiber's own update by the law's computeTrial.
template <class Law>
auto ownUpdate(const Law& law) {
  return [&law](const typename Law::State& c, typename Law::State& trial, double strain) {
    return law.computeTrial(c, trial, strain);
  };
}

/// The first n states as the array of fours computeTrials and commitTrials read (the lanes past
/// the last state hold `padding`).
template <class State>
std::vector<StateFours<State>> asFours(const std::vector<State>& states, std::size_t n,
                                       const State& padding) {
  std::vector<StateFours<State>> fours((n + 3) / 4, StateFours<State>::filledWith(padding));
  for (std::size_t i = 0; i < n; ++i) fours[i / 4].set(i % 4, states[i]);
  return fours;
}

/// Expects law.computeTrials over the first n fibers to give each fiber the stress and tangent of
/// `reference(committed, trial, strain)` (the law's computeTrial unless said) to the bit.
template <class Law, class Reference>
void expectEachFibersOwnUpdate(const Law& law, const std::vector<typename Law::State>& committed,
                               const std::vector<double>& strains, std::size_t n,
                               const Reference& reference) {
  // Four values past the last fiber that nothing may write over.
  constexpr double kUntouched = 12345.0;
  std::vector<double> stresses(n + 4, kUntouched), tangents(n + 4, kUntouched);
  // Lanes past the last fiber hold a state of the walk, not a virgin one (nobody reads them).
  const auto fours = asFours(committed, n, committed.back());
  law.computeTrials(fours.data(), FiberStrains::given(strains.data()),
                    Responses{stresses.data(), tangents.data()}, n);
  SCOPED_TRACE(::testing::Message() << "group of " << n);
  for (std::size_t i = n; i < n + 4; ++i) {
    EXPECT_EQ(stresses[i], kUntouched) << "response " << i << " past the last fiber";
    EXPECT_EQ(tangents[i], kUntouched) << "response " << i << " past the last fiber";
  }
  for (std::size_t i = 0; i < n; ++i) {
    typename Law::State trial;
    static_cast<void>(reference(committed[i], trial, strains[i]));
    expectSameBits(StressTangent{stresses[i], tangents[i]}, trial, i, strains[i]);
  }
}
template <class Law>
void expectEachFibersOwnUpdate(const Law& law, const std::vector<typename Law::State>& committed,
                               const std::vector<double>& strains, std::size_t n) {
  expectEachFibersOwnUpdate(law, committed, strains, n, ownUpdate(law));
}

/// Fibers (a committed state and a strain each) as the two arrays computeTrials reads, shuffled
/// so that the four lanes of the AVX update mix branches.
template <class State, class Random>
std::pair<std::vector<State>, std::vector<double>> shuffledArrays(
    std::vector<std::pair<State, double>> fibers, Random& random) {
  std::shuffle(fibers.begin(), fibers.end(), random);
  std::pair<std::vector<State>, std::vector<double>> arrays;
  for (const auto& [state, strain] : fibers) {
    arrays.first.push_back(state);
    arrays.second.push_back(strain);
  }
  return arrays;
}

/// expectEachFibersOwnUpdate for groups of n fibers (three left after the fours: n is the
/// largest count one less than a multiple of four), of four to seven, and with tails of one and
/// two after the fours (the last fibers go again as the group's last four); returns n.
template <class Law, class Reference>
std::size_t expectEveryGroupSize(const Law& law, const std::vector<typename Law::State>& committed,
                                 const std::vector<double>& strains, const Reference& reference) {
#if defined(DABS_FOUR_LANES)
  // On x86-64 the four-lane path runs wherever the processor has AVX (else this compares the
  // one-by-one loop with itself).
  EXPECT_EQ(Law::updatesFourAtOnce(), __builtin_cpu_supports("avx") != 0);
#endif
  const std::size_t n = strains.size() / 4 * 4 - 1;
  for (const std::size_t size :
       {n, std::size_t{4}, std::size_t{5}, std::size_t{6}, std::size_t{7}, n - 1, n - 2})
    expectEachFibersOwnUpdate(law, committed, strains, size, reference);
  return n;
}
template <class Law>
std::size_t expectEveryGroupSize(const Law& law, const std::vector<typename Law::State>& committed,
                                 const std::vector<double>& strains) {
  return expectEveryGroupSize(law, committed, strains, ownUpdate(law));
}

/// Expects law.commitTrials over the first n fibers, each committed at its strain with its
/// computeTrial's stress and tangent, to leave each state as commitTrial leaves it, every field
/// to the bit (the law's state is all doubles).
template <class Law>
void expectEachFibersOwnCommit(const Law& law, const std::vector<typename Law::State>& committed,
                               const std::vector<double>& strains, std::size_t n) {
  using State = typename Law::State;
  static_assert(sizeof(State) % sizeof(std::uint64_t) == 0);
  std::vector<double> stresses(n), tangents(n);
  for (std::size_t i = 0; i < n; ++i) {
    State trial;
    static_cast<void>(law.computeTrial(committed[i], trial, strains[i]));
    stresses[i] = trial.stress;
    tangents[i] = trial.tangent;
  }
  auto fours = asFours(committed, n, committed.back());
  law.commitTrials(fours.data(), FiberStrains::given(strains.data()),
                   Responses{stresses.data(), tangents.data()}, n);
  SCOPED_TRACE(::testing::Message() << "commit of a group of " << n);
  // The lanes past the last fiber are left as they were.
  using Bits = std::array<std::uint64_t, sizeof(State) / 8>;
  const auto padding = std::bit_cast<Bits>(committed.back());
  for (std::size_t i = n; i % 4 != 0; ++i) {
    const auto lane = std::bit_cast<Bits>(stateOf(fours.data(), i));
    EXPECT_EQ(lane, padding) << "lane " << i % 4 << " past the last fiber";
  }
  for (std::size_t i = 0; i < n; ++i) {
    State one = committed[i];
    law.commitTrial(one, strains[i], stresses[i], tangents[i]);
    const auto got =
        std::bit_cast<std::array<std::uint64_t, sizeof(State) / 8>>(stateOf(fours.data(), i));
    const auto expected = std::bit_cast<Bits>(one);
    for (std::size_t k = 0; k < got.size(); ++k)
      EXPECT_EQ(got[k], expected[k]) << "fiber " << i << " field " << k << " strain " << strains[i];
  }
}

/// expectEachFibersOwnCommit for the group sizes expectEveryGroupSize takes.
template <class Law>
void expectEveryGroupSizeCommits(const Law& law, const std::vector<typename Law::State>& committed,
                                 const std::vector<double>& strains) {
  const std::size_t n = strains.size() / 4 * 4 - 1;
  for (const std::size_t size : {n, std::size_t{1}, std::size_t{4}, std::size_t{5}, std::size_t{6},
                                 std::size_t{7}, n - 1, n - 2})
    expectEachFibersOwnCommit(law, committed, strains, size);
}

}  // namespace dabs::materials::testing
