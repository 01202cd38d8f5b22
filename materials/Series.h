// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials {

/// Materials in series: the strains add up and every component carries the same stress. The
/// component strains are found by Newton iteration on the stress unbalance, starting each time
/// from the committed component strains (so a trial depends only on the committed state, unlike
/// OpenSees' SeriesMaterial, which continues from the previous trial).
/// OpenSees: `uniaxialMaterial Series tag mat1 mat2 ...`
/// (OpenSees/OpenSees:SRC/material/uniaxial/SeriesMaterial.cpp).
///
/// Components receive zero strain rate: rate-dependent components are not supported in series.
/// When the iteration fails setTrialStrain returns Status::NotConverged.
class Series final : public UniaxialMaterial {
 public:
  struct Params {
    std::vector<const UniaxialMaterial*> components;  ///< prototypes (cloned), at least two
    int maxIterations = 50;                           ///< Newton iterations per trial, >= 1
    double tolerance = 1e-12;  ///< stress unbalance relative to the stress level, > 0
    /// Throws InputError for fewer than two or null components, or bad iteration controls.
    void validate() const;
  };

  /// Trial and committed values; componentStrains has one entry per component.
  struct State {
    double strain = 0.0;                   ///< total strain
    double stress = 0.0;                   ///< common stress
    double tangent = 0.0;                  ///< 1 / sum of component flexibilities
    std::vector<double> componentStrains;  ///< strain of each component
  };

  Series(int tag, const Params& params);
  Series(const Series& other);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  double getInitialTangent() const override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;

  std::size_t size() const noexcept { return components_.size(); }
  const UniaxialMaterial& component(std::size_t i) const { return *components_[i]; }
  /// Trial strain of component i.
  double componentStrain(std::size_t i) const { return trial_.componentStrains[i]; }

 private:
  double flexibility(std::size_t i, double tangent) const;
  std::vector<std::unique_ptr<UniaxialMaterial>> components_;
  std::vector<double> minTangent_;  // |tangent| below this counts as this (keeps 1/k finite)
  std::vector<double> stress_;      // scratch: component stresses of the current iterate
  std::vector<double> flex_;        // scratch: component flexibilities of the current iterate
  double stressFloor_ = 0.0;        // stress scale used when all stresses are near zero
  int maxIterations_;
  double tolerance_;
  State trial_{};
  State committed_{};
};

}  // namespace dabs::materials
