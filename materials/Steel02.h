// SPDX-License-Identifier: MIT
#pragma once

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "materials/FourLanes.h"
#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

namespace steel02 {
/// Below this value of |eps*|^R the binomial series replaces pow(1 + t, 1/R).
inline constexpr double kSeriesLimit = 1e-4;
/// Above this value of |eps*|^R, |eps*| times the series in its reciprocal replaces it.
inline constexpr double kFarSeriesFrom = 1e4;

/// (1 + x)^a by its binomial series to x^3, 1 + a x (1 + (a - 1) x (0.5 + (a - 2) x / 6)): for
/// x < 1e-4 and 0 < a <= 1 the next term is below 1e-17. The sixth as a product (the x^3 term,
/// itself below 1e-12 of the sum, changes by an ulp at most): a division less in the chain of
/// every update on a curve (the RC frame benchmark 0.7 % faster).
inline double binomialSeries(double a, double x) {
  return 1.0 + a * x * (1.0 + (a - 1.0) * x * (0.5 + (a - 2.0) * x * (1.0 / 6.0)));
}

/// The two powers of the curve: |eps*|^R as e^(R log x) (x > 0), and the root (1 + t)^(1/R) as
/// pow(base, a). By the C library's exp, log and pow one value at a time:
struct LibmPowers {
  static double power(double x, double R) { return std::exp(R * std::log(x)); }
  static double root(double base, double a) { return std::pow(base, a); }
};
/// By the functions Steel02::computeTrials takes four fibers at a time: glibc's vector math
/// library (libmvec: its four-lane exp, log and pow, the variant for AVX2 and FMA where the
/// processor has them) where the build has it and the processor AVX, with the value in lane 0
/// (a lane's result depends on its own inputs alone); LibmPowers elsewhere. The two differ in the
/// last bits (within an ulp or two of the exact values each, which R |log x| may grow to a few
/// tens of ulps of t).
struct LanePowers {
  static double power(double x, double R);
  static double root(double base, double a);
  /// Whether the build takes them from libmvec (else they are LibmPowers').
  static bool fromLibmvec();
};

/// The linear limit of a branch of curvature R (Steel02State::linearLimit): 2^(q/4) with
/// q = floor(-4 (38/R) log2 e), a lower bound of e^(-38/R) within a factor 2^(1/4) of it, from
/// the bits of 2^floor(q/4) and a power 2^(j/4), j = 0..3: a division and a few operations
/// where it was an exp per reversal (the pushover benchmark 2 % faster). Only where the
/// initial line is taken depends on it, never a number: between it and e^(-36.74/R), |eps*|^R is
/// below half an ulp of 1 and the curve's own operations give the line's bits. 0 for R < 1.
inline double linearLimit(double R) {
  if (!(R >= 1.0)) return 0.0;
  constexpr double kQuarterPowers[4] = {1.0, 1.1892071150027210667, 1.4142135623730950488,
                                        1.6817928305074290861};
  constexpr double kQuarterSteps = -4.0 * 38.0 * 1.4426950408889634074;  // -4 * 38 log2 e
  const double q = std::floor(kQuarterSteps / R);                        // -220 .. -1 (R >= 1)
  const double whole = std::floor(q * 0.25);
  const auto j = static_cast<std::size_t>(q - 4.0 * whole);
  const auto bits = static_cast<std::uint64_t>(static_cast<std::int64_t>(whole) + 1023) << 52;
  return kQuarterPowers[j] * std::bit_cast<double>(bits);
}
}  // namespace steel02

/// History of Steel02 (strains are the material's own, including the initial strain sigInit/E).
/// The fields an update on the current branch reads come first, on the four cache lines of a
/// StateFours that a pass reads; the rest (the stress and tangent, which a commit writes, and
/// the extremes, which only a reversal reads) on the three lines after them.
struct Steel02State {
  double strain = 0.0;   ///< strain as given to setTrialStrain
  double epsR = 0.0;     ///< strain at the last reversal
  double invSpan = 0.0;  ///< 1 / (eps0 - epsR), the strain normaliser of the branch
  /// Below this |eps*| the branch is its initial line to round-off: |eps*|^R < e^-38 (below half
  /// an ulp of 1), so 1 + |eps*|^R and its power 1/R are exactly 1 (steel02::linearLimit).
  double linearLimit = 0.0;
  double sig0 = 0.0;  ///< stress where the asymptotes meet (at eps0)
  double sigR = 0.0;  ///< stress at the last reversal
  double R = 0.0;     ///< curvature of the current branch (a function of epsPl and eps0)
  /// 0 virgin, 1 loading (towards tension), 2 towards compression, 3 virgin at sigInit (a double,
  /// so that the state is all doubles)
  double kon = 0.0;
  double stress = 0.0;   ///< stress
  double tangent = 0.0;  ///< d(stress)/d(strain)
  double epsMin = 0.0;   ///< most negative reversal strain (starts at -epsy)
  double epsMax = 0.0;   ///< most positive reversal strain (starts at +epsy)
  double epsPl = 0.0;    ///< previous extreme strain in the opposite direction (sets xi)
  double eps0 = 0.0;     ///< strain where the elastic and hardening asymptotes meet
};

