// SPDX-License-Identifier: MIT
#pragma once

#include <cfloat>
#include <cmath>
#include <cstddef>

#include "materials/FourLanes.h"
#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Concrete02. In a fiber section's StateFours two fields share a cache line: the
/// strain, stress and tangent (and dept, which moves as a crack opens) on the lines every commit
/// writes, the functions of ecmin on two lines only a new most compressive strain writes.
struct Concrete02State {
  double strain = 0.0;   ///< strain (compression negative)
  double stress = 0.0;   ///< stress (compression negative)
  double tangent = 0.0;  ///< d(stress)/d(strain)
  double dept = 0.0;     ///< largest tensile strain beyond the zero-stress strain ept
  double ecmin = 0.0;    ///< most compressive strain reached
  // Functions of ecmin alone, formed when ecmin changes rather than at every update:
  double sigMin = 0.0;  ///< envelope stress at ecmin
  double Er = 0.0;      ///< reloading slope (EERC report eq. 2.35)
  double ept = 0.0;     ///< zero-stress strain of the reloading line (eq. 2.36)
};

namespace concrete02 {
/// Tangent used by OpenSees on the flat branches instead of an exact zero.
inline constexpr double kResidualTangent = 1.0e-10;
}  // namespace concrete02

/// Concrete with linear tension softening (Yassin 1994; FEDEAS Concr2 by Sze & Filippou):
/// Kent-Scott-Park compression envelope (parabola to (epsc0, fpc), linear to (epsU, fpcu), then
/// flat), unloading with slope lambda-dependent damage (EERC report eqs. 2.31-2.36), and in
/// tension a linear branch Ec0*eps up to ft followed by linear softening with slope -Ets.
/// OpenSees: `uniaxialMaterial Concrete02 tag fpc epsc0 fpcu epsU ?lambda ft Ets?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/Concrete02.cpp); defaults lambda = 0.1,
/// ft = 0.1*|fpc|, Ets = 0.1*fpc/epsc0. Compression values must be negative.
class Concrete02 final : public StatefulUniaxial<Concrete02, Concrete02State> {
 public:
  using State = Concrete02State;

  struct Params {
    double fpc = 0.0;     ///< compressive strength (< 0)
    double epsc0 = 0.0;   ///< strain at fpc (< 0)
    double fpcu = 0.0;    ///< crushing strength (<= 0, |fpcu| <= |fpc|)
    double epsU = 0.0;    ///< strain at fpcu (< epsc0)
    double lambda = 0.1;  ///< ratio of unloading slope at epsU to the initial slope, in [0, 1)
    double ft = 0.0;      ///< tensile strength (>= 0)
    double Ets = 0.0;     ///< tension softening stiffness (> 0)
    /// Params with the OpenSees defaults for lambda, ft and Ets.
    static Params withDefaults(double fpc, double epsc0, double fpcu, double epsU);
    /// Throws InputError naming the offending parameter.
    void validate() const;
  };

