// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "materials/Status.h"

namespace dabs::materials::section {

/// Meaning of one section resultant, with OpenSees' numeric codes
/// (OpenSees/OpenSees:SRC/material/section/SectionForceDeformation.h SECTION_RESPONSE_*).
enum class SectionCode : int { Mz = 1, P = 2, Vy = 3, My = 4, Vz = 5, T = 6 };

/// Section stress resultants versus generalised deformations (axial strain, curvatures, shear,
/// twist), with the trial/commit/revert protocol of the materials.
class SectionForceDeformation {
 public:
  explicit SectionForceDeformation(int tag) noexcept : tag_(tag) {}
  virtual ~SectionForceDeformation() = default;
  SectionForceDeformation(const SectionForceDeformation&) = default;
  SectionForceDeformation& operator=(const SectionForceDeformation&) = delete;

  int tag() const noexcept { return tag_; }
  /// Number of resultants.
  virtual int order() const = 0;
  /// Meaning of each resultant, in order.
  virtual std::span<const SectionCode> type() const = 0;

  [[nodiscard]] virtual Status setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) = 0;
  virtual Eigen::Ref<const Eigen::VectorXd> getDeformation() const = 0;
  virtual Eigen::Ref<const Eigen::VectorXd> getStressResultant() const = 0;
  virtual Eigen::Ref<const Eigen::MatrixXd> getSectionTangent() const = 0;
  virtual Eigen::Ref<const Eigen::MatrixXd> getInitialTangent() const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  [[nodiscard]] virtual std::unique_ptr<SectionForceDeformation> clone() const = 0;

  /// True when an update at the deformations of a state an update formed (the trial, or the
  /// committed state after a commit) leaves that state as it is, bit for bit (its materials keep
  /// theirs at the same strain: UniaxialMaterial::keepsStateAtSameStrain). False by default.
  virtual bool keepsStateAtSameDeformation() const { return false; }

  /// Material updates (setTrialStrain calls of the section's materials) since construction: a
  /// work count for benchmarks, not part of the state.
  virtual long materialUpdates() const noexcept { return 0; }

  /// Named responses (e.g. {"fiber","0.1","0.2","stressStrain"}); nullopt when unknown.
  virtual std::optional<Eigen::VectorXd> response(std::span<const std::string> /*args*/) const {
    return std::nullopt;
  }

 private:
  int tag_;
};

}  // namespace dabs::materials::section
