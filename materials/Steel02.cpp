// SPDX-License-Identifier: MIT
#include "materials/Steel02.h"

#include <cassert>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "materials/FourLanes.h"
#include "materials/InputError.h"

namespace dabs::materials {

#if defined(DABS_FOUR_LANES) && defined(DABS_HAVE_LIBMVEC)
// glibc's vector math library (libmvec, the x86-64 vector ABI: four doubles in a ymm register;
// its variant for AVX2 and FMA where the processor has them, else one built on SSE).
extern "C" {
__attribute__((target("avx"))) __m256d _ZGVdN4v_exp(__m256d x);
__attribute__((target("avx"))) __m256d _ZGVdN4v_log(__m256d x);
__attribute__((target("avx"))) __m256d _ZGVdN4vv_pow(__m256d x, __m256d y);
}

namespace {
/// e^(R log x) in every lane where x > 0 and `where`, else 0.
__attribute__((target("avx"))) __m256d powersOf(__m256d x, __m256d R, __m256d where) {
  const __m256d positive = _mm256_and_pd(where, _mm256_cmp_pd(x, _mm256_setzero_pd(), _CMP_GT_OQ));
  const __m256d logs = _ZGVdN4v_log(lanes::pick(positive, x, _mm256_set1_pd(1.0)));
  return _mm256_and_pd(positive, _ZGVdN4v_exp(_mm256_mul_pd(R, logs)));
}
__attribute__((target("avx"))) double powerInLanes(double x, double R) {
  return _mm256_cvtsd_f64(
      _ZGVdN4v_exp(_mm256_mul_pd(_mm256_set1_pd(R), _ZGVdN4v_log(_mm256_set1_pd(x)))));
}
__attribute__((target("avx"))) double rootInLanes(double base, double a) {
  return _mm256_cvtsd_f64(_ZGVdN4vv_pow(_mm256_set1_pd(base), _mm256_set1_pd(a)));
}
}  // namespace

double steel02::LanePowers::power(double x, double R) {
  return lanes::available() ? powerInLanes(x, R) : LibmPowers::power(x, R);
}
double steel02::LanePowers::root(double base, double a) {
  return lanes::available() ? rootInLanes(base, a) : LibmPowers::root(base, a);
}
bool steel02::LanePowers::fromLibmvec() { return true; }
#else
double steel02::LanePowers::power(double x, double R) { return LibmPowers::power(x, R); }
double steel02::LanePowers::root(double base, double a) { return LibmPowers::root(base, a); }
bool steel02::LanePowers::fromLibmvec() { return false; }
#endif

void Steel02::Params::validate() const {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0) throw InputError(name, "must be positive");
  };
  auto nonNegative = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0) throw InputError(name, "must be >= 0");
  };
  positive(Fy, "Fy");
  positive(E, "E");
  if (!std::isfinite(b) || b < 0.0 || b >= 1.0) throw InputError("b", "must be in [0, 1)");
  positive(R0, "R0");
  if (!std::isfinite(cR1) || cR1 < 0.0 || cR1 >= 1.0) throw InputError("cR1", "must be in [0, 1)");
  positive(cR2, "cR2");
  nonNegative(a1, "a1");
  positive(a2, "a2");
  nonNegative(a3, "a3");
  positive(a4, "a4");
  if (!std::isfinite(sigInit) || std::fabs(sigInit) >= Fy)
    throw InputError("sigInit", "must be smaller than Fy in magnitude");
}

Steel02::Steel02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.Fy > 0.0 && params.E > 0.0 && params.b < 1.0);
  epsy_ = params.Fy / params.E;
  Esh_ = params.b * params.E;
  epsIni_ = params.sigInit / params.E;
  revertToStart();
}

Steel02::State Steel02::initialState() const {
  State s;
  s.stress = params_.sigInit;
  s.tangent = params_.E;
  s.epsMax = params_.Fy / params_.E;
  s.epsMin = -s.epsMax;
  return s;
}

// Flattened: the update one at a time inlined whole (its branch tests among them), as it was
// where it had one caller; left to the compiler it kept followBranch a call of its own, a fifth
// more instructions in the RC frame benchmark's bar updates.
[[gnu::flatten]] void Steel02::computeTrials(const StateFours<State>* committed,
                                             const FiberStrains& strains, const Responses& out,
                                             std::size_t n) const {
  if (n < 4)
    lanes::computeOneByOne(*this, committed, strains, out, 0, n);
  else
    lanes::computeInFours(*this, &Steel02::computeFourAtOnce, committed, strains, out, n);
}

