// SPDX-License-Identifier: MIT
#pragma once

// Helpers for material updates of four fibers at a time in AVX registers (x86 only; the callers
// check the processor first). Each function carries the AVX target itself, so that the rest of
// the program keeps the baseline instruction set.

#include <array>
#include <bit>
#include <cfloat>
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

/// The strains of an array of fibers: given one by one (`values`), or under plane-section
/// kinematics from the fibers' coordinates, e0 - y kz + z ky (a fiber section's pass; without the
/// z term in a plane section), formed where an update reads them. A section's strains formed
/// again (to commit a pass, or for a fiber's response) are the pass's to the bit: one expression,
/// here and in lanes::strainsAt, with the same operations (but for the payload of a NaN made of
/// two NaNs, which on x86 is the first operand's, and the compiler may order a product's
/// operands either way; a NaN strain fails the section whatever its bits).
struct FiberStrains {
  const double* values = nullptr;  ///< the strains, or null for the section's kinematics
  const double* y = nullptr;       ///< fibers' coordinates (values null)
  const double* z = nullptr;
  double e0 = 0.0, kz = 0.0, ky = 0.0;  ///< section strains (values null)
  bool planar = false;                  ///< a plane section: no z term

  /// Strains given one by one.
  static FiberStrains given(const double* values) {
    FiberStrains s;
    s.values = values;
    return s;
  }
  /// A section's: e0 - y kz (+ z ky unless `planar`).
  static FiberStrains ofSection(double e0, double kz, double ky, bool planar, const double* y,
                                const double* z) {
    return FiberStrains{nullptr, y, z, e0, kz, ky, planar};
  }
  double operator[](std::size_t i) const {
    if (values != nullptr) return values[i];
    return planar ? e0 - y[i] * kz : e0 - y[i] * kz + z[i] * ky;
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
                     const FiberStrains& strains, const Responses& out, std::size_t from,
                     std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    typename Law::State trial;
    static_cast<void>(law.computeTrial(stateOf(committed, i), trial, strains[i]));
    out.set(i, trial.stress, trial.tangent);
  }
}

/// law.commitTrial of fibers from..n-1, one at a time.
template <class Law>
void commitOneByOne(const Law& law, StateFours<typename Law::State>* states,
                    const FiberStrains& strains, const Responses& trial, std::size_t from,
                    std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    typename Law::State s = stateOf(states, i);
    law.commitTrial(s, strains[i], trial.stress[i], trial.tangent[i]);
    states[i / 4].set(i % 4, s);
  }
}

/// A law's computeTrials: its `fours` member updates all n fibers four at a time (the last one
/// to three in their own four); where the processor cannot run the fours (Law::updatesFourAtOnce)
/// they go one by one.
template <class Law>
void computeInFours(const Law& law,
                    void (Law::*fours)(const StateFours<typename Law::State>*, const FiberStrains&,
                                       const Responses&, std::size_t) const,
                    const StateFours<typename Law::State>* committed, const FiberStrains& strains,
                    const Responses& out, std::size_t n) {
  if (Law::updatesFourAtOnce())
    (law.*fours)(committed, strains, out, n);
  else
    computeOneByOne(law, committed, strains, out, 0, n);
}

/// A law's commitTrials: its `fours` member commits all n fibers four at a time (the last one to
/// three in their own four, its other lanes untouched); where the processor cannot run the fours
/// they go one at a time through law.commitTrial.
template <class Law>
void commitInFours(const Law& law,
                   void (Law::*fours)(StateFours<typename Law::State>*, const FiberStrains&,
                                      const Responses&, std::size_t) const,
                   StateFours<typename Law::State>* states, const FiberStrains& strains,
                   const Responses& trial, std::size_t n) {
  if (Law::updatesFourAtOnce())
    (law.*fours)(states, strains, trial, n);
  else
    commitOneByOne(law, states, strains, trial, 0, n);
}

}  // namespace dabs::materials::lanes

// x86-64 only: 32-bit x86 may compute the scalar updates in x87 extended precision, which the
// lanes would not reproduce. DABS_NO_LANES builds the one-at-a-time code alone, as off x86-64
// (the build compiles the laws so once, so that that code cannot break unseen).
#if defined(__x86_64__) && !defined(DABS_NO_LANES)
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

