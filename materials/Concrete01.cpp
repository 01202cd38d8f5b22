// SPDX-License-Identifier: MIT
#include "materials/Concrete01.h"

#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "materials/FourLanes.h"
#include "materials/InputError.h"

namespace dabs::materials {

void Concrete01::Params::validate() const {
  if (!std::isfinite(fpc) || fpc == 0.0) throw InputError("fpc", "must be nonzero");
  if (!std::isfinite(epsc0) || epsc0 == 0.0) throw InputError("epsc0", "must be nonzero");
  if (!std::isfinite(fpcu) || std::fabs(fpcu) > std::fabs(fpc))
    throw InputError("fpcu", "must not exceed fpc in magnitude");
  if (!std::isfinite(epsU) || std::fabs(epsU) <= std::fabs(epsc0))
    throw InputError("epsU", "must exceed epsc0 in magnitude (crushing after the peak)");
}

Concrete01::Params Concrete01::Params::normalized() const {
  return Params{-std::fabs(fpc), -std::fabs(epsc0), -std::fabs(fpcu), -std::fabs(epsU)};
}

Concrete01::Concrete01(int tag, const Params& params)
    : StatefulUniaxial(tag), params_(params.normalized()) {
  assert(params_.fpc < 0.0 && params_.epsc0 < 0.0 && params_.epsU < params_.epsc0);
  Ec0_ = 2.0 * params_.fpc / params_.epsc0;
  descentSlope_ = (params_.fpc - params_.fpcu) / (params_.epsc0 - params_.epsU);
  revertToStart();
}

Concrete01::State Concrete01::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  s.unloadSlope = s.tangent;
  return s;
}

void Concrete01::computeTrials(const StateFours<State>* committed, const FiberStrains& strains,
                               const Responses& out, std::size_t n) const {
  lanes::computeInFours(*this, &Concrete01::computeFourAtOnce, committed, strains, out, n);
}

void Concrete01::commitTrials(StateFours<State>* states, const FiberStrains& strains,
                              const Responses& trial, std::size_t n) const {
  lanes::commitInFours(*this, &Concrete01::commitFourAtOnce, states, strains, trial, n);
}

#ifdef DABS_FOUR_LANES

namespace {

using lanes::any;
using lanes::pick;

// Rows of a StateFours<Concrete01State>.
constexpr std::size_t kStrain = offsetof(Concrete01State, strain) / sizeof(double);
constexpr std::size_t kStress = offsetof(Concrete01State, stress) / sizeof(double);
constexpr std::size_t kTangent = offsetof(Concrete01State, tangent) / sizeof(double);
constexpr std::size_t kMinStrain = offsetof(Concrete01State, minStrain) / sizeof(double);
constexpr std::size_t kEndStrain = offsetof(Concrete01State, endStrain) / sizeof(double);
constexpr std::size_t kUnloadSlope = offsetof(Concrete01State, unloadSlope) / sizeof(double);
static_assert(std::is_standard_layout_v<Concrete01State> && sizeof(Concrete01State) == 48);

/// Concrete01::envelope and Concrete01::unload in four lanes, with their operations in their
/// order: the update and the commit of a new most compressive strain share them.
struct EnvelopeLanes {
  __m256d Ec0, descentSlope, fpc, epsc0, fpcu, epsU, zero, one, two, minusEpsilon;
  // Karsan-Jirsa's zero-stress strain (unload): its two polynomials' coefficients.
  __m256d a2, a1, b1, b0;

  /// For the parameters `p` (negative), the initial tangent and the descent's slope.
  __attribute__((target("avx"))) static EnvelopeLanes of(const Concrete01::Params& p, double Ec0,
                                                         double descentSlope) {
    return EnvelopeLanes{
        _mm256_set1_pd(Ec0),          _mm256_set1_pd(descentSlope), _mm256_set1_pd(p.fpc),
        _mm256_set1_pd(p.epsc0),      _mm256_set1_pd(p.fpcu),       _mm256_set1_pd(p.epsU),
        _mm256_setzero_pd(),          _mm256_set1_pd(1.0),          _mm256_set1_pd(2.0),
        _mm256_set1_pd(-DBL_EPSILON), _mm256_set1_pd(0.145),        _mm256_set1_pd(0.13),
        _mm256_set1_pd(0.707),        _mm256_set1_pd(0.834)};
  }

