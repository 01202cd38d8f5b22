// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Steel02 (strains are the material's own, including the initial strain sigInit/E).
struct Steel02State {
  double strain = 0.0;   ///< strain as given to setTrialStrain
  double stress = 0.0;   ///< stress
  double tangent = 0.0;  ///< d(stress)/d(strain)
  double epsMin = 0.0;   ///< most negative reversal strain (starts at -epsy)
  double epsMax = 0.0;   ///< most positive reversal strain (starts at +epsy)
  double epsPl = 0.0;    ///< previous extreme strain in the opposite direction (sets xi)
  double eps0 = 0.0;     ///< strain where the elastic and hardening asymptotes meet
  double sig0 = 0.0;     ///< stress at that intersection
  double epsR = 0.0;     ///< strain at the last reversal
  double sigR = 0.0;     ///< stress at the last reversal
  int kon = 0;           ///< 0 virgin, 1 loading (towards tension), 2 towards compression, 3 virgin at sigInit
  double R = 0.0;        ///< curvature of the current branch (a function of epsPl and eps0)
  double invR = 0.0;     ///< 1 / R
  double invSpan = 0.0;  ///< 1 / (eps0 - epsR), the strain normaliser of the branch
};

/// Menegotto-Pinto steel with Filippou isotropic hardening (Menegotto & Pinto 1973; Filippou,
/// Popov & Bertero 1983, EERC 83/19, eqs. 3-5):
///   sig* = b*eps* + (1-b)*eps*/(1+|eps*|^R)^(1/R),  eps* = (eps-epsR)/(eps0-epsR),
///   sig* = (sig-sigR)/(sig0-sigR),  R = R0*(1 - cR1*xi/(cR2+xi)).
/// OpenSees: `uniaxialMaterial Steel02 tag Fy E b ?R0 cR1 cR2? ?a1 a2 a3 a4? ?sigInit?`, defaults
/// R0=15 cR1=0.925 cR2=0.15 a1=0 a2=1 a3=0 a4=1 sigInit=0
/// (OpenSees/OpenSees:SRC/material/uniaxial/Steel02.cpp).
class Steel02 final : public StatefulUniaxial<Steel02State> {
 public:
  using State = Steel02State;

  struct Params {
    double Fy = 0.0;      ///< yield stress, > 0
    double E = 0.0;       ///< initial modulus, > 0
    double b = 0.0;       ///< strain-hardening ratio, in [0, 1)
    double R0 = 15.0;     ///< initial transition curvature, > 0
    double cR1 = 0.925;   ///< curvature degradation, in [0, 1)
    double cR2 = 0.15;    ///< curvature degradation, > 0
    double a1 = 0.0;      ///< compressive isotropic hardening, >= 0
    double a2 = 1.0;      ///< normalising strain for a1 (units of epsy), > 0
    double a3 = 0.0;      ///< tensile isotropic hardening, >= 0
    double a4 = 1.0;      ///< normalising strain for a3 (units of epsy), > 0
    double sigInit = 0.0; ///< initial stress (strain offset sigInit/E), |sigInit| < Fy
    /// Throws InputError naming the offending parameter.
    void validate() const;
  };

  Steel02(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  double getInitialTangent() const override { return params_.E; }
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  /// R = R0 (1 - cR1 xi / (cR2 + xi)) and 1 / (eps0 - epsR) for the branch of `s`.
  void setCurvature(State& s) const;
  Params params_;
  double epsy_ = 0.0;    ///< Fy / E
  double Esh_ = 0.0;     ///< b E
  double epsIni_ = 0.0;  ///< sigInit / E
};

}  // namespace dabs::materials
