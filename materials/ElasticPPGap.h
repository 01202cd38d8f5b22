// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of ElasticPPGap: the current elastic range [minYieldStrain, maxYieldStrain] (for a
/// compression gap, Fy < 0, the range is mirrored: max <= strain <= min).
struct ElasticPPGapState {
  double strain = 0.0;          ///< strain
  double stress = 0.0;          ///< stress
  double tangent = 0.0;         ///< 0 (gap open), E (closed, elastic) or eta*E (yielding)
  double minYieldStrain = 0.0;  ///< strain at which the gap closes (stress zero)
  double maxYieldStrain = 0.0;  ///< strain at which yielding starts
};

/// Elastic-plastic gap: no stress while the gap is open, elastic with modulus E once closed,
/// yield at Fy with hardening eta*E. Plastic strain widens the gap; without `damage` a gap
/// that re-closes at a strain between the original gap and the widened one resets the yield
/// point (OpenSees/OpenSees:SRC/material/uniaxial/EPPGapMaterial.cpp).
/// Fy and gap both negative make a compression gap.
/// OpenSees: `uniaxialMaterial ElasticPPGap tag E Fy gap ?eta? ?damage?`
class ElasticPPGap final : public StatefulUniaxial<ElasticPPGap, ElasticPPGapState> {
 public:
  using State = ElasticPPGapState;

  struct Params {
    double E = 0.0;       ///< modulus once closed, > 0
    double Fy = 0.0;      ///< yield stress, nonzero; negative for a compression gap
    double gap = 0.0;     ///< initial gap (strain), same sign as Fy for a real gap
    double eta = 0.0;     ///< post-yield hardening ratio, < 1
    bool damage = false;  ///< accumulate the gap (no recovery of the yield point)
    /// Throws InputError for E <= 0, Fy == 0, eta >= 1 or non-finite values.
    void validate() const;
  };

  ElasticPPGap(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  /// 0 when the gap is initially open, E when the material starts in contact (gap of the
  /// other sign), as OpenSees.
  double getInitialTangent() const override;
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  /// Stress and tangent at `strain` for the elastic range of `from`, written to `out`.
  void respond(const State& from, double strain, State& out) const;
  Params params_;
};

}  // namespace dabs::materials