  /// The envelope's stress and tangent at `strain`.
  __attribute__((target("avx"))) void envelope(__m256d strain, __m256d& stress,
                                               __m256d& tangent) const {
    const __m256d parabola = _mm256_cmp_pd(strain, epsc0, _CMP_GT_OQ);
    const __m256d descending = _mm256_cmp_pd(strain, epsU, _CMP_GT_OQ);
    const __m256d eta = _mm256_div_pd(strain, epsc0);
    const __m256d parabolaStress =
        _mm256_mul_pd(fpc, _mm256_sub_pd(_mm256_mul_pd(two, eta), _mm256_mul_pd(eta, eta)));
    const __m256d parabolaTangent = _mm256_mul_pd(Ec0, _mm256_sub_pd(one, eta));
    const __m256d descentStress =
        _mm256_add_pd(fpc, _mm256_mul_pd(descentSlope, _mm256_sub_pd(strain, epsc0)));
    stress = pick(parabola, parabolaStress, pick(descending, descentStress, fpcu));
    tangent = pick(parabola, parabolaTangent, pick(descending, descentSlope, zero));
  }
  /// The unloading line from the envelope point (minStrain, stress): its zero-stress strain and
  /// its slope.
  __attribute__((target("avx"))) void unload(__m256d minStrain, __m256d stress, __m256d& endStrain,
                                             __m256d& slope) const {
    const __m256d forRatio = pick(_mm256_cmp_pd(minStrain, epsU, _CMP_LT_OQ), epsU, minStrain);
    const __m256d eta = _mm256_div_pd(forRatio, epsc0);
    const __m256d ratio =
        pick(_mm256_cmp_pd(eta, two, _CMP_LT_OQ),
             _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(a2, eta), eta), _mm256_mul_pd(a1, eta)),
             _mm256_add_pd(_mm256_mul_pd(b1, _mm256_sub_pd(eta, two)), b0));
    const __m256d end = _mm256_mul_pd(ratio, epsc0);
    const __m256d span = _mm256_sub_pd(minStrain, end);
    const __m256d elasticSpan = _mm256_div_pd(stress, Ec0);
    const __m256d flat = _mm256_cmp_pd(span, minusEpsilon, _CMP_GT_OQ);
    const __m256d steep = _mm256_andnot_pd(flat, _mm256_cmp_pd(span, elasticSpan, _CMP_LE_OQ));
    endStrain =
        pick(flat, end,
             pick(steep, _mm256_sub_pd(minStrain, span), _mm256_sub_pd(minStrain, elasticSpan)));
    slope = pick(steep, _mm256_div_pd(stress, span), Ec0);
  }
};

}  // namespace

// computeTrial, lane by lane: each branch is evaluated with the scalar code's operations in its
// order (so the same bits) wherever one of the four lanes takes it, and each lane keeps the
// result of its own branch. Comparisons with a NaN are false here as there.
__attribute__((target("avx"))) void Concrete01::computeFourAtOnce(
    const StateFours<State>* committed, const FiberStrains& strains, const Responses& out,
    std::size_t n) const {
  const EnvelopeLanes envelope = EnvelopeLanes::of(params_, Ec0_, descentSlope_);
  const __m256d zero = _mm256_setzero_pd(), epsilon = _mm256_set1_pd(DBL_EPSILON);
  const __m256d signBit = _mm256_set1_pd(-0.0);

  for (std::size_t i = 0; i < n; i += 4) {
    const StateFours<State>& c = committed[i / 4];
    const __m256d cStrain = lanes::load(c, kStrain), cStress = lanes::load(c, kStress);
    const __m256d cTangent = lanes::load(c, kTangent);
    const __m256d strain = lanes::strainsAt(strains, i, n);
    const __m256d unchanged = _mm256_cmp_pd(
        _mm256_andnot_pd(signBit, _mm256_sub_pd(strain, cStrain)), epsilon, _CMP_LT_OQ);
    const __m256d tensile = _mm256_cmp_pd(strain, zero, _CMP_GT_OQ);
    if (lanes::all(tensile)) {
      // Four open cracks (the tension side of a section in bending): no stress, no tangent.
      lanes::store(out, i, n, _mm256_and_pd(unchanged, cStress),
                   _mm256_and_pd(unchanged, cTangent));
      continue;
    }
    const __m256d minStrain = lanes::load(c, kMinStrain);
    const __m256d endStrain = lanes::load(c, kEndStrain);
    const __m256d slope = lanes::load(c, kUnloadSlope);

    const __m256d linear = _mm256_sub_pd(_mm256_add_pd(cStress, _mm256_mul_pd(slope, strain)),
                                         _mm256_mul_pd(slope, cStrain));
    const __m256d loading = _mm256_cmp_pd(strain, cStrain, _CMP_LT_OQ);

    // Unloading (strain at or above the committed one): along the line while in compression.
    const __m256d onLine = _mm256_andnot_pd(loading, _mm256_cmp_pd(linear, zero, _CMP_LE_OQ));
    __m256d stress = pick(onLine, linear, zero);
    __m256d tangent = pick(onLine, slope, zero);

    if (any(loading)) {
      // reload: the envelope past the most compressive strain, else the unloading line to
      // endStrain, else zero; then the committed line where it lies above.
      const __m256d reloadLine = _mm256_cmp_pd(strain, endStrain, _CMP_LE_OQ);
      __m256d loadStress =
          pick(reloadLine, _mm256_mul_pd(slope, _mm256_sub_pd(strain, endStrain)), zero);
      __m256d loadTangent = pick(reloadLine, slope, zero);
      __m256d lineSlope = slope;
      const __m256d newMinimum =
          _mm256_and_pd(loading, _mm256_cmp_pd(strain, minStrain, _CMP_LE_OQ));
      if (any(newMinimum)) {
        __m256d envelopeStress, envelopeTangent;
        envelope.envelope(strain, envelopeStress, envelopeTangent);
        loadStress = pick(newMinimum, envelopeStress, loadStress);
        loadTangent = pick(newMinimum, envelopeTangent, loadTangent);
        // The new unloading slope matters only where the committed line lies above the
        // envelope and gives the stress (unload).
        const __m256d unloads =
            _mm256_and_pd(newMinimum, _mm256_cmp_pd(linear, envelopeStress, _CMP_GT_OQ));
        if (any(unloads)) {
          __m256d newEnd, newSlope;
          envelope.unload(strain, envelopeStress, newEnd, newSlope);
          lineSlope = pick(unloads, newSlope, lineSlope);
        }
      }
      const __m256d aboveLine = _mm256_cmp_pd(linear, loadStress, _CMP_GT_OQ);
      loadStress = pick(aboveLine, linear, loadStress);
      loadTangent = pick(aboveLine, lineSlope, loadTangent);
      stress = pick(loading, loadStress, stress);
      tangent = pick(loading, loadTangent, tangent);
    }
    stress = pick(tensile, zero, stress);
    tangent = pick(tensile, zero, tangent);
    stress = pick(unchanged, cStress, stress);
    tangent = pick(unchanged, cTangent, tangent);
    lanes::store(out, i, n, stress, tangent);
  }
}

