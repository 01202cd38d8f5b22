// SPDX-License-Identifier: MIT
#include "materials/Concrete02.h"

#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "materials/FourLanes.h"
#include "materials/InputError.h"

namespace dabs::materials {

Concrete02::Params Concrete02::Params::withDefaults(double fpc, double epsc0, double fpcu,
                                                    double epsU) {
  return Params{fpc, epsc0, fpcu, epsU, 0.1, 0.1 * std::fabs(fpc), 0.1 * fpc / epsc0};
}

void Concrete02::Params::validate() const {
  if (!std::isfinite(fpc) || fpc >= 0.0) throw InputError("fpc", "must be negative");
  if (!std::isfinite(epsc0) || epsc0 >= 0.0) throw InputError("epsc0", "must be negative");
  if (!std::isfinite(fpcu) || fpcu > 0.0 || fpcu < fpc)
    throw InputError("fpcu", "must be in [fpc, 0]");
  if (!std::isfinite(epsU) || epsU >= epsc0)
    throw InputError("epsU", "must be more negative than epsc0");
  if (!std::isfinite(lambda) || lambda < 0.0 || lambda >= 1.0)
    throw InputError("lambda", "must be in [0, 1)");
  if (!std::isfinite(ft) || ft < 0.0) throw InputError("ft", "must be >= 0");
  if (!std::isfinite(Ets) || Ets <= 0.0) throw InputError("Ets", "must be positive");
}

Concrete02::Concrete02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.fpc < 0.0 && params.epsc0 < 0.0 && params.Ets > 0.0);
  const auto& p = params_;
  Ec0_ = 2.0 * p.fpc / p.epsc0;
  epsR_ = (p.fpcu - p.lambda * Ec0_ * p.epsU) / (Ec0_ * (1.0 - p.lambda));
  sigR_ = Ec0_ * epsR_;
  epsCrack_ = p.ft / Ec0_;
  epsZero_ = p.ft * (1.0 / p.Ets + 1.0 / Ec0_);
  revertToStart();
}

Concrete02::State Concrete02::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  setMinimumStrain(s, 0.0, 0.0);
  return s;
}

void Concrete02::computeTrials(const StateFours<State>* committed, const FiberStrains& strains,
                               const Responses& out, std::size_t n) const {
  lanes::computeInFours(*this, &Concrete02::computeFourAtOnce, committed, strains, out, n);
}

void Concrete02::commitTrials(StateFours<State>* states, const FiberStrains& strains,
                              const Responses& trial, std::size_t n) const {
  lanes::commitInFours(*this, &Concrete02::commitFourAtOnce, states, strains, trial, n);
}

#ifdef DABS_FOUR_LANES

namespace {

using lanes::any;
using lanes::pick;

// Rows of a StateFours<Concrete02State>.
constexpr std::size_t kStrain = offsetof(Concrete02State, strain) / sizeof(double);
constexpr std::size_t kStress = offsetof(Concrete02State, stress) / sizeof(double);
constexpr std::size_t kTangent = offsetof(Concrete02State, tangent) / sizeof(double);
constexpr std::size_t kDept = offsetof(Concrete02State, dept) / sizeof(double);
constexpr std::size_t kEcmin = offsetof(Concrete02State, ecmin) / sizeof(double);
constexpr std::size_t kSigMin = offsetof(Concrete02State, sigMin) / sizeof(double);
constexpr std::size_t kEr = offsetof(Concrete02State, Er) / sizeof(double);
constexpr std::size_t kEpt = offsetof(Concrete02State, ept) / sizeof(double);
static_assert(std::is_standard_layout_v<Concrete02State> && sizeof(Concrete02State) == 64);
// A commit writes the lines of rows 0 to 3 (strain, stress, tangent, dept) and, at a new most
// compressive strain, those of rows 4 to 7.
static_assert(kStrain < 4 && kStress < 4 && kTangent < 4 && kDept < 4);

/// Concrete02::tensionEnvelope in four lanes.
struct TensionLanes {
  __m256d Ec0, epsCrack, epsZero, ft, Ets, minusEts, residualTangent, zero;

  __attribute__((target("avx"))) void at(__m256d x, __m256d& stress, __m256d& tangent) const {
    const __m256d uncracked = _mm256_cmp_pd(x, epsCrack, _CMP_LE_OQ);
    const __m256d softening = _mm256_cmp_pd(x, epsZero, _CMP_LE_OQ);
    const __m256d softStress = _mm256_sub_pd(ft, _mm256_mul_pd(Ets, _mm256_sub_pd(x, epsCrack)));
    stress = pick(uncracked, _mm256_mul_pd(x, Ec0), pick(softening, softStress, zero));
    tangent = pick(uncracked, Ec0, pick(softening, minusEts, residualTangent));
  }
};

}  // namespace

