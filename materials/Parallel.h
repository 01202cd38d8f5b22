// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials {

/// Materials acting side by side under the same strain: stress = sum f_i*stress_i, and likewise
/// for the tangent and the damping tangent.
/// OpenSees: `uniaxialMaterial Parallel tag mat1 mat2 ... ?-factors f1 f2 ...?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/ParallelMaterial.cpp).
///
/// Derives from UniaxialMaterial rather than StatefulUniaxial because commit and revert must
/// also reach the owned components.
class Parallel final : public UniaxialMaterial {
 public:
  struct Params {
    std::vector<const UniaxialMaterial*> components;  ///< prototypes (cloned), at least one
    std::vector<double> factors;                      ///< one per component; empty = all 1
    /// Throws InputError for no or null components, a factor count mismatch or non-finite factors.
    void validate() const;
  };

  /// Trial and committed values of the combination (the history lives in the components).
  struct State {
    double strain = 0.0;       ///< common strain
    double strainRate = 0.0;   ///< common strain rate
    double stress = 0.0;       ///< sum f_i*stress_i
    double tangent = 0.0;      ///< sum f_i*tangent_i
    double dampTangent = 0.0;  ///< sum f_i*dampTangent_i
  };

  Parallel(int tag, const Params& params);
  Parallel(const Parallel& other);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStrainRate() const override { return trial_.strainRate; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  double getDampTangent() const override { return trial_.dampTangent; }
  double getInitialTangent() const override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;

  /// Number of components.
  std::size_t size() const noexcept { return components_.size(); }
  /// Component i (its trial state is the one of the last setTrialStrain).
  const UniaxialMaterial& component(std::size_t i) const { return *components_[i]; }

 private:
  void gather();  // fills trial_ from the components' trial values
  std::vector<std::unique_ptr<UniaxialMaterial>> components_;
  std::vector<double> factors_;
  State trial_{};
  State committed_{};
};

}  // namespace dabs::materials
