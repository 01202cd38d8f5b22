// SPDX-License-Identifier: MIT
#pragma once

// Helpers for material updates of four fibers at a time in AVX registers (x86 only; the callers
// check the processor first). Each function carries the AVX target itself, so that the rest of
// the program keeps the baseline instruction set.

#include <array>
#include <bit>
#include <cstddef>
#include <type_traits>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// The states of four fibers, field by field: row k holds field k (the state's k-th double) of
/// the four. A four-lane update loads a field of four fibers with one instruction (no transposes
/// of rows of fields), and a commit stores only the rows that changed; a four starts on a cache
/// line and each line holds two rows, so an update that reads only some fields, or a commit that
/// changes only some, moves only their lines. On a model whose fiber states do not fit in the
/// cache, what a pass moves bounds its time. Fibers of an array of fours: fiber i is lane i % 4
/// of four i / 4; lanes past the last fiber hold a state of their own (the law's virgin state)
/// that nobody reads.
template <class State>
struct alignas(64) StateFours {
  static_assert(std::is_trivially_copyable_v<State> && sizeof(State) % sizeof(double) == 0,
                "a state of doubles alone");
  static constexpr std::size_t kFields = sizeof(State) / sizeof(double);
  double row[kFields][4];

  /// Four copies of `s`.
  static StateFours filledWith(const State& s) {
    StateFours four;
    for (std::size_t lane = 0; lane < 4; ++lane) four.set(lane, s);
    return four;
  }
  State get(std::size_t lane) const {
    std::array<double, kFields> fields;
    for (std::size_t k = 0; k < kFields; ++k) fields[k] = row[k][lane];
    return std::bit_cast<State>(fields);
  }
  void set(std::size_t lane, const State& s) {
    const auto fields = std::bit_cast<std::array<double, kFields>>(s);
    for (std::size_t k = 0; k < kFields; ++k) row[k][lane] = fields[k];
  }
};

/// Fiber i of an array of fours.
template <class State>
State stateOf(const StateFours<State>* fours, std::size_t i) {
  return fours[i / 4].get(i % 4);
}

}  // namespace dabs::materials

namespace dabs::materials::lanes {

/// law.computeTrial of fibers from..n-1, one at a time: the fibers of a group of fewer than four,
/// or all of them where the processor has no AVX.
template <class Law>
void computeOneByOne(const Law& law, const StateFours<typename Law::State>* committed,
                     const double* strains, const Responses& out, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    typename Law::State trial;
    static_cast<void>(law.computeTrial(stateOf(committed, i), trial, strains[i]));
    out.set(i, trial.stress, trial.tangent);
  }
}

/// law.commitTrial of fibers from..n-1, one at a time.
template <class Law>
void commitOneByOne(const Law& law, StateFours<typename Law::State>* states, const double* strains,
                    const Responses& trial, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    typename Law::State s = stateOf(states, i);
    law.commitTrial(s, strains[i], trial.stress[i], trial.tangent[i]);
    states[i / 4].set(i % 4, s);
  }
}

/// A law's computeTrials: its `fours` member updates all n fibers four at a time, the last one
/// to three in their own four. A group of fewer than four (a plane section's bars at two heights)
/// goes one by one, and so does every group where the processor cannot run the fours
/// (Law::updatesFourAtOnce).
template <class Law>
void computeInFours(const Law& law,
                    void (Law::*fours)(const StateFours<typename Law::State>*, const double*,
                                       const Responses&, std::size_t) const,
                    const StateFours<typename Law::State>* committed, const double* strains,
                    const Responses& out, std::size_t n) {
  if (n >= 4 && Law::updatesFourAtOnce())
    (law.*fours)(committed, strains, out, n);
  else
    computeOneByOne(law, committed, strains, out, 0, n);
}

/// A law's commitTrials: its `fours` member commits the first n - n % 4 fibers four at a time
/// and returns their count; the rest (all of them where the processor cannot run the fours) go one
/// at a time through law.commitTrial.
template <class Law>
void commitInFours(const Law& law,
                   std::size_t (Law::*fours)(StateFours<typename Law::State>*, const double*,
                                             const Responses&, std::size_t) const,
                   StateFours<typename Law::State>* states, const double* strains,
                   const Responses& trial, std::size_t n) {
  const std::size_t done =
      n >= 4 && Law::updatesFourAtOnce() ? (law.*fours)(states, strains, trial, n) : 0;
  commitOneByOne(law, states, strains, trial, done, n);
}

}  // namespace dabs::materials::lanes

// x86-64 only: 32-bit x86 may compute the scalar updates in x87 extended precision, which the
// lanes would not reproduce.
#if defined(__x86_64__)
#define DABS_FOUR_LANES 1
#include <immintrin.h>

namespace dabs::materials::lanes {

/// Whether this processor runs AVX; a property of the machine, the same for the whole run.
inline bool available() {
  static const bool hasAvx = __builtin_cpu_supports("avx");
  return hasAvx;
}

/// `where` ? a : b, lane by lane (`where` all ones or all zeros in each lane).
__attribute__((target("avx"))) inline __m256d pick(__m256d where, __m256d a, __m256d b) {
  __m256d picked;
  // AT&T operand order, and Intel's for a build with -masm=intel.
  asm("vblendvpd {%3, %2, %1, %0|%0, %1, %2, %3}" : "=x"(picked) : "x"(b), "x"(a), "x"(where));
  return picked;
}

__attribute__((target("avx"))) inline bool any(__m256d mask) {
  return _mm256_movemask_pd(mask) != 0;
}

__attribute__((target("avx"))) inline bool all(__m256d mask) {
  return _mm256_movemask_pd(mask) == 0xF;
}

/// Row k of a four (field k of its four fibers) as one vector.
template <class State>
__attribute__((target("avx"))) inline __m256d load(const StateFours<State>& four, std::size_t k) {
  return _mm256_load_pd(four.row[k]);
}
template <class State>
__attribute__((target("avx"))) inline void store(StateFours<State>& four, std::size_t k,
                                                 __m256d v) {
  _mm256_store_pd(four.row[k], v);
}

/// The strains of fibers i .. i + 3 of n; a lane past the last fiber gets `padding`'s (the
/// four's own committed strain, so that its update is a cheap one nobody reads).
__attribute__((target("avx"))) inline __m256d strainsAt(const double* strains, std::size_t i,
                                                        std::size_t n, const double* padding) {
  if (i + 4 <= n) return _mm256_loadu_pd(strains + i);
  alignas(32) double four[4];
  for (std::size_t l = 0; l < 4; ++l) four[l] = i + l < n ? strains[i + l] : padding[l];
  return _mm256_load_pd(four);
}

/// Four fibers' stresses and tangents stored as fibers i .. i + 3 of `out`, those of them below n.
__attribute__((target("avx"))) inline void store(const Responses& out, std::size_t i, std::size_t n,
                                                 __m256d stress, __m256d tangent) {
  if (i + 4 <= n) {
    _mm256_storeu_pd(out.stress + i, stress);
    _mm256_storeu_pd(out.tangent + i, tangent);
    return;
  }
  alignas(32) double stresses[4], tangents[4];
  _mm256_store_pd(stresses, stress);
  _mm256_store_pd(tangents, tangent);
  for (std::size_t l = 0; i + l < n; ++l) out.set(i + l, stresses[l], tangents[l]);
}

}  // namespace dabs::materials::lanes

#else

namespace dabs::materials::lanes {
/// No four-lane updates on this processor family.
inline bool available() { return false; }
}  // namespace dabs::materials::lanes

#endif
