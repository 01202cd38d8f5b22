// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "materials/section/SectionForceDeformation.h"

namespace dabs::materials::section {

/// Parameters of `section Elastic`: 2D `tag E A Iz ?G alphaY?`, 3D `tag E A Iz Iy G J ?alphaY
/// alphaZ?` (OpenSees/OpenSees:SRC/material/section/ElasticSection2d.cpp, ElasticSection3d.cpp,
/// ElasticShearSection2d/3d.cpp for the shear-flexible variants).
struct ElasticSectionParams {
  int ndm = 2;              ///< model dimension, 2 or 3
  double modulus = 0.0;     ///< E
  double area = 0.0;        ///< A
  double inertiaZ = 0.0;    ///< Iz
  double inertiaY = 0.0;    ///< Iy (3D)
  double shearModulus = 0;  ///< G (3D always; 2D only with shear)
  double torsion = 0.0;     ///< J (3D)
  double alphaY = 0.0;      ///< shear shape factor for Vy; 0: no shear resultant
  double alphaZ = 0.0;      ///< shear shape factor for Vz (3D); 0: no shear resultant
  /// Throws InputError unless E, A, Iz (and in 3D Iy, G, J) are positive, G > 0 when a shear
  /// factor is given and the shear factors are zero or positive.
  void validate() const;
};

/// Linear elastic section with a diagonal stiffness: resultants [P, Mz] (2D) or [P, Mz, My, T]
/// (3D) with stiffnesses EA, EIz, EIy, GJ, plus Vy (and Vz) with alpha G A when shear factors are
/// given, in the order P, Mz, Vy (2D) or P, Mz, Vy, My, Vz, T (3D) as OpenSees'
/// ElasticShearSection2d/3d.
class ElasticSection final : public SectionForceDeformation {
 public:
  using Params = ElasticSectionParams;
  ElasticSection(int tag, const Params& params);

  int order() const override { return static_cast<int>(codes_.size()); }
  std::span<const SectionCode> type() const override { return codes_; }
  [[nodiscard]] Status setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) override;
  Eigen::Ref<const Eigen::VectorXd> getDeformation() const override { return e_; }
  Eigen::Ref<const Eigen::VectorXd> getStressResultant() const override { return s_; }
  Eigen::Ref<const Eigen::MatrixXd> getSectionTangent() const override { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> getInitialTangent() const override { return k_; }
  void commitState() override { eCommitted_ = e_; }
  void revertToLastCommit() override;
  void revertToStart() override;
  std::unique_ptr<SectionForceDeformation> clone() const override {
    return std::make_unique<ElasticSection>(*this);
  }
  bool keepsStateAtSameDeformation() const override { return true; }
  /// {"force"}, {"deformation"}.
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

 private:
  std::vector<SectionCode> codes_;
  Eigen::VectorXd e_, eCommitted_, s_;
  Eigen::MatrixXd k_;
};

}  // namespace dabs::materials::section