// commitTrial, lane by lane, with its operations in its order: at a new most compressive strain
// the envelope and the new unloading line (envelope, unload), then the trial's strain, stress and
// tangent, in every lane whose strain moved; a lane that did not, or lies past the last fiber,
// keeps its fields.
__attribute__((target("avx"))) void Concrete01::commitFourAtOnce(StateFours<State>* states,
                                                                 const FiberStrains& strains,
                                                                 const Responses& trial,
                                                                 std::size_t n) const {
  const EnvelopeLanes envelope = EnvelopeLanes::of(params_, Ec0_, descentSlope_);
  const __m256d zero = _mm256_setzero_pd();
  for (std::size_t i = 0; i < n; i += 4) {
    StateFours<State>& s = states[i / 4];
    const __m256d strain = lanes::load(s, kStrain);
    const __m256d newStrain = lanes::strainsAt(strains, i, n);
    const __m256d moved = lanes::movedLanes(strain, newStrain, i, n);
    const __m256d newMinimum = _mm256_and_pd(
        _mm256_and_pd(moved, _mm256_cmp_pd(newStrain, zero, _CMP_NGT_UQ)),
        _mm256_and_pd(_mm256_cmp_pd(newStrain, strain, _CMP_LT_OQ),
                      _mm256_cmp_pd(newStrain, lanes::load(s, kMinStrain), _CMP_LE_OQ)));
    if (lanes::any(newMinimum)) {
      // commitTrial's envelope and unload at the new most compressive strain.
      __m256d envelopeStress, envelopeTangent, newEnd, newSlope;
      envelope.envelope(newStrain, envelopeStress, envelopeTangent);
      envelope.unload(newStrain, envelopeStress, newEnd, newSlope);
      lanes::store(s, kMinStrain, lanes::pick(newMinimum, newStrain, lanes::load(s, kMinStrain)));
      lanes::store(s, kEndStrain, lanes::pick(newMinimum, newEnd, lanes::load(s, kEndStrain)));
      lanes::store(s, kUnloadSlope,
                   lanes::pick(newMinimum, newSlope, lanes::load(s, kUnloadSlope)));
    }
    lanes::takeTrial(s, moved, newStrain, trial, i, n, kStrain, kStress, kTangent);
  }
}

#else

void Concrete01::commitFourAtOnce(StateFours<State>*, const FiberStrains&, const Responses&,
                                  std::size_t) const {}
void Concrete01::computeFourAtOnce(const StateFours<State>*, const FiberStrains&, const Responses&,
                                   std::size_t) const {}

#endif

}  // namespace dabs::materials
