// SPDX-License-Identifier: MIT
#pragma once

// Helpers for material updates of four fibers at a time in AVX registers (x86 only; the callers
// check the processor first). Each function carries the AVX target itself, so that the rest of
// the program keeps the baseline instruction set.

#include <cstddef>
#include <type_traits>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials::lanes {

/// law.computeTrial of fibers from..n-1, one at a time: the fibers left after the fours, or all
/// of them where the processor has no AVX.
template <class Law>
void computeOneByOne(const Law& law, const typename Law::State* committed, const double* strains,
                     const Responses& out, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    typename Law::State trial;
    static_cast<void>(law.computeTrial(committed[i], trial, strains[i]));
    out.set(i, trial.stress, trial.tangent);
  }
}

/// A law's computeTrials: its `fours` member updates the first n - n % 4 fibers four at a time
/// and returns their count. A group of fewer than four (a plane section's bars at two heights)
/// goes one by one, and so does every group where the processor cannot run the fours
/// (Law::updatesFourAtOnce); in a larger one the fibers after the fours go as the group's last
/// four again (each fiber's update is its own, so those written twice get the same bits twice).
template <class Law>
void computeInFours(const Law& law,
                    std::size_t (Law::*fours)(const typename Law::State*, const double*,
                                              const Responses&, std::size_t) const,
                    const typename Law::State* committed, const double* strains,
                    const Responses& out, std::size_t n) {
  if (n >= 4 && Law::updatesFourAtOnce()) {
    if ((law.*fours)(committed, strains, out, n) < n)
      (law.*fours)(committed + (n - 4), strains + (n - 4), out.from(n - 4), std::size_t{4});
    return;
  }
  computeOneByOne(law, committed, strains, out, 0, n);
}

/// A law's commitTrials: its `fours` member commits the first n - n % 4 fibers four at a time
/// and returns their count; the rest (all of them where the processor cannot run the fours) go one
/// at a time through law.commitTrial.
template <class Law>
void commitInFours(const Law& law,
                   std::size_t (Law::*fours)(typename Law::State*, const double*, const Responses&,
                                             std::size_t) const,
                   typename Law::State* states, const double* strains, const Responses& trial,
                   std::size_t n) {
  std::size_t i = n >= 4 && Law::updatesFourAtOnce() ? (law.*fours)(states, strains, trial, n) : 0;
  for (; i < n; ++i) law.commitTrial(states[i], strains[i], trial.stress[i], trial.tangent[i]);
}

}  // namespace dabs::materials::lanes

// x86-64 only: 32-bit x86 may compute the scalar updates in x87 extended precision, which the
// lanes would not reproduce.
#if defined(__x86_64__)
#define DABS_FOUR_LANES 1
#include <immintrin.h>

namespace dabs::materials::lanes {

/// A state's fields as an array of doubles (its laws assert the layout: all doubles, no padding).
template <class State>
const double* fields(const State& s) {
  static_assert(std::is_standard_layout_v<State>);
  return reinterpret_cast<const double*>(&s);
}
template <class State>
double* fields(State& s) {
  static_assert(std::is_standard_layout_v<State>);
  return reinterpret_cast<double*>(&s);
}

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

/// Rows r0..r3 (four doubles of one fiber each) to columns c0..c3 (one field of the four each).
__attribute__((target("avx"))) inline void transpose(__m256d r0, __m256d r1, __m256d r2, __m256d r3,
                                                     __m256d& c0, __m256d& c1, __m256d& c2,
                                                     __m256d& c3) {
  const __m256d t0 = _mm256_unpacklo_pd(r0, r1), t1 = _mm256_unpackhi_pd(r0, r1);
  const __m256d t2 = _mm256_unpacklo_pd(r2, r3), t3 = _mm256_unpackhi_pd(r2, r3);
  c0 = _mm256_permute2f128_pd(t0, t2, 0x20);
  c1 = _mm256_permute2f128_pd(t1, t3, 0x20);
  c2 = _mm256_permute2f128_pd(t0, t2, 0x31);
  c3 = _mm256_permute2f128_pd(t1, t3, 0x31);
}

/// The rows of four fibers (four doubles at rows[k] for fiber k) as columns c0..c3, one field of
/// the four each: storeAsRows' inverse.
__attribute__((target("avx"))) inline void loadAsColumns(const double* const rows[4], __m256d& c0,
                                                         __m256d& c1, __m256d& c2, __m256d& c3) {
  transpose(_mm256_loadu_pd(rows[0]), _mm256_loadu_pd(rows[1]), _mm256_loadu_pd(rows[2]),
            _mm256_loadu_pd(rows[3]), c0, c1, c2, c3);
}

/// Columns c0..c3 (one field of four fibers each) stored as the fibers' rows: four doubles at
/// rows[k] for fiber k (the fields of a state, a row of four at a time).
__attribute__((target("avx"))) inline void storeAsRows(double* const rows[4], __m256d c0,
                                                       __m256d c1, __m256d c2, __m256d c3) {
  __m256d r0, r1, r2, r3;
  transpose(c0, c1, c2, c3, r0, r1, r2, r3);
  _mm256_storeu_pd(rows[0], r0);
  _mm256_storeu_pd(rows[1], r1);
  _mm256_storeu_pd(rows[2], r2);
  _mm256_storeu_pd(rows[3], r3);
}

/// Four fibers' stresses and tangents stored as fibers i .. i + 3 of `out`.
__attribute__((target("avx"))) inline void store(const Responses& out, std::size_t i,
                                                 __m256d stress, __m256d tangent) {
  _mm256_storeu_pd(out.stress + i, stress);
  _mm256_storeu_pd(out.tangent + i, tangent);
}

}  // namespace dabs::materials::lanes

#else

namespace dabs::materials::lanes {
/// No four-lane updates on this processor family.
inline bool available() { return false; }
}  // namespace dabs::materials::lanes

#endif
