// SPDX-License-Identifier: MIT
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>

#include "materials/FourLanes.h"
#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Concrete01.
struct Concrete01State {
  double strain = 0.0;       ///< strain (compression negative)
  double stress = 0.0;       ///< stress (compression negative)
  double tangent = 0.0;      ///< d(stress)/d(strain)
  double minStrain = 0.0;    ///< most compressive strain reached
  double endStrain = 0.0;    ///< strain where the unloading line reaches zero stress
  double unloadSlope = 0.0;  ///< slope of the unloading/reloading line
};

/// Kent-Scott-Park concrete without tensile strength (Kent & Park 1971; Scott, Park & Priestley
/// 1982): parabola fpc*(2*eta - eta^2), eta = eps/epsc0, up to epsc0, linear descent to
/// (epsU, fpcu), then constant; unloading to zero stress at a strain given by Karsan & Jirsa
/// (1969). OpenSees: `uniaxialMaterial Concrete01 tag fpc epsc0 fpcu epsU`; as in OpenSees
/// (OpenSees/OpenSees:SRC/material/uniaxial/Concrete01.cpp) positive inputs are taken as
/// magnitudes of compressive values.
class Concrete01 final : public StatefulUniaxial<Concrete01, Concrete01State> {
 public:
  using State = Concrete01State;

  struct Params {
    double fpc = 0.0;    ///< compressive strength (negative)
    double epsc0 = 0.0;  ///< strain at fpc (negative)
    double fpcu = 0.0;   ///< crushing strength (negative or zero)
    double epsU = 0.0;   ///< strain at fpcu (negative, beyond epsc0)
    /// Throws InputError for zero fpc or epsc0, |fpcu| > |fpc|, or |epsU| <= |epsc0|.
    void validate() const;
    /// The same values with every sign made negative (compression), as OpenSees does.
    Params normalized() const;
  };