  Concrete02(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  /// The update as a function of the committed state: trial = the state at `strain`. Fiber
  /// sections keep only the states of their fibers and call this with one parameter set.
  [[nodiscard]] Status computeTrial(const State& committed, State& trial, double strain) const;
  /// Turns `state` into the state computeTrial(state, trial, strain) leaves, given that state's
  /// stress and tangent: the history updates alone, bit for bit the same. A fiber section keeps
  /// only its fibers' trial stress and tangent, and commits with this.
  void commitTrial(State& state, double strain, double stress, double tangent) const;
  /// computeTrial of n fibers: out.stress[i] and out.tangent[i] are the trial stress and tangent at
  /// strains[i] from fiber i of `committed`, bit for bit. Where the processor has AVX the fibers
  /// go four at a time through every branch one of the four takes, each lane keeping its own
  /// result: fewer mispredicted branches, and the divisions of four fibers in one instruction.
  void computeTrials(const StateFours<State>* committed, const FiberStrains& strains,
                     const Responses& out, std::size_t n) const;
  /// commitTrial of n fibers: fiber i of `states` committed at strains[i] with trial.stress[i]
  /// and trial.tangent[i], bit for bit. Where the processor has AVX four fibers at a time (the
  /// pass after a commit folds the commit in; one at a time it was a third of that pass's group
  /// work), storing only the rows that change.
  void commitTrials(StateFours<State>* states, const FiberStrains& strains, const Responses& trial,
                    std::size_t n) const;
  /// Whether computeTrials takes four fibers at a time on this processor.
  static bool updatesFourAtOnce() { return lanes::available(); }
  /// The virgin state.
  State virginState() const { return initialState(); }
  double getInitialTangent() const override { return Ec0_; }
  /// computeTrial returns the committed state at its strain (within DBL_EPSILON).
  bool keepsStateAtSameStrain() const override { return true; }
  const Params& params() const noexcept { return params_; }

  /// Compression envelope at `eps`: stress and tangent.
  void compressionEnvelope(double eps, double& stress, double& tangent) const;
  /// Tension envelope at `eps` measured from the zero-stress strain: stress and tangent.
  void tensionEnvelope(double eps, double& stress, double& tangent) const;

 private:
  State initialState() const override;
  /// Sets ecmin (envelope stress sigMin there) and the reloading data that follow from it.
  void setMinimumStrain(State& s, double ecmin, double sigMin) const;
  /// commitTrials four at a time (AVX), the last one to three in their own four.
  void commitFourAtOnce(StateFours<State>* states, const FiberStrains& strains,
                        const Responses& trial, std::size_t n) const;
  /// computeTrials four at a time (AVX), the last one to three in their own four.
  void computeFourAtOnce(const StateFours<State>* committed, const FiberStrains& strains,
                         const Responses& out, std::size_t n) const;
  Params params_;
  // Constants of the parameters (formed once; divisions are the cost of this law's update):
  double Ec0_ = 0.0;       ///< initial tangent 2 fpc / epsc0
  double epsR_ = 0.0;      ///< strain of point R fixing the reloading slope (eqs. 2.31, 2.32)
  double sigR_ = 0.0;      ///< stress of point R
  double epsCrack_ = 0.0;  ///< cracking strain ft / Ec0
  double epsZero_ = 0.0;   ///< strain where tension softening reaches zero stress
};

// The update and its envelopes are defined here, inline, so that a fiber section's loop over
// its Concrete02 fibers can inline them (the update is most of a fiber section's cost).

// Reloading from the largest compression reached (envelope stress sigMin there): the slope Er
// towards point R (EERC report eq. 2.35) and the strain ept where that line crosses zero stress
// (eq. 2.36).
inline void Concrete02::setMinimumStrain(State& s, double ecmin, double sigMin) const {
  s.ecmin = ecmin;
  s.sigMin = sigMin;
  s.Er = (s.sigMin - sigR_) / (ecmin - epsR_);
  s.ept = ecmin - s.sigMin / s.Er;
}

inline void Concrete02::compressionEnvelope(double eps, double& stress, double& tangent) const {
  const auto& p = params_;
  const double Ec0 = Ec0_;
  const double ratio = eps / p.epsc0;
  if (eps >= p.epsc0) {  // Hognestad/Kent-Park parabola
    stress = p.fpc * ratio * (2.0 - ratio);
    tangent = Ec0 * (1.0 - ratio);
  } else if (eps > p.epsU) {  // linear descending branch
    stress = (p.fpcu - p.fpc) * (eps - p.epsc0) / (p.epsU - p.epsc0) + p.fpc;
    tangent = (p.fpcu - p.fpc) / (p.epsU - p.epsc0);
  } else {  // residual strength
    stress = p.fpcu;
    tangent = concrete02::kResidualTangent;
  }
}

inline void Concrete02::tensionEnvelope(double eps, double& stress, double& tangent) const {
  const auto& p = params_;
  const double Ec0 = Ec0_;
  const double epsCrack = epsCrack_;
  const double epsZero = epsZero_;
  if (eps <= epsCrack) {
    stress = eps * Ec0;
    tangent = Ec0;
  } else if (eps <= epsZero) {
    tangent = -p.Ets;
    stress = p.ft - p.Ets * (eps - epsCrack);
  } else {
    tangent = concrete02::kResidualTangent;
    stress = 0.0;
  }
}

inline Status Concrete02::computeTrial(const State& committed, State& trial, double strain) const {
  const double Ec0 = Ec0_;
  trial = committed;
  // Deliberate difference: OpenSees keeps the previous TRIAL stress here, which breaks trial
  // idempotence; the committed state is the consistent answer.
  const double deps = strain - committed.strain;
  if (std::fabs(deps) < DBL_EPSILON) return Status::Ok;
  trial.strain = strain;

  if (strain < trial.ecmin) {
    compressionEnvelope(strain, trial.stress, trial.tangent);
    setMinimumStrain(trial, strain, trial.stress);
    return std::isfinite(trial.stress) ? Status::Ok : Status::NonFinite;
  }
  const double sigMin = trial.sigMin, Er = trial.Er, ept = trial.ept;

  if (strain <= ept) {
    // between the reloading line (lower bound) and half its slope through ept (upper bound)
    const double lower = sigMin + Er * (strain - trial.ecmin);
    const double upper = 0.5 * Er * (strain - ept);
    trial.stress = committed.stress + Ec0 * deps;
    trial.tangent = Ec0;
    if (trial.stress <= lower) {
      trial.stress = lower;
      trial.tangent = Er;
    }
    if (trial.stress >= upper) {
      trial.stress = upper;
      trial.tangent = 0.5 * Er;
    }
  } else {
    // tension: reload towards the largest previous tensile strain (eqs. 2.42, 2.43), then
    // follow the tension envelope shifted by ept
    const double epn = ept + trial.dept;
    if (strain <= epn) {
      double sicn = 0.0;
      tensionEnvelope(trial.dept, sicn, trial.tangent);
      trial.tangent = trial.dept != 0.0 ? sicn / trial.dept : Ec0;
      trial.stress = trial.tangent * (strain - ept);
    } else {
      tensionEnvelope(strain - ept, trial.stress, trial.tangent);
      trial.dept = strain - ept;
    }
  }
  return std::isfinite(trial.stress) ? Status::Ok : Status::NonFinite;
}

// The history updates of computeTrial, branch for branch: a new minimum strain on the
// compression envelope, a new largest tensile strain past the reloading point epn.
inline void Concrete02::commitTrial(State& state, double strain, double stress,
                                    double tangent) const {
  if (std::fabs(strain - state.strain) < DBL_EPSILON) return;
  if (strain < state.ecmin) {
    setMinimumStrain(state, strain, stress);
  } else if (!(strain <= state.ept) && !(strain <= state.ept + state.dept)) {
    state.dept = strain - state.ept;
  }
  state.strain = strain;
  state.stress = stress;
  state.tangent = tangent;
}

inline Status Concrete02::setTrialStrain(double strain, double /*strainRate*/) {
  return computeTrial(committed_, trial_, strain);
}

}  // namespace dabs::materials
