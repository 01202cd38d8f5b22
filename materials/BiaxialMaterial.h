// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string_view>

#include "materials/Status.h"

namespace dabs::materials {

/// Two-component force-deformation law for coupled shear (a bearing's shear plane), with the same
/// trial/commit/revert protocol as UniaxialMaterial. Strain, stress and tangent are 2-vectors and a
/// 2x2 matrix in the element's local shear plane (y, z).
class BiaxialMaterial {
 public:
  explicit BiaxialMaterial(int tag) noexcept : tag_(tag) {}
  virtual ~BiaxialMaterial() = default;
  BiaxialMaterial(const BiaxialMaterial&) = default;
  BiaxialMaterial& operator=(const BiaxialMaterial&) = delete;

  /// User tag given in the `biaxialMaterial` command.
  int tag() const noexcept { return tag_; }

  /// Sets the trial deformation from the committed state. `dt` is the time since the last commit
  /// (zero in a static step), for rate-dependent parts such as a Maxwell dashpot.
  [[nodiscard]] virtual Status setTrialStrain(const Eigen::Vector2d& strain,
                                              const Eigen::Vector2d& strainRate, double dt) = 0;
  virtual Eigen::Vector2d getStrain() const = 0;
  virtual Eigen::Vector2d getStress() const = 0;
  /// d(stress)/d(strain) at the trial state (consistent algorithmic tangent).
  virtual Eigen::Matrix2d getTangent() const = 0;
  virtual Eigen::Matrix2d getInitialTangent() const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  [[nodiscard]] virtual std::unique_ptr<BiaxialMaterial> clone() const = 0;

  /// Extra named responses (e.g. "backForce"); none by default.
  virtual std::optional<Eigen::VectorXd> response(std::string_view /*name*/) const {
    return std::nullopt;
  }

 private:
  int tag_;
};

}  // namespace dabs::materials
