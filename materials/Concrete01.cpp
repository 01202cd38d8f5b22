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

}  // namespace

// computeTrial, lane by lane: each branch is evaluated with the scalar code's operations in its
// order (so the same bits) wherever one of the four lanes takes it, and each lane keeps the
// result of its own branch. Comparisons with a NaN are false here as there.
__attribute__((target("avx"))) void Concrete01::computeFourAtOnce(
    const StateFours<State>* committed, const FiberStrains& strains, const Responses& out,
    std::size_t n) const {
  const auto& p = params_;
  const __m256d Ec0 = _mm256_set1_pd(Ec0_), descentSlope = _mm256_set1_pd(descentSlope_);
  const __m256d fpc = _mm256_set1_pd(p.fpc), epsc0 = _mm256_set1_pd(p.epsc0);
  const __m256d fpcu = _mm256_set1_pd(p.fpcu), epsU = _mm256_set1_pd(p.epsU);
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
  const __m256d epsilon = _mm256_set1_pd(DBL_EPSILON), minusEpsilon = _mm256_set1_pd(-DBL_EPSILON);
  const __m256d signBit = _mm256_set1_pd(-0.0);
  // Karsan-Jirsa's zero-stress strain (unload): its two polynomials' coefficients.
  const __m256d a2 = _mm256_set1_pd(0.145), a1 = _mm256_set1_pd(0.13);
  const __m256d b1 = _mm256_set1_pd(0.707), b0 = _mm256_set1_pd(0.834);

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
        const __m256d parabola = _mm256_cmp_pd(strain, epsc0, _CMP_GT_OQ);
        const __m256d descending = _mm256_cmp_pd(strain, epsU, _CMP_GT_OQ);
        const __m256d eta = _mm256_div_pd(strain, epsc0);
        const __m256d parabolaStress =
            _mm256_mul_pd(fpc, _mm256_sub_pd(_mm256_mul_pd(two, eta), _mm256_mul_pd(eta, eta)));
        const __m256d parabolaTangent = _mm256_mul_pd(Ec0, _mm256_sub_pd(one, eta));
        const __m256d descentStress =
            _mm256_add_pd(fpc, _mm256_mul_pd(descentSlope, _mm256_sub_pd(strain, epsc0)));
        const __m256d envelopeStress =
            pick(parabola, parabolaStress, pick(descending, descentStress, fpcu));
        const __m256d envelopeTangent =
            pick(parabola, parabolaTangent, pick(descending, descentSlope, zero));
        loadStress = pick(newMinimum, envelopeStress, loadStress);
        loadTangent = pick(newMinimum, envelopeTangent, loadTangent);
        // The new unloading slope matters only where the committed line lies above the
        // envelope and gives the stress (unload).
        const __m256d unloads =
            _mm256_and_pd(newMinimum, _mm256_cmp_pd(linear, envelopeStress, _CMP_GT_OQ));
        if (any(unloads)) {
          const __m256d forRatio = pick(_mm256_cmp_pd(strain, epsU, _CMP_LT_OQ), epsU, strain);
          const __m256d etaU = _mm256_div_pd(forRatio, epsc0);
          const __m256d ratio = pick(
              _mm256_cmp_pd(etaU, two, _CMP_LT_OQ),
              _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(a2, etaU), etaU), _mm256_mul_pd(a1, etaU)),
              _mm256_add_pd(_mm256_mul_pd(b1, _mm256_sub_pd(etaU, two)), b0));
          const __m256d span = _mm256_sub_pd(strain, _mm256_mul_pd(ratio, epsc0));
          const __m256d elasticSpan = _mm256_div_pd(envelopeStress, Ec0);
          const __m256d secant = _mm256_div_pd(envelopeStress, span);
          const __m256d steep = _mm256_andnot_pd(_mm256_cmp_pd(span, minusEpsilon, _CMP_GT_OQ),
                                                 _mm256_cmp_pd(span, elasticSpan, _CMP_LE_OQ));
          lineSlope = pick(unloads, pick(steep, secant, Ec0), lineSlope);
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
  const auto& p = params_;
  const __m256d minusEpsilon = _mm256_set1_pd(-DBL_EPSILON);
  const __m256d zero = _mm256_setzero_pd(), two = _mm256_set1_pd(2.0);
  const __m256d Ec0 = _mm256_set1_pd(Ec0_), descentSlope = _mm256_set1_pd(descentSlope_);
  const __m256d fpc = _mm256_set1_pd(p.fpc), epsc0 = _mm256_set1_pd(p.epsc0);
  const __m256d fpcu = _mm256_set1_pd(p.fpcu), epsU = _mm256_set1_pd(p.epsU);
  // Karsan-Jirsa's zero-stress strain (unload): its two polynomials' coefficients.
  const __m256d a2 = _mm256_set1_pd(0.145), a1 = _mm256_set1_pd(0.13);
  const __m256d b1 = _mm256_set1_pd(0.707), b0 = _mm256_set1_pd(0.834);
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
      const __m256d eta = _mm256_div_pd(newStrain, epsc0);
      const __m256d parabolaStress =
          _mm256_mul_pd(fpc, _mm256_sub_pd(_mm256_mul_pd(two, eta), _mm256_mul_pd(eta, eta)));
      const __m256d descentStress =
          _mm256_add_pd(fpc, _mm256_mul_pd(descentSlope, _mm256_sub_pd(newStrain, epsc0)));
      const __m256d envelopeStress =
          lanes::pick(_mm256_cmp_pd(newStrain, epsc0, _CMP_GT_OQ), parabolaStress,
                      lanes::pick(_mm256_cmp_pd(newStrain, epsU, _CMP_GT_OQ), descentStress, fpcu));
      const __m256d forRatio =
          lanes::pick(_mm256_cmp_pd(newStrain, epsU, _CMP_LT_OQ), epsU, newStrain);
      const __m256d etaU = _mm256_div_pd(forRatio, epsc0);
      const __m256d ratio = lanes::pick(
          _mm256_cmp_pd(etaU, two, _CMP_LT_OQ),
          _mm256_add_pd(_mm256_mul_pd(_mm256_mul_pd(a2, etaU), etaU), _mm256_mul_pd(a1, etaU)),
          _mm256_add_pd(_mm256_mul_pd(b1, _mm256_sub_pd(etaU, two)), b0));
      const __m256d endStrain = _mm256_mul_pd(ratio, epsc0);
      const __m256d span = _mm256_sub_pd(newStrain, endStrain);
      const __m256d elasticSpan = _mm256_div_pd(envelopeStress, Ec0);
      const __m256d flat = _mm256_cmp_pd(span, minusEpsilon, _CMP_GT_OQ);
      const __m256d steep = _mm256_andnot_pd(flat, _mm256_cmp_pd(span, elasticSpan, _CMP_LE_OQ));
      const __m256d newEnd = lanes::pick(flat, endStrain,
                                         lanes::pick(steep, _mm256_sub_pd(newStrain, span),
                                                     _mm256_sub_pd(newStrain, elasticSpan)));
      const __m256d newSlope = lanes::pick(steep, _mm256_div_pd(envelopeStress, span), Ec0);
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
