// SPDX-License-Identifier: MIT
#pragma once

#include <optional>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Elastic: the trial (or committed) strain and strain rate with their response.
struct ElasticState {
  double strain = 0.0;      ///< strain
  double strainRate = 0.0;  ///< strain rate (1/time)
  double stress = 0.0;      ///< stress including the viscous part eta*strainRate
  double tangent = 0.0;     ///< d(stress)/d(strain)
};

/// Linear elastic law with an optional different modulus in compression and a linear dashpot:
/// stress = E*eps + eta*rate (eps >= 0), Eneg*eps + eta*rate (eps < 0).
/// OpenSees: `uniaxialMaterial Elastic tag E ?eta? ?Eneg?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/ElasticMaterial.cpp).
class Elastic final : public StatefulUniaxial<Elastic, ElasticState> {
 public:
  using State = ElasticState;

  struct Params {
    double E = 0.0;              ///< modulus in tension (and compression unless Eneg is given)
    double eta = 0.0;            ///< viscous coefficient (stress per unit strain rate), >= 0
    std::optional<double> Eneg;  ///< modulus in compression; defaults to E
    /// Throws InputError when a value is not finite or eta < 0.
    void validate() const;
    /// Modulus in compression.
    double compressionModulus() const { return Eneg.value_or(E); }
  };

  Elastic(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrainRate() const override { return trial_.strainRate; }
  double getDampTangent() const override { return params_.eta; }
  double getInitialTangent() const override;
  /// No history; the stress depends on the strain rate when eta is not zero.
  bool keepsStateAtSameStrain() const override { return params_.eta == 0.0; }
  const Params& params() const noexcept { return params_; }

 private:
  State initialState() const override;
  Params params_;
};

}  // namespace dabs::materials