void Steel02::commitTrials(StateFours<State>* states, const FiberStrains& strains,
                           const Responses& trial, std::size_t n) const {
  lanes::commitInFours(*this, &Steel02::commitFourAtOnce, states, strains, trial, n);
}

#ifdef DABS_FOUR_LANES

namespace {

using lanes::any;
using lanes::pick;

// Rows of a StateFours<Steel02State>.
constexpr std::size_t kStrain = offsetof(Steel02State, strain) / sizeof(double);
constexpr std::size_t kEpsR = offsetof(Steel02State, epsR) / sizeof(double);
constexpr std::size_t kInvSpan = offsetof(Steel02State, invSpan) / sizeof(double);
constexpr std::size_t kLinearLimit = offsetof(Steel02State, linearLimit) / sizeof(double);
constexpr std::size_t kSig0 = offsetof(Steel02State, sig0) / sizeof(double);
constexpr std::size_t kSigR = offsetof(Steel02State, sigR) / sizeof(double);
constexpr std::size_t kR = offsetof(Steel02State, R) / sizeof(double);
constexpr std::size_t kKon = offsetof(Steel02State, kon) / sizeof(double);
constexpr std::size_t kStress = offsetof(Steel02State, stress) / sizeof(double);
constexpr std::size_t kTangent = offsetof(Steel02State, tangent) / sizeof(double);
constexpr std::size_t kEpsMin = offsetof(Steel02State, epsMin) / sizeof(double);
constexpr std::size_t kEpsMax = offsetof(Steel02State, epsMax) / sizeof(double);
static_assert(std::is_standard_layout_v<Steel02State> && sizeof(Steel02State) == 112);
// An update on the branch reads rows 0 to 7 (the first four cache lines of a four) alone.
static_assert(kStrain < 8 && kEpsR < 8 && kInvSpan < 8 && kLinearLimit < 8 && kSig0 < 8 &&
              kSigR < 8 && kR < 8 && kKon < 8);
// A commit on the branch writes the strain and the stress and tangent, which share a line.
static_assert(kStress / 2 == kTangent / 2);

/// The lanes whose fiber stays on its branch (followBranch changes nothing): kon 1 (loading) and
/// an increment deps not below zero, or kon 2 and one not above (a NaN increment stays).
__attribute__((target("avx"))) inline __m256d onTheirBranch(__m256d kon, __m256d deps) {
  const __m256d zero = _mm256_setzero_pd();
  return _mm256_or_pd(_mm256_and_pd(_mm256_cmp_pd(kon, _mm256_set1_pd(1.0), _CMP_EQ_OQ),
                                    _mm256_cmp_pd(deps, zero, _CMP_NLT_UQ)),
                      _mm256_and_pd(_mm256_cmp_pd(kon, _mm256_set1_pd(2.0), _CMP_EQ_OQ),
                                    _mm256_cmp_pd(deps, zero, _CMP_NGT_UQ)));
}

/// steel02::binomialSeries of four lanes, its operations in its order.
__attribute__((target("avx"))) inline __m256d binomialSeries(__m256d a, __m256d x) {
  const __m256d one = _mm256_set1_pd(1.0), two = _mm256_set1_pd(2.0);
  const __m256d inner = _mm256_add_pd(
      _mm256_set1_pd(0.5),
      _mm256_mul_pd(_mm256_mul_pd(_mm256_sub_pd(a, two), x), _mm256_set1_pd(1.0 / 6.0)));
  const __m256d middle =
      _mm256_add_pd(one, _mm256_mul_pd(_mm256_mul_pd(_mm256_sub_pd(a, one), x), inner));
  return _mm256_add_pd(one, _mm256_mul_pd(_mm256_mul_pd(a, x), middle));
}

}  // namespace

