// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"
#include "materials/section/SectionForceDeformation.h"

namespace dabs::materials::section {

/// `section Aggregator tag matTag1 code1 ... ?-section secTag?`: uncoupled uniaxial responses
/// added to an optional base section
/// (OpenSees/OpenSees:SRC/material/section/SectionAggregator.cpp). Resultant order as OpenSees: the
/// base section's resultants first, then the materials' in the order given. The tangent is block
/// diagonal. Unlike OpenSees, a code may appear only once.
class SectionAggregator final : public SectionForceDeformation {
 public:
  struct Part {
    const UniaxialMaterial* material = nullptr;  ///< prototype, cloned by the constructor
    SectionCode code = SectionCode::P;
  };
  /// `base` may be null. Throws InputError for no parts at all, a missing material, a repeated
  /// code or more than 6 resultants.
  SectionAggregator(int tag, const std::vector<Part>& parts, const SectionForceDeformation* base);
  SectionAggregator(const SectionAggregator& other);

  int order() const override { return static_cast<int>(codes_.size()); }
  std::span<const SectionCode> type() const override { return codes_; }
  [[nodiscard]] Status setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) override;
  Eigen::Ref<const Eigen::VectorXd> getDeformation() const override { return e_; }
  Eigen::Ref<const Eigen::VectorXd> getStressResultant() const override { return s_; }
  Eigen::Ref<const Eigen::MatrixXd> getSectionTangent() const override { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> getInitialTangent() const override { return k0_; }
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::unique_ptr<SectionForceDeformation> clone() const override {
    return std::make_unique<SectionAggregator>(*this);
  }
  bool keepsStateAtSameDeformation() const override;
  /// {"force"}, {"deformation"}; other names go to the base section.
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

 private:
  void gather(bool initial);  // s_, k_ (or k0_) from the parts' trial state

  std::unique_ptr<SectionForceDeformation> base_;
  int baseOrder_ = 0;
  std::vector<std::unique_ptr<UniaxialMaterial>> mats_;
  std::vector<SectionCode> codes_;
  Eigen::VectorXd e_, eCommitted_, s_;
  Eigen::MatrixXd k_, k0_;
};

}  // namespace dabs::materials::section