/// The lanes of fibers i .. i + 3 that are below n (all ones), the others zero.
__attribute__((target("avx"))) inline __m256d fibersBelow(std::size_t i, std::size_t n) {
  if (i + 4 <= n) return _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const auto lane = [i, n](std::size_t l) { return i + l < n ? -1LL : 0LL; };
  return _mm256_castsi256_pd(_mm256_set_epi64x(lane(3), lane(2), lane(1), lane(0)));
}

/// Fibers i .. i + 3 of an array of n, zero past the last (a masked load: no copy, whose stores
/// would stall the vector load that reads them).
__attribute__((target("avx"))) inline __m256d loadFibers(const double* values, std::size_t i,
                                                         std::size_t n) {
  if (i + 4 <= n) return _mm256_loadu_pd(values + i);
  return _mm256_maskload_pd(values + i, _mm256_castpd_si256(fibersBelow(i, n)));
}

/// The strains of fibers i .. i + 3 of n, FiberStrains::operator[] of each; a lane past the last
/// fiber gets the section's axial strain e0 (or zero), an update of it nobody reads.
__attribute__((target("avx"))) inline __m256d strainsAt(const FiberStrains& strains, std::size_t i,
                                                        std::size_t n) {
  if (strains.values != nullptr) return loadFibers(strains.values, i, n);
  __m256d strain =
      _mm256_sub_pd(_mm256_set1_pd(strains.e0),
                    _mm256_mul_pd(loadFibers(strains.y, i, n), _mm256_set1_pd(strains.kz)));
  if (!strains.planar)
    strain = _mm256_add_pd(strain,
                           _mm256_mul_pd(loadFibers(strains.z, i, n), _mm256_set1_pd(strains.ky)));
  return strain;
}

/// The lanes of fibers i .. i + 3 below n whose strain moved from `committed` to `strain` by
/// DBL_EPSILON or more (a NaN strain counts as moved): the fibers a commit changes, as the laws'
/// commitTrial decides it.
__attribute__((target("avx"))) inline __m256d movedLanes(__m256d committed, __m256d strain,
                                                         std::size_t i, std::size_t n) {
  const __m256d distance = _mm256_andnot_pd(_mm256_set1_pd(-0.0), _mm256_sub_pd(strain, committed));
  return _mm256_and_pd(fibersBelow(i, n),
                       _mm256_cmp_pd(distance, _mm256_set1_pd(DBL_EPSILON), _CMP_NLT_UQ));
}

/// In the lanes of `where`, fibers i .. i + 3 of n take their trial's strain, stress and tangent
/// (rows `strainRow`, `stressRow`, `tangentRow` of their four); the other lanes keep theirs.
template <class State>
__attribute__((target("avx"))) inline void takeTrial(StateFours<State>& four, __m256d where,
                                                     __m256d strain, const Responses& trial,
                                                     std::size_t i, std::size_t n,
                                                     std::size_t strainRow, std::size_t stressRow,
                                                     std::size_t tangentRow) {
  store(four, strainRow, pick(where, strain, load(four, strainRow)));
  store(four, stressRow, pick(where, loadFibers(trial.stress, i, n), load(four, stressRow)));
  store(four, tangentRow, pick(where, loadFibers(trial.tangent, i, n), load(four, tangentRow)));
}

/// Four fibers' stresses and tangents stored as fibers i .. i + 3 of `out`, those of them below n.
__attribute__((target("avx"))) inline void store(const Responses& out, std::size_t i, std::size_t n,
                                                 __m256d stress, __m256d tangent) {
  if (i + 4 <= n) {
    _mm256_storeu_pd(out.stress + i, stress);
    _mm256_storeu_pd(out.tangent + i, tangent);
    return;
  }
  const __m256i below = _mm256_castpd_si256(fibersBelow(i, n));
  _mm256_maskstore_pd(out.stress + i, below, stress);
  _mm256_maskstore_pd(out.tangent + i, below, tangent);
}

}  // namespace dabs::materials::lanes

#else

namespace dabs::materials::lanes {
/// No four-lane updates on this processor family.
inline bool available() { return false; }
}  // namespace dabs::materials::lanes

#endif