// computeTrialWith<steel02::LanePowers>, lane by lane, for fibers on a branch (kon 1 or 2): the
// new branch of a reversal without isotropic shift, the initial line, the binomial series and the
// quotients with the scalar code's operations in its order, so the same bits; |eps*|^R and the
// power 1/R by libmvec's four-lane functions (LanePowers' own; without libmvec its calls one lane
// at a time), and a new branch's linear limit by steel02::linearLimit one lane at a time, where a
// lane needs them. A fiber on its first excursion, or reversing with a shift, takes
// computeTrialWith<steel02::LanePowers> itself.
__attribute__((target("avx"))) void Steel02::computeFourAtOnce(const StateFours<State>* committed,
                                                               const FiberStrains& strains,
                                                               const Responses& out,
                                                               std::size_t n) const {
  const auto& p = params_;
  const __m256d b = _mm256_set1_pd(p.b), rest = _mm256_set1_pd(1.0 - p.b);
  const __m256d lineSlope = _mm256_set1_pd(p.b + (1.0 - p.b));
  const __m256d epsIni = _mm256_set1_pd(epsIni_);
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const __m256d signBit = _mm256_set1_pd(-0.0);
  const __m256d loading = _mm256_set1_pd(1.0), unloading = _mm256_set1_pd(2.0);
  const __m256d seriesLimit = _mm256_set1_pd(steel02::kSeriesLimit);
  const __m256d farSeriesFrom = _mm256_set1_pd(steel02::kFarSeriesFrom);
  // A reversal's new branch (followBranch) where its asymptote has no isotropic shift (a3 = 0
  // towards tension, a1 = 0 towards compression): the shift is then 1, and x * 1 is x, so these
  // constants, written without it, are followBranch's partial results to the bit.
  const __m256d tensionShiftless = _mm256_castsi256_pd(_mm256_set1_epi64x(p.a3 == 0.0 ? -1 : 0));
  const __m256d compressionShiftless =
      _mm256_castsi256_pd(_mm256_set1_epi64x(p.a1 == 0.0 ? -1 : 0));
  const bool anyShiftless = p.a1 == 0.0 || p.a3 == 0.0;
  const __m256d tensionStart = _mm256_set1_pd(p.Fy - Esh_ * epsy_);
  const __m256d compressionStart = _mm256_set1_pd(-p.Fy + Esh_ * epsy_);
  const __m256d hardeningGap = _mm256_set1_pd(p.E - Esh_);
  const __m256d E = _mm256_set1_pd(p.E), Esh = _mm256_set1_pd(Esh_);
  const __m256d Fy = _mm256_set1_pd(p.Fy), minusFy = _mm256_set1_pd(-p.Fy);
  const __m256d epsy = _mm256_set1_pd(epsy_);
  const __m256d R0 = _mm256_set1_pd(p.R0), cR1 = _mm256_set1_pd(p.cR1), cR2 = _mm256_set1_pd(p.cR2);

  for (std::size_t i = 0; i < n; i += 4) {
    const StateFours<State>& c = committed[i / 4];
    const __m256d cStrain = lanes::load(c, kStrain);
    __m256d epsR = lanes::load(c, kEpsR), invSpan = lanes::load(c, kInvSpan);
    __m256d linearLimit = lanes::load(c, kLinearLimit), sig0 = lanes::load(c, kSig0);
    __m256d sigR = lanes::load(c, kSigR), R = lanes::load(c, kR);
    const __m256d kon = lanes::load(c, kKon);
    const __m256d strain = lanes::strainsAt(strains, i, n);

    // computeTrial's shifted strains and the increment that decides a reversal.
    const __m256d eps = _mm256_add_pd(strain, epsIni);
    const __m256d epsP = _mm256_add_pd(cStrain, epsIni);
    const __m256d deps = _mm256_sub_pd(eps, epsP);
    const __m256d isLoading = _mm256_cmp_pd(kon, loading, _CMP_EQ_OQ);
    const __m256d isUnloading = _mm256_cmp_pd(kon, unloading, _CMP_EQ_OQ);
    const __m256d steady = onTheirBranch(kon, deps);
    __m256d updated = steady;
    if (anyShiftless && !lanes::all(steady)) {
      // Reversals: the new origin is the committed point, the asymptotes meet where the elastic
      // line from it crosses the hardening line, and R follows from the plastic excursion
      // (followBranch, setCurvature).
      const __m256d toTension = _mm256_and_pd(
          tensionShiftless, _mm256_and_pd(isUnloading, _mm256_cmp_pd(deps, zero, _CMP_GT_OQ)));
      const __m256d toCompression = _mm256_and_pd(
          compressionShiftless, _mm256_and_pd(isLoading, _mm256_cmp_pd(deps, zero, _CMP_LT_OQ)));
      const __m256d reversing = _mm256_or_pd(toTension, toCompression);
      if (any(reversing)) {
        const __m256d cStress = lanes::load(c, kStress);
        const __m256d epsMin = lanes::load(c, kEpsMin), epsMax = lanes::load(c, kEpsMax);
        // epsMin and epsMax move only into the shift, which is 1 here; epsPl is the extreme
        // reached in the other direction, before this reversal.
        const __m256d newEps0 = _mm256_div_pd(
            _mm256_add_pd(_mm256_sub_pd(pick(toTension, tensionStart, compressionStart), cStress),
                          _mm256_mul_pd(E, epsP)),
            hardeningGap);
        const __m256d newSig0 = _mm256_add_pd(
            pick(toTension, Fy, minusFy),
            _mm256_mul_pd(
                Esh, pick(toTension, _mm256_sub_pd(newEps0, epsy), _mm256_add_pd(newEps0, epsy))));
        const __m256d newEpsPl = pick(toTension, epsMax, epsMin);
        const __m256d xi =
            _mm256_andnot_pd(signBit, _mm256_div_pd(_mm256_sub_pd(newEpsPl, newEps0), epsy));
        const __m256d newR = _mm256_mul_pd(
            R0, _mm256_sub_pd(one, _mm256_div_pd(_mm256_mul_pd(cR1, xi), _mm256_add_pd(cR2, xi))));
        alignas(32) double curvature[4], limit[4];
        _mm256_store_pd(curvature, newR);
        const int reversingLanes = _mm256_movemask_pd(reversing);
        for (int l = 0; l < 4; ++l)
          limit[l] = reversingLanes >> l & 1 ? steel02::linearLimit(curvature[l]) : 0.0;
        const __m256d newInvSpan = _mm256_div_pd(one, _mm256_sub_pd(newEps0, epsP));
        epsR = pick(reversing, epsP, epsR);
        sigR = pick(reversing, cStress, sigR);
        sig0 = pick(reversing, newSig0, sig0);
        R = pick(reversing, newR, R);
        linearLimit = pick(reversing, _mm256_load_pd(limit), linearLimit);
        invSpan = pick(reversing, newInvSpan, invSpan);
        updated = _mm256_or_pd(steady, reversing);
      }
    }

    const __m256d epsRat = _mm256_mul_pd(_mm256_sub_pd(eps, epsR), invSpan);
    const __m256d absRat = _mm256_andnot_pd(signBit, epsRat);
    const __m256d span = _mm256_sub_pd(sig0, sigR);
    // The initial line (absRat below the limit).
    __m256d stress = _mm256_add_pd(
        _mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(b, epsRat), _mm256_mul_pd(rest, epsRat)), span),
        sigR);
    __m256d tangent = _mm256_mul_pd(_mm256_mul_pd(lineSlope, span), invSpan);
    const __m256d curve = _mm256_andnot_pd(_mm256_cmp_pd(absRat, linearLimit, _CMP_LT_OQ), updated);
    const int curveLanes = _mm256_movemask_pd(curve);
    if (curveLanes != 0) {
#ifdef DABS_HAVE_LIBMVEC
      const __m256d t = powersOf(absRat, R, curve);
#else
      alignas(32) double ratio[4], curvature[4], power[4];
      _mm256_store_pd(ratio, absRat);
      _mm256_store_pd(curvature, R);
      for (int l = 0; l < 4; ++l) {
        power[l] = (curveLanes >> l & 1) && ratio[l] > 0.0
                       ? steel02::LanePowers::power(ratio[l], curvature[l])
                       : 0.0;
      }
      const __m256d t = _mm256_load_pd(power);
#endif
      const __m256d dum1 = _mm256_add_pd(one, t);
      const __m256d a = _mm256_div_pd(one, R);
      const __m256d series = _mm256_and_pd(_mm256_cmp_pd(t, seriesLimit, _CMP_LT_OQ),
                                           _mm256_cmp_pd(R, one, _CMP_GE_OQ));
      __m256d dum2 = binomialSeries(a, t);
      const __m256d far = _mm256_and_pd(_mm256_cmp_pd(t, farSeriesFrom, _CMP_GT_OQ),
                                        _mm256_cmp_pd(R, one, _CMP_GE_OQ));
      if (any(_mm256_and_pd(far, curve)))
        dum2 = pick(far, _mm256_mul_pd(absRat, binomialSeries(a, _mm256_div_pd(one, t))), dum2);
      const int powerLanes = curveLanes & ~_mm256_movemask_pd(_mm256_or_pd(series, far));
      if (powerLanes != 0) {
#ifdef DABS_HAVE_LIBMVEC
        const __m256d rootLanes = _mm256_andnot_pd(_mm256_or_pd(series, far), curve);
        dum2 = lanes::pick(
            rootLanes,
            _ZGVdN4vv_pow(lanes::pick(rootLanes, dum1, one), lanes::pick(rootLanes, a, one)), dum2);
#else
        alignas(32) double base[4], exponent[4], root[4];
        _mm256_store_pd(base, dum1);
        _mm256_store_pd(exponent, a);
        _mm256_store_pd(root, dum2);
        for (int l = 0; l < 4; ++l)
          if (powerLanes >> l & 1) root[l] = steel02::LanePowers::root(base[l], exponent[l]);
        dum2 = _mm256_load_pd(root);
#endif
      }
      const __m256d sigStar =
          _mm256_add_pd(_mm256_mul_pd(b, epsRat), _mm256_div_pd(_mm256_mul_pd(rest, epsRat), dum2));
      const __m256d eStar = _mm256_add_pd(b, _mm256_div_pd(rest, _mm256_mul_pd(dum1, dum2)));
      stress = pick(curve, _mm256_add_pd(_mm256_mul_pd(sigStar, span), sigR), stress);
      tangent = pick(curve, _mm256_mul_pd(_mm256_mul_pd(eStar, span), invSpan), tangent);
    }
    lanes::store(out, i, n, stress, tangent);
    const int updatedLanes = _mm256_movemask_pd(updated);
    for (std::size_t l = 0; l < 4 && i + l < n; ++l) {
      if (updatedLanes >> l & 1) continue;
      State trial;
      static_cast<void>(computeTrialWith<steel02::LanePowers>(c.get(l), trial, strains[i + l]));
      out.set(i + l, trial.stress, trial.tangent);
    }
  }
}

