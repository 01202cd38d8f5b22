// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials {

/// Wraps another uniaxial material and fails it when the fatigue damage of its strain history
/// reaches Dmax, or when the strain reaches the limits [min, max].
/// OpenSees: `uniaxialMaterial Fatigue tag matTag ?-E0 E0? ?-m m? ?-min min? ?-max max? ?-Dmax D?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/FatigueMaterial.cpp, after Uriz and Mahin 2004,
/// "Seismic performance assessment of concentrically braced steel frames", 13th WCEE).
///
/// Damage: Miner's rule over the cycles found by a modified rainflow count of the strain
/// reversals, each cycle of strain range de costing 1/N with the Coffin-Manson relation
/// de = E0 * N^m (de is the peak-to-valley range, as OpenSees computes it); a half cycle costs
/// half. Reversals are found one step late (the previous strain was a peak when the slope changes
/// sign), so the half cycle still open is also counted, as if the current strain were a peak (the
/// pseudo damage): the material fails at a pseudo peak when that damage exceeds Dmax while the
/// wrapped stress is tensile, and at a counted peak when the counted damage reaches Dmax.
///
/// The count runs on the trial strain from the committed count (so a trial is idempotent and the
/// getters do not change at commit); OpenSees runs it in commitState, so the failure shows in
/// OpenSees' getters only after the commit of the failing step, in ours already in its trial.
/// Along a history of committed strains (testUniaxialMaterial/setStrain) both give the same
/// numbers.
///
/// Once failed the stress is 1e-8 times the wrapped stress and the tangent 1e-8 times the wrapped
/// initial tangent (OpenSees' choice: a tiny positive stiffness keeps the element matrix regular);
/// the wrapped material is no longer committed, so it stays at the last state before failure.
class Fatigue final : public UniaxialMaterial {
 public:
  struct Params {
    const UniaxialMaterial* material = nullptr;  ///< wrapped prototype (cloned)
    double Dmax = 1.0;                           ///< damage at failure, 0 < Dmax <= 1
    double E0 = 0.191;         ///< strain range failing in one cycle (Coffin-Manson), > 0
    double m = -0.458;         ///< Coffin-Manson exponent, < 0
    double minStrain = -1e16;  ///< the material fails at strains <= minStrain
    double maxStrain = 1e16;   ///< the material fails at strains >= maxStrain, > minStrain
    /// Throws InputError for a missing material or parameters out of range.
    void validate() const;
  };

  /// Where the rainflow count stands (OpenSees' peaks A, B, C, D and counter PCC).
  enum class Phase {
    First,     ///< only the starting point A is known
    OneRange,  ///< A and B known: the range Y = |B - A| is waiting
    TwoRanges  ///< A, B and C known: Y = |C - B| may close as a full cycle
  };

  /// The whole fatigue history: trial and committed copies are assigned as one value.
  struct State {
    double strain = 0.0;               ///< strain given to the wrapped material
    double strainRate = 0.0;           ///< strain rate given to the wrapped material
    bool started = false;              ///< A holds the first committed strain
    Phase phase = Phase::First;        ///< which of the peaks below are known
    double a = 0.0, b = 0.0, c = 0.0;  ///< the last reversal points kept by the count
    double y = 0.0;                    ///< range waiting to be counted
    double lastSlope = 0.0;            ///< strain increment of the previous step (its sign)
    double lastStrain = 0.0;           ///< strain of the previous step (a candidate peak)
    double damage = 0.0;               ///< Miner damage of the counted cycles (OpenSees DI)
    double pseudoDamage = 0.0;         ///< damage if the current strain were a peak (OpenSees DL)
    bool failed = false;               ///< the material has failed
  };

  Fatigue(int tag, const Params& params);
  Fatigue(const Fatigue& other);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStrainRate() const override { return material_->getStrainRate(); }
  double getStress() const override;
  double getTangent() const override;
  double getDampTangent() const override;
  double getInitialTangent() const override { return material_->getInitialTangent(); }
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;

  /// "damage": counted Miner damage (OpenSees' `damage` response); "failure": 1 once failed.
  std::optional<double> response(std::string_view name) const override;

  const Params& params() const noexcept { return params_; }
  const State& trialState() const noexcept { return trial_; }
  const State& committedState() const noexcept { return committed_; }
  const UniaxialMaterial& material() const noexcept { return *material_; }

  /// Miner damage of `cycles` cycles (0.5 or 1) of strain range `range`: cycles / N with
  /// N = (range / E0)^(1/m) (Coffin-Manson; a zero range costs nothing).
  double cycleDamage(double cycles, double range) const;

 private:
  /// The count after the step from `committed_` to `strain` (OpenSees' commitState).
  State advance(double strain, double wrappedStress) const;

  Params params_;
  std::unique_ptr<UniaxialMaterial> material_;
  State trial_{};
  State committed_{};
};

}  // namespace dabs::materials