  Concrete01(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  /// The update as a function of the committed state: trial = the state at `strain`. Fiber
  /// sections keep only the states of their fibers and call this with one parameter set.
  [[nodiscard]] Status computeTrial(const State& committed, State& trial, double strain) const;
  /// Turns `state` into the state computeTrial(state, trial, strain) leaves, given that state's
  /// stress and tangent: the history updates alone, bit for bit the same. A fiber section keeps
  /// only its fibers' trial stress and tangent (16 bytes instead of the 48 of a state), and
  /// commits with this.
  void commitTrial(State& state, double strain, double stress, double tangent) const;
  /// computeTrial of n fibers: out.stress[i] and out.tangent[i] are the trial stress and tangent at
  /// strains[i] from committed[i], bit for bit. Where the processor has AVX the fibers go four at a
  /// time through every branch one of the four takes, each lane keeping its own result.
  void computeTrials(const StateFours<State>* committed, const FiberStrains& strains,
                     const Responses& out, std::size_t n) const;
  /// commitTrial of n fibers: fiber i of `states` committed at strains[i] with trial.stress[i]
  /// and trial.tangent[i], bit for bit. Where the processor has AVX four fibers at a time (the
  /// pass after a commit folds the commit in; one at a time it was a third of that pass's group
  /// work).
  void commitTrials(StateFours<State>* states, const FiberStrains& strains, const Responses& trial,
                    std::size_t n) const;
  /// Whether computeTrials takes four fibers at a time on this processor.
  static bool updatesFourAtOnce() { return lanes::available(); }
  /// The virgin state.
  State virginState() const { return initialState(); }
  double getInitialTangent() const override { return Ec0_; }
  /// computeTrial returns the committed state at its strain (within DBL_EPSILON).
  bool keepsStateAtSameStrain() const override { return true; }
  /// Parameters with negative (compressive) signs.
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  void envelope(State& s) const;
  void unload(State& s) const;
  void reload(State& s) const;
  /// commitTrials four at a time (AVX), the last one to three in their own four.
  void commitFourAtOnce(StateFours<State>* states, const FiberStrains& strains,
                        const Responses& trial, std::size_t n) const;
  /// computeTrials four at a time (AVX), the last one to three in their own four.
  void computeFourAtOnce(const StateFours<State>* committed, const FiberStrains& strains,
                         const Responses& out, std::size_t n) const;
  Params params_;
  // Constants of the parameters, formed once with the expressions the update used to evaluate
  // (so the same bits): divisions are much of this law's cost in a fiber loop.
  double Ec0_ = 0.0;           ///< initial tangent 2 fpc / epsc0
  double descentSlope_ = 0.0;  ///< (fpc - fpcu) / (epsc0 - epsU)
};

// The update and its branches are defined here, inline, so that a fiber section's loop over
// its Concrete01 fibers can inline them.

// Monotonic envelope (Kent & Park 1971 with the Scott et al. 1982 descending branch).
inline void Concrete01::envelope(State& s) const {
  const auto& p = params_;
  if (s.strain > p.epsc0) {
    const double eta = s.strain / p.epsc0;
    s.stress = p.fpc * (2.0 * eta - eta * eta);
    s.tangent = Ec0_ * (1.0 - eta);
  } else if (s.strain > p.epsU) {
    s.tangent = descentSlope_;
    s.stress = p.fpc + s.tangent * (s.strain - p.epsc0);
  } else {
    s.stress = p.fpcu;
    s.tangent = 0.0;
  }
}

// Unloading line from the envelope point at minStrain: zero-stress strain from Karsan & Jirsa
// (1969), eps_end/epsc0 = 0.145*eta^2 + 0.13*eta (eta < 2) or 0.707*(eta-2) + 0.834, limited so
// that the line is never stiffer than the initial modulus.
inline void Concrete01::unload(State& s) const {
  const auto& p = params_;
  const double strainForRatio = s.minStrain < p.epsU ? p.epsU : s.minStrain;
  const double eta = strainForRatio / p.epsc0;
  const double ratio = eta < 2.0 ? 0.145 * eta * eta + 0.13 * eta : 0.707 * (eta - 2.0) + 0.834;
  s.endStrain = ratio * p.epsc0;
  const double span = s.minStrain - s.endStrain;  // negative
  const double Ec0 = Ec0_;
  const double elasticSpan = s.stress / Ec0;
  if (span > -DBL_EPSILON) {
    s.unloadSlope = Ec0;
  } else if (span <= elasticSpan) {
    s.endStrain = s.minStrain - span;
    s.unloadSlope = s.stress / span;
  } else {
    s.endStrain = s.minStrain - elasticSpan;
    s.unloadSlope = Ec0;
  }
}

inline void Concrete01::reload(State& s) const {
  if (s.strain <= s.minStrain) {
    s.minStrain = s.strain;
    envelope(s);
    unload(s);
  } else if (s.strain <= s.endStrain) {
    s.tangent = s.unloadSlope;
    s.stress = s.tangent * (s.strain - s.endStrain);
  } else {
    s.stress = 0.0;
    s.tangent = 0.0;
  }
}

inline Status Concrete01::computeTrial(const State& committed, State& trial, double strain) const {
  trial = committed;
  if (std::fabs(strain - committed.strain) < DBL_EPSILON) return Status::Ok;
  trial.strain = strain;
  if (strain > 0.0) {  // no tensile strength
    trial.stress = 0.0;
    trial.tangent = 0.0;
    return Status::Ok;
  }
  // Line through the committed point with the committed unloading slope. It meets the
  // envelope exactly where a reloading line rejoins it, so the evaluation order decides ties;
  // it is kept as in OpenSees (sig_c + k*eps - k*eps_c) to reproduce its branch choice.
  const double linear =
      committed.stress + committed.unloadSlope * strain - committed.unloadSlope * committed.strain;
  if (strain < committed.strain) {
    reload(trial);
    if (linear > trial.stress) {
      trial.stress = linear;
      trial.tangent = trial.unloadSlope;
    }
  } else if (linear <= 0.0) {
    trial.stress = linear;
    trial.tangent = committed.unloadSlope;
  } else {
    trial.stress = 0.0;
    trial.tangent = 0.0;
  }
  return std::isfinite(trial.stress) ? Status::Ok : Status::NonFinite;
}

// The history update of computeTrial: only a compressive strain below both the committed strain
// and the most compressive one reached moves the unloading line (reload's first branch, which
// unloads from the envelope stress, not from the trial stress a steeper line may give).
inline void Concrete01::commitTrial(State& state, double strain, double stress,
                                    double tangent) const {
  if (std::fabs(strain - state.strain) < DBL_EPSILON) return;
  if (!(strain > 0.0) && strain < state.strain && strain <= state.minStrain) {
    State onEnvelope = state;
    onEnvelope.strain = strain;
    onEnvelope.minStrain = strain;
    envelope(onEnvelope);
    unload(onEnvelope);
    state.minStrain = onEnvelope.minStrain;
    state.endStrain = onEnvelope.endStrain;
    state.unloadSlope = onEnvelope.unloadSlope;
  }
  state.strain = strain;
  state.stress = stress;
  state.tangent = tangent;
}

inline Status Concrete01::setTrialStrain(double strain, double /*strainRate*/) {
  return computeTrial(committed_, trial_, strain);
}

}  // namespace dabs::materials