// computeTrial, lane by lane: each branch is evaluated with the scalar code's operations in its
// order (so the same bits) wherever one of the four lanes takes it, and each lane keeps the
// result of its own branch. A comparison with a NaN is false here as there, so a NaN strain
// takes the same branch too.
__attribute__((target("avx"))) void Concrete02::computeFourAtOnce(
    const StateFours<State>* committed, const FiberStrains& strains, const Responses& out,
    std::size_t n) const {
  const auto& p = params_;
  const __m256d Ec0 = _mm256_set1_pd(Ec0_);
  const __m256d half = _mm256_set1_pd(0.5), one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
  const __m256d fpc = _mm256_set1_pd(p.fpc), epsc0 = _mm256_set1_pd(p.epsc0);
  const __m256d fpcu = _mm256_set1_pd(p.fpcu), epsU = _mm256_set1_pd(p.epsU);
  const __m256d descent = _mm256_set1_pd(p.fpcu - p.fpc),
                descentSpan = _mm256_set1_pd(p.epsU - p.epsc0);
  const __m256d descentSlope = _mm256_set1_pd((p.fpcu - p.fpc) / (p.epsU - p.epsc0));
  const __m256d residualTangent = _mm256_set1_pd(concrete02::kResidualTangent);
  const __m256d ft = _mm256_set1_pd(p.ft), Ets = _mm256_set1_pd(p.Ets);
  const __m256d minusEts = _mm256_set1_pd(-p.Ets);
  const __m256d epsCrack = _mm256_set1_pd(epsCrack_), epsZero = _mm256_set1_pd(epsZero_);
  const __m256d zero = _mm256_setzero_pd(), epsilon = _mm256_set1_pd(DBL_EPSILON);
  const __m256d signBit = _mm256_set1_pd(-0.0);

  const TensionLanes tensionLanes{Ec0, epsCrack, epsZero, ft, Ets, minusEts, residualTangent, zero};

  for (std::size_t i = 0; i < n; i += 4) {
    const StateFours<State>& c = committed[i / 4];
    const __m256d cStrain = lanes::load(c, kStrain), cStress = lanes::load(c, kStress);
    const __m256d ecmin = lanes::load(c, kEcmin), dept = lanes::load(c, kDept);
    const __m256d sigMin = lanes::load(c, kSigMin), Er = lanes::load(c, kEr);
    const __m256d ept = lanes::load(c, kEpt);
    const __m256d strain = lanes::strainsAt(strains, i, n);
    const __m256d deps = _mm256_sub_pd(strain, cStrain);
    const __m256d unchanged = _mm256_cmp_pd(_mm256_andnot_pd(signBit, deps), epsilon, _CMP_LT_OQ);
    const __m256d newMinimum =
        _mm256_andnot_pd(unchanged, _mm256_cmp_pd(strain, ecmin, _CMP_LT_OQ));
    const __m256d belowEpt = _mm256_cmp_pd(strain, ept, _CMP_LE_OQ);

    // Between the reloading line and half its slope through ept.
    const __m256d lower = _mm256_add_pd(sigMin, _mm256_mul_pd(Er, _mm256_sub_pd(strain, ecmin)));
    const __m256d halfEr = _mm256_mul_pd(half, Er);
    const __m256d upper = _mm256_mul_pd(halfEr, _mm256_sub_pd(strain, ept));
    __m256d stress = _mm256_add_pd(cStress, _mm256_mul_pd(Ec0, deps));
    __m256d tangent = Ec0;
    const __m256d atLower = _mm256_cmp_pd(stress, lower, _CMP_LE_OQ);
    stress = pick(atLower, lower, stress);
    tangent = pick(atLower, Er, tangent);
    const __m256d atUpper = _mm256_cmp_pd(stress, upper, _CMP_GE_OQ);
    stress = pick(atUpper, upper, stress);
    tangent = pick(atUpper, halfEr, tangent);

    // Tension: along the line to the largest tensile strain reached, then the envelope.
    if (!lanes::all(belowEpt)) {
      const __m256d strainFromEpt = _mm256_sub_pd(strain, ept);
      const __m256d reloading = _mm256_cmp_pd(strain, _mm256_add_pd(ept, dept), _CMP_LE_OQ);
      __m256d tensionStress, tensionTangent;
      tensionLanes.at(strainFromEpt, tensionStress, tensionTangent);
      if (any(_mm256_andnot_pd(belowEpt, reloading))) {
        __m256d peakStress, ignored;
        tensionLanes.at(dept, peakStress, ignored);
        const __m256d secant =
            pick(_mm256_cmp_pd(dept, zero, _CMP_NEQ_UQ), _mm256_div_pd(peakStress, dept), Ec0);
        tensionStress = pick(reloading, _mm256_mul_pd(secant, strainFromEpt), tensionStress);
        tensionTangent = pick(reloading, secant, tensionTangent);
      }
      stress = pick(belowEpt, stress, tensionStress);
      tangent = pick(belowEpt, tangent, tensionTangent);
    }

    // A new most compressive strain: the compression envelope.
    if (any(newMinimum)) {
      const __m256d ratio = _mm256_div_pd(strain, epsc0);
      const __m256d parabola = _mm256_cmp_pd(strain, epsc0, _CMP_GE_OQ);
      const __m256d descending = _mm256_cmp_pd(strain, epsU, _CMP_GT_OQ);
      const __m256d parabolaStress =
          _mm256_mul_pd(_mm256_mul_pd(fpc, ratio), _mm256_sub_pd(two, ratio));
      const __m256d parabolaTangent = _mm256_mul_pd(Ec0, _mm256_sub_pd(one, ratio));
      const __m256d descentStress = _mm256_add_pd(
          _mm256_div_pd(_mm256_mul_pd(descent, _mm256_sub_pd(strain, epsc0)), descentSpan), fpc);
      const __m256d envelopeStress =
          pick(parabola, parabolaStress, pick(descending, descentStress, fpcu));
      const __m256d envelopeTangent =
          pick(parabola, parabolaTangent, pick(descending, descentSlope, residualTangent));
      stress = pick(newMinimum, envelopeStress, stress);
      tangent = pick(newMinimum, envelopeTangent, tangent);
    }
    if (any(unchanged)) {
      stress = pick(unchanged, cStress, stress);
      tangent = pick(unchanged, lanes::load(c, kTangent), tangent);
    }
    lanes::store(out, i, n, stress, tangent);
  }
}