/// Menegotto-Pinto steel with Filippou isotropic hardening (Menegotto & Pinto 1973; Filippou,
/// Popov & Bertero 1983, EERC 83/19, eqs. 3-5):
///   sig* = b*eps* + (1-b)*eps*/(1+|eps*|^R)^(1/R),  eps* = (eps-epsR)/(eps0-epsR),
///   sig* = (sig-sigR)/(sig0-sigR),  R = R0*(1 - cR1*xi/(cR2+xi)).
/// OpenSees: `uniaxialMaterial Steel02 tag Fy E b ?R0 cR1 cR2? ?a1 a2 a3 a4? ?sigInit?`, defaults
/// R0=15 cR1=0.925 cR2=0.15 a1=0 a2=1 a3=0 a4=1 sigInit=0
/// (OpenSees/OpenSees:SRC/material/uniaxial/Steel02.cpp).
class Steel02 final : public StatefulUniaxial<Steel02, Steel02State> {
 public:
  using State = Steel02State;

  struct Params {
    double Fy = 0.0;       ///< yield stress, > 0
    double E = 0.0;        ///< initial modulus, > 0
    double b = 0.0;        ///< strain-hardening ratio, in [0, 1)
    double R0 = 15.0;      ///< initial transition curvature, > 0
    double cR1 = 0.925;    ///< curvature degradation, in [0, 1)
    double cR2 = 0.15;     ///< curvature degradation, > 0
    double a1 = 0.0;       ///< compressive isotropic hardening, >= 0
    double a2 = 1.0;       ///< normalising strain for a1 (units of epsy), > 0
    double a3 = 0.0;       ///< tensile isotropic hardening, >= 0
    double a4 = 1.0;       ///< normalising strain for a3 (units of epsy), > 0
    double sigInit = 0.0;  ///< initial stress (strain offset sigInit/E), |sigInit| < Fy
    /// Throws InputError naming the offending parameter.
    void validate() const;
  };

