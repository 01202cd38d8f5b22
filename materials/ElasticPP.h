// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of ElasticPP.
struct ElasticPPState {
  double strain = 0.0;         ///< total strain
  double stress = 0.0;         ///< stress
  double tangent = 0.0;        ///< E (elastic) or 0 (yielding)
  double plasticStrain = 0.0;  ///< accumulated plastic strain
};

/// Elastic-perfectly plastic law with different yield strains in tension and compression and an
/// initial strain: stress = E*(eps - eps0 - epsP) clipped to [E*epsyN, E*epsyP].
/// OpenSees: `uniaxialMaterial ElasticPP tag E epsyP ?epsyN? ?eps0?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/ElasticPPMaterial.cpp).
class ElasticPP final : public StatefulUniaxial<ElasticPP, ElasticPPState> {
 public:
  using State = ElasticPPState;

  struct Params {
    double E = 0.0;               ///< elastic modulus, > 0
    double epsyP = 0.0;           ///< yield strain in tension, > 0
    std::optional<double> epsyN;  ///< yield strain in compression, < 0; defaults to -epsyP
    double eps0 = 0.0;            ///< initial strain (shifts the elastic branch)
    /// Throws InputError for E <= 0, epsyP <= 0, epsyN >= 0 or non-finite values.
    void validate() const;
    double compressionYieldStrain() const { return epsyN.value_or(-epsyP); }
  };

  ElasticPP(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getInitialTangent() const override { return params_.E; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override { return State{0.0, 0.0, params_.E, 0.0}; }
  Params params_;
  double fyP_;  ///< tensile yield stress E*epsyP
  double fyN_;  ///< compressive yield stress E*epsyN (negative)
};

}  // namespace dabs::materials
