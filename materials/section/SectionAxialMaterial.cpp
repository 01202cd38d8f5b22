// SPDX-License-Identifier: MIT
#include "materials/section/SectionAxialMaterial.h"

#include <algorithm>

#include "materials/InputError.h"

namespace dabs::materials::section {

SectionAxialMaterial::SectionAxialMaterial(std::unique_ptr<SectionForceDeformation> section)
    : UniaxialMaterial(section->tag()), section_(std::move(section)) {
  const auto codes = section_->type();
  const auto it = std::find(codes.begin(), codes.end(), SectionCode::P);
  if (it == codes.end())
    throw InputError("secTag", "section " + std::to_string(section_->tag()) +
                                   " has no axial resultant (P) for a truss");
  axial_ = static_cast<int>(it - codes.begin());
  deformation_ = Eigen::VectorXd::Zero(section_->order());
}

SectionAxialMaterial::SectionAxialMaterial(const SectionAxialMaterial& other)
    : UniaxialMaterial(other.tag()),
      section_(other.section_->clone()),
      axial_(other.axial_),
      deformation_(other.deformation_) {}

Status SectionAxialMaterial::setTrialStrain(double strain, double /*strainRate*/) {
  deformation_(axial_) = strain;
  return section_->setTrialDeformation(deformation_);
}

}  // namespace dabs::materials::section
