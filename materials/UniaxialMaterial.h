// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "materials/Status.h"

namespace dabs::materials {

/// One-dimensional stress-strain (or force-deformation) law with the OpenSees trial/commit/revert
/// protocol (OpenSees/OpenSees:SRC/material/uniaxial/UniaxialMaterial.h), made const-correct.
///
/// Contract (checked for every material by tests/MaterialContract.h):
/// - setTrialStrain always starts from the committed state: calling it with e1 then e2 equals e2
///   alone. It is the only mutator during iterations.
/// - getStrain/getStress/getTangent report the TRIAL state; they are const and compute nothing.
/// - commitState: committed = trial; revertToLastCommit: trial = committed; revertToStart: both =
///   initial. No other hidden state escapes this protocol.
class UniaxialMaterial {
 public:
  explicit UniaxialMaterial(int tag) noexcept : tag_(tag) {}
  virtual ~UniaxialMaterial() = default;
  UniaxialMaterial(const UniaxialMaterial&) = default;
  UniaxialMaterial& operator=(const UniaxialMaterial&) = delete;

  /// User tag given in the `uniaxialMaterial` command.
  int tag() const noexcept { return tag_; }

  /// Sets the trial strain (and strain rate, for rate-dependent laws) from the committed state.
  [[nodiscard]] virtual Status setTrialStrain(double strain, double strainRate = 0.0) = 0;
  /// Trial strain.
  virtual double getStrain() const = 0;
  /// Trial strain rate (zero for rate-independent laws).
  virtual double getStrainRate() const { return 0.0; }
  /// Trial stress.
  virtual double getStress() const = 0;
  /// d(stress)/d(strain) at the trial state (algorithmic tangent).
  virtual double getTangent() const = 0;
  /// d(stress)/d(strain rate) at the trial state: the material's own viscous tangent.
  virtual double getDampTangent() const { return 0.0; }
  /// Tangent of the virgin material.
  virtual double getInitialTangent() const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  /// Independent copy with the same parameters and the same committed and trial state.
  [[nodiscard]] virtual std::unique_ptr<UniaxialMaterial> clone() const = 0;

  /// True when an update at the strain of a state an update formed (the trial, or the committed
  /// state after a commit) leaves that state as it is, bit for bit: an element made of such
  /// materials whose nodes have not moved may then skip its update (a transient step's
  /// predictor, which moves the rates: the law's response must not depend on them, and the rate
  /// it records is then the last update's). False unless the law is shown to; the material
  /// contract test checks every law that says so.
  virtual bool keepsStateAtSameStrain() const { return false; }

  /// Extra named responses for recorders (e.g. "damage"); none by default.
  virtual std::optional<double> response(std::string_view /*name*/) const { return std::nullopt; }

 private:
  int tag_;
};

}  // namespace dabs::materials
