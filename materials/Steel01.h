// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Steel01.
struct Steel01State {
  double strain = 0.0;     ///< strain
  double stress = 0.0;     ///< stress
  double tangent = 0.0;    ///< E0 (elastic) or b*E0 (on a hardening asymptote)
  double minStrain = 0.0;  ///< most negative strain at a reversal
  double maxStrain = 0.0;  ///< most positive strain at a reversal
  double shiftP = 1.0;     ///< isotropic-hardening factor of the tensile asymptote
  double shiftN = 1.0;     ///< isotropic-hardening factor of the compressive asymptote
  int loading = 0;         ///< +1 loading, -1 unloading, 0 virgin
};

/// Bilinear steel with kinematic hardening and optional isotropic hardening (Filippou et al.
/// 1983, EERC 83/19: asymptote shift 1 + a1*((epsmax-epsmin)/(2*a2*epsy))^0.8).
/// OpenSees: `uniaxialMaterial Steel01 tag Fy E0 b ?a1 a2 a3 a4?`, defaults a1=0 a2=55 a3=0 a4=55
/// (OpenSees/OpenSees:SRC/material/uniaxial/Steel01.cpp).
class Steel01 final : public StatefulUniaxial<Steel01, Steel01State> {
 public:
  using State = Steel01State;

  struct Params {
    double Fy = 0.0;   ///< yield stress, > 0
    double E0 = 0.0;   ///< initial modulus, > 0
    double b = 0.0;    ///< strain-hardening ratio, below 1 (negative: softening after yield)
    double a1 = 0.0;   ///< compressive asymptote shift after tensile excursions
    double a2 = 55.0;  ///< strain (in units of epsy) normalising a1's shift, > 0
    double a3 = 0.0;   ///< tensile asymptote shift after compressive excursions
    double a4 = 55.0;  ///< strain (in units of epsy) normalising a3's shift, > 0
    /// Throws InputError for non-positive Fy, E0, a2, a4, b of 1 or more or negative a1, a3.
    void validate() const;
  };

  Steel01(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getInitialTangent() const override { return params_.E0; }
  /// setTrialStrain returns the committed state at its strain (within DBL_EPSILON).
  bool keepsStateAtSameStrain() const override { return true; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  Params params_;
};

}  // namespace dabs::materials
