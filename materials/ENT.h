// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// State of ENT (no history).
struct ENTState {
  double strain = 0.0;   ///< strain
  double stress = 0.0;   ///< E*strain in compression, 0 in tension
  double tangent = 0.0;  ///< E for strain <= 0, 0 for strain > 0
};

/// Elastic-no-tension law: stress = E*min(eps, 0).
/// OpenSees: `uniaxialMaterial ENT tag E`
/// (OpenSees/OpenSees:SRC/material/uniaxial/ENTMaterial.cpp).
class ENT final : public StatefulUniaxial<ENT, ENTState> {
 public:
  using State = ENTState;

  struct Params {
    double E = 0.0;  ///< compressive modulus, > 0
    /// Throws InputError for E <= 0.
    void validate() const;
  };

  ENT(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getInitialTangent() const override { return params_.E; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override { return State{0.0, 0.0, params_.E}; }
  Params params_;
};

}  // namespace dabs::materials
