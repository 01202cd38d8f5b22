// SPDX-License-Identifier: MIT
#pragma once

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
class Concrete01 final : public StatefulUniaxial<Concrete01State> {
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
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  double getInitialTangent() const override { return 2.0 * params_.fpc / params_.epsc0; }
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;
  /// Parameters with negative (compressive) signs.
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  void envelope(State& s) const;
  void unload(State& s) const;
  void reload(State& s) const;
  Params params_;
};

}  // namespace dabs::materials