// commitTrial, lane by lane: a fiber that stays on its branch (kon 1 and a strain increment not
// below zero, kon 2 and one not above: followBranch changes nothing) takes the trial's strain,
// stress and tangent; the others of its four (a reversal, a first excursion) go one at a time, and
// lanes past the last fiber are left as they are.
__attribute__((target("avx"))) void Steel02::commitFourAtOnce(StateFours<State>* states,
                                                              const FiberStrains& strains,
                                                              const Responses& trial,
                                                              std::size_t n) const {
  const __m256d epsIni = _mm256_set1_pd(epsIni_);
  for (std::size_t i = 0; i < n; i += 4) {
    StateFours<State>& s = states[i / 4];
    const __m256d cStrain = lanes::load(s, kStrain), kon = lanes::load(s, kKon);
    const __m256d below = lanes::fibersBelow(i, n);
    const __m256d newStrain = lanes::strainsAt(strains, i, n);
    // commitTrial's increment: (strain + epsIni) - (committed strain + epsIni).
    const __m256d deps =
        _mm256_sub_pd(_mm256_add_pd(newStrain, epsIni), _mm256_add_pd(cStrain, epsIni));
    const __m256d steady = _mm256_and_pd(below, onTheirBranch(kon, deps));
    lanes::takeTrial(s, steady, newStrain, trial, i, n, kStrain, kStress, kTangent);
    const int others = _mm256_movemask_pd(_mm256_andnot_pd(steady, below));
    for (std::size_t l = 0; l < 4; ++l)
      if (others >> l & 1) lanes::commitOneByOne(*this, states, strains, trial, i + l, i + l + 1);
  }
}

#else

void Steel02::computeFourAtOnce(const StateFours<State>*, const FiberStrains&, const Responses&,
                                std::size_t) const {}
void Steel02::commitFourAtOnce(StateFours<State>*, const FiberStrains&, const Responses&,
                               std::size_t) const {}

#endif

}  // namespace dabs::materials