// commitTrial, lane by lane, with its operations in its order: a new most compressive strain
// (setMinimumStrain's reloading slope and zero-stress strain), else a crack opened further, then
// the trial's strain, stress and tangent, in every lane whose strain moved; a lane that did not
// move, or lies past the last fiber, keeps its fields. A row is stored only where one of its lanes
// changes.
__attribute__((target("avx"))) void Concrete02::commitFourAtOnce(StateFours<State>* states,
                                                                 const FiberStrains& strains,
                                                                 const Responses& trial,
                                                                 std::size_t n) const {
  const __m256d sigR = _mm256_set1_pd(sigR_), epsR = _mm256_set1_pd(epsR_);
  for (std::size_t i = 0; i < n; i += 4) {
    StateFours<State>& s = states[i / 4];
    const __m256d strain = lanes::load(s, kStrain);
    const __m256d newStrain = lanes::strainsAt(strains, i, n);
    const __m256d moved = lanes::movedLanes(strain, newStrain, i, n);
    if (!lanes::any(moved)) continue;
    const __m256d newStress = lanes::loadFibers(trial.stress, i, n);
    const __m256d ecmin = lanes::load(s, kEcmin), ept = lanes::load(s, kEpt);
    const __m256d dept = lanes::load(s, kDept);
    const __m256d newMinimum = _mm256_and_pd(moved, _mm256_cmp_pd(newStrain, ecmin, _CMP_LT_OQ));
    const __m256d crackOpens = _mm256_andnot_pd(
        newMinimum,
        _mm256_and_pd(
            moved, _mm256_and_pd(_mm256_cmp_pd(newStrain, ept, _CMP_NLE_UQ),
                                 _mm256_cmp_pd(newStrain, _mm256_add_pd(ept, dept), _CMP_NLE_UQ))));
    if (lanes::any(crackOpens))
      lanes::store(s, kDept, lanes::pick(crackOpens, _mm256_sub_pd(newStrain, ept), dept));
    if (lanes::any(newMinimum)) {
      const __m256d newEr =
          _mm256_div_pd(_mm256_sub_pd(newStress, sigR), _mm256_sub_pd(newStrain, epsR));
      const __m256d newEpt = _mm256_sub_pd(newStrain, _mm256_div_pd(newStress, newEr));
      lanes::store(s, kEcmin, lanes::pick(newMinimum, newStrain, ecmin));
      lanes::store(s, kSigMin, lanes::pick(newMinimum, newStress, lanes::load(s, kSigMin)));
      lanes::store(s, kEr, lanes::pick(newMinimum, newEr, lanes::load(s, kEr)));
      lanes::store(s, kEpt, lanes::pick(newMinimum, newEpt, ept));
    }
    lanes::takeTrial(s, moved, newStrain, trial, i, n, kStrain, kStress, kTangent);
  }
}

#else

void Concrete02::commitFourAtOnce(StateFours<State>*, const FiberStrains&, const Responses&,
                                  std::size_t) const {}
void Concrete02::computeFourAtOnce(const StateFours<State>*, const FiberStrains&, const Responses&,
                                   std::size_t) const {}

#endif

}  // namespace dabs::materials
