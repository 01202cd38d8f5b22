// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// State of Viscous (no history beyond the trial values).
struct ViscousState {
  double strain = 0.0;       ///< strain (not used by the law)
  double strainRate = 0.0;   ///< strain rate
  double stress = 0.0;       ///< C*|rate|^alpha*sign(rate)
  double dampTangent = 0.0;  ///< d(stress)/d(rate)
};

/// Nonlinear dashpot: stress = C*|rate|^alpha*sign(rate); the damping tangent
/// alpha*C*|rate|^(alpha-1) uses max(|rate|, minVel) so that it stays finite for alpha < 1.
/// OpenSees: `uniaxialMaterial Viscous tag C alpha ?minVel?`, minVel default 1e-11
/// (OpenSees/OpenSees:SRC/material/uniaxial/ViscousMaterial.cpp).
class Viscous final : public StatefulUniaxial<Viscous, ViscousState> {
 public:
  using State = ViscousState;

  struct Params {
    double C = 0.0;         ///< damping coefficient (stress per rate^alpha), >= 0
    double alpha = 1.0;     ///< velocity exponent, > 0
    double minVel = 1e-11;  ///< floor of |rate| in the damping tangent, > 0
    /// Throws InputError for C < 0, alpha <= 0, minVel <= 0 or non-finite values.
    void validate() const;
  };

  Viscous(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrainRate() const override { return trial_.strainRate; }
  double getDampTangent() const override { return trial_.dampTangent; }
  double getInitialTangent() const override { return 0.0; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  double dampTangentAt(double rate) const;
  Params params_;
};

}  // namespace dabs::materials