  Steel02(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  /// The update as a function of the committed state: trial = the state at `strain`. Fiber
  /// sections keep only the states of their fibers and call this with one parameter set.
  [[nodiscard]] Status computeTrial(const State& committed, State& trial, double strain) const {
    return computeTrialWith<steel02::LibmPowers>(committed, trial, strain);
  }
  /// computeTrial with the curve's powers from `Powers` (steel02::LibmPowers or LanePowers).
  template <class Powers>
  [[nodiscard]] Status computeTrialWith(const State& committed, State& trial, double strain) const;
  /// Turns `state` into the state computeTrial(state, trial, strain) leaves, given that state's
  /// stress and tangent: the branch bookkeeping alone, bit for bit the same. A fiber section
  /// keeps only its fibers' trial stress and tangent, and commits with this.
  void commitTrial(State& state, double strain, double stress, double tangent) const;
  /// The updates of n fibers: out.stress[i] and out.tangent[i] are the trial stress and tangent at
  /// strains[i] from fiber i of `committed`, bit for bit those of
  /// computeTrialWith<steel02::LanePowers> where the processor has AVX and n >= 4 (the fibers on
  /// a branch four at a time, their powers by libmvec's four-lane functions: the pushover
  /// benchmark 7 % faster; a fiber on its first excursion, or reversing where a1 or a3 shifts the
  /// asymptote, on its own), else those of computeTrial. (Fewer than four, a plane section's bars
  /// at two heights, go one at a time with the C library's powers: their results wait on each
  /// power, and glibc's one-value functions answer sooner; through the four-lane ones the RC
  /// frame benchmark took 4 % longer, and through the four-lane code with the C library's powers
  /// 4 % longer too.)
  void computeTrials(const StateFours<State>* committed, const FiberStrains& strains,
                     const Responses& out, std::size_t n) const;
  /// commitTrial of n fibers: fiber i of `states` committed at strains[i] with trial.stress[i]
  /// and trial.tangent[i], bit for bit. Where the processor has AVX, four fibers at a time that
  /// stay on their branches store only their strain, stress and tangent rows (two cache lines of
  /// the four's seven); a fiber that reverses or leaves its virgin point goes one at a time.
  void commitTrials(StateFours<State>* states, const FiberStrains& strains, const Responses& trial,
                    std::size_t n) const;
  /// Whether computeTrials takes four fibers at a time on this processor.
  static bool updatesFourAtOnce() { return lanes::available(); }
  /// The virgin state.
  State virginState() const { return initialState(); }
  double getInitialTangent() const override { return params_.E; }
  /// At the committed strain no branch reverses and the curve is the committed one's.
  bool keepsStateAtSameStrain() const override { return true; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  /// R = R0 (1 - cR1 xi / (cR2 + xi)) and 1 / (eps0 - epsR) for the branch of `s`.
  void setCurvature(State& s) const;
  /// Puts `s` (the committed state with the trial strain) on the branch a shifted strain
  /// increment `deps` from the committed point (epsP, sigP) follows: the first excursion or a
  /// reversal. False when the material stays at its virgin point (s then has its stress and
  /// tangent).
  bool followBranch(State& s, double epsP, double sigP, double deps) const;
  /// computeTrials of n >= 4 fibers four at a time (AVX), the last one to three in their own four.
  void computeFourAtOnce(const StateFours<State>* committed, const FiberStrains& strains,
                         const Responses& out, std::size_t n) const;
  /// commitTrials four at a time (AVX), the last one to three in their own four.
  void commitFourAtOnce(StateFours<State>* states, const FiberStrains& strains,
                        const Responses& trial, std::size_t n) const;
  Params params_;
  double epsy_ = 0.0;    ///< Fy / E
  double Esh_ = 0.0;     ///< b E
  double epsIni_ = 0.0;  ///< sigInit / E
};

// The update is defined here, inline, so that a fiber section's loop over its Steel02 fibers can
// inline it.

inline void Steel02::setCurvature(State& s) const {
  const auto& p = params_;
  const double xi = std::fabs((s.epsPl - s.eps0) / epsy_);
  s.R = p.R0 * (1.0 - (p.cR1 * xi) / (p.cR2 + xi));
  // The limit costs a few operations per reversal and saves an exp and a log per update on
  // every fiber still near the start of its branch (most bars of a structure that stays elastic).
  s.linearLimit = steel02::linearLimit(s.R);
  s.invSpan = 1.0 / (s.eps0 - s.epsR);
}

inline bool Steel02::followBranch(State& trial, double epsP, double sigP, double deps) const {
  const auto& p = params_;
  const double Esh = Esh_;
  const double epsy = epsy_;
  if (trial.kon == 0 || trial.kon == 3) {
    if (std::fabs(deps) < 10.0 * DBL_EPSILON) {
      trial.tangent = p.E;
      trial.stress = p.sigInit;
      trial.kon = 3;
      return false;
    }
    // first excursion: asymptotes meet at (+-epsy, +-Fy); the curve starts at the origin
    trial.epsMax = epsy;
    trial.epsMin = -epsy;
    if (deps < 0.0) {
      trial.kon = 2;
      trial.eps0 = -epsy;
      trial.sig0 = -p.Fy;
      trial.epsPl = -epsy;
    } else {
      trial.kon = 1;
      trial.eps0 = epsy;
      trial.sig0 = p.Fy;
      trial.epsPl = epsy;
    }
    setCurvature(trial);
  }

  if (trial.kon == 2 && deps > 0.0) {
    // reversal towards tension: new origin at the last committed point; the hardening
    // asymptote is shifted by the isotropic term a3*((epsmax-epsmin)/(2*a4*epsy))^0.8
    trial.kon = 1;
    trial.epsR = epsP;
    trial.sigR = sigP;
    if (epsP < trial.epsMin) trial.epsMin = epsP;
    const double d1 = (trial.epsMax - trial.epsMin) / (2.0 * p.a4 * epsy);
    const double shift = p.a3 == 0.0 ? 1.0 : 1.0 + p.a3 * std::pow(d1, 0.8);
    // intersection of sig = sigR + E*(eps-epsR) with sig = Fy*shift + Esh*(eps - epsy*shift)
    trial.eps0 = (p.Fy * shift - Esh * epsy * shift - trial.sigR + p.E * trial.epsR) / (p.E - Esh);
    trial.sig0 = p.Fy * shift + Esh * (trial.eps0 - epsy * shift);
    trial.epsPl = trial.epsMax;
    setCurvature(trial);
  } else if (trial.kon == 1 && deps < 0.0) {
    // reversal towards compression, mirrored (a1, a2)
    trial.kon = 2;
    trial.epsR = epsP;
    trial.sigR = sigP;
    if (epsP > trial.epsMax) trial.epsMax = epsP;
    const double d1 = (trial.epsMax - trial.epsMin) / (2.0 * p.a2 * epsy);
    const double shift = p.a1 == 0.0 ? 1.0 : 1.0 + p.a1 * std::pow(d1, 0.8);
    trial.eps0 = (-p.Fy * shift + Esh * epsy * shift - trial.sigR + p.E * trial.epsR) / (p.E - Esh);
    trial.sig0 = -p.Fy * shift + Esh * (trial.eps0 + epsy * shift);
    trial.epsPl = trial.epsMin;
    setCurvature(trial);
  }

  return true;
}

template <class Powers>
inline Status Steel02::computeTrialWith(const State& committed, State& trial, double strain) const {
  const auto& p = params_;
  // The curve works in strains shifted by the initial strain sigInit/E (C.-P. Lamarche's
  // extension in OpenSees), so the virgin state sits at (sigInit/E, sigInit).
  const double epsIni = epsIni_;
  const double eps = strain + epsIni;
  const double epsP = committed.strain + epsIni;  // committed shifted strain
  const double sigP = committed.stress;
  const double deps = eps - epsP;

  trial = committed;
  trial.strain = strain;
  if (!followBranch(trial, epsP, sigP, deps)) return Status::Ok;

  // Menegotto-Pinto curve (Filippou et al. 1983, eqs. 3-5) and its exact derivative.
  const double epsRat = (eps - trial.epsR) * trial.invSpan;
  // |eps*|^R as exp(R log|eps*|) (Powers::power): half the cost of pow, with a relative error
  // of about R |log eps*| times round-off (1e-14 here), far below anything a step resolves.
  const double absRat = std::fabs(epsRat);
  if (absRat < trial.linearLimit) {
    // 1 + t and (1 + t)^(1/R) below are exactly 1 here: the same numbers without exp and log.
    trial.stress = (p.b * epsRat + (1.0 - p.b) * epsRat) * (trial.sig0 - trial.sigR) + trial.sigR;
    trial.tangent = (p.b + (1.0 - p.b)) * (trial.sig0 - trial.sigR) * trial.invSpan;
    return std::isfinite(trial.stress) && std::isfinite(trial.tangent) ? Status::Ok
                                                                       : Status::NonFinite;
  }
  const double t = absRat > 0.0 ? Powers::power(absRat, trial.R) : 0.0;
  const double dum1 = 1.0 + t;
  // (1 + t)^(1/R): near the elastic branch t is small and the binomial series to t^3 equals the
  // power to round-off (the next term is below 1e-17 for t < 1e-4 and R >= 1), at a fraction of
  // the cost of a second pow. Far along the branch (t > 1e4: |eps*| beyond 1e4^(1/R), 1.67 at
  // R = 18) it is |eps*| (1 + 1/t)^(1/R), the same series in 1/t; of the pushover benchmark's bar
  // updates that took the power, three in four are there.
  const double a = 1.0 / trial.R;
  double dum2;
  if (t < steel02::kSeriesLimit && trial.R >= 1.0) {
    dum2 = steel02::binomialSeries(a, t);
  } else if (t > steel02::kFarSeriesFrom && trial.R >= 1.0) {
    dum2 = absRat * steel02::binomialSeries(a, 1.0 / t);
  } else {
    dum2 = Powers::root(dum1, a);
  }
  const double sigStar = p.b * epsRat + (1.0 - p.b) * epsRat / dum2;
  trial.stress = sigStar * (trial.sig0 - trial.sigR) + trial.sigR;
  const double eStar = p.b + (1.0 - p.b) / (dum1 * dum2);
  trial.tangent = eStar * (trial.sig0 - trial.sigR) * trial.invSpan;
  return std::isfinite(trial.stress) && std::isfinite(trial.tangent) ? Status::Ok
                                                                     : Status::NonFinite;
}

inline void Steel02::commitTrial(State& state, double strain, double stress, double tangent) const {
  const double epsP = state.strain + epsIni_;
  const double deps = strain + epsIni_ - epsP;
  const double sigP = state.stress;
  state.strain = strain;
  static_cast<void>(followBranch(state, epsP, sigP, deps));
  state.stress = stress;
  state.tangent = tangent;
}

inline Status Steel02::setTrialStrain(double strain, double /*strainRate*/) {
  return computeTrial(committed_, trial_, strain);
}

}  // namespace dabs::materials
