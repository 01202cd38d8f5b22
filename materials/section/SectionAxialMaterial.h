// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>

#include "materials/UniaxialMaterial.h"
#include "materials/section/SectionForceDeformation.h"

namespace dabs::materials::section {

/// The axial resultant of a section seen as a uniaxial material: a strain sets the section's
/// axial deformation (every other deformation zero) and the stress is its axial force P, so a
/// truss of unit area built on it is OpenSees' truss with a section
/// (OpenSees/OpenSees:SRC/element/truss/TrussSection.cpp). Owns a clone of the section.
class SectionAxialMaterial final : public UniaxialMaterial {
 public:
  /// Throws InputError when the section has no axial resultant (code P).
  explicit SectionAxialMaterial(std::unique_ptr<SectionForceDeformation> section);
  SectionAxialMaterial(const SectionAxialMaterial& other);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return section_->getDeformation()(axial_); }
  double getStress() const override { return section_->getStressResultant()(axial_); }
  double getTangent() const override { return section_->getSectionTangent()(axial_, axial_); }
  double getInitialTangent() const override {
    return section_->getInitialTangent()(axial_, axial_);
  }
  void commitState() override { section_->commitState(); }
  void revertToLastCommit() override { section_->revertToLastCommit(); }
  void revertToStart() override { section_->revertToStart(); }
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<SectionAxialMaterial>(*this);
  }

 private:
  std::unique_ptr<SectionForceDeformation> section_;
  int axial_ = 0;                ///< row of P in the section's resultants
  Eigen::VectorXd deformation_;  ///< trial deformation handed to the section
};

}  // namespace dabs::materials::section
