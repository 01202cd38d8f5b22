// SPDX-License-Identifier: MIT
#pragma once

#include "materials/UniaxialMaterial.h"

namespace dabs::materials {

/// Keeps a material's whole history in one value struct, so commit, revert and revertToStart are
/// one assignment each and adding a history variable means editing one struct (style.md section 2;
/// compare peer-open-source/xara BoucWenMG `cState = tState`).
///
/// `State` must be a copyable aggregate holding strain, stress, tangent and every history
/// variable. The derived class fills `trial_` in setTrialStrain, starting from `committed_`.
template <class State>
class StatefulUniaxial : public UniaxialMaterial {
 public:
  using UniaxialMaterial::UniaxialMaterial;

  void commitState() final { committed_ = trial_; }
  void revertToLastCommit() final { trial_ = committed_; }
  void revertToStart() final { trial_ = committed_ = initialState(); }

  /// Read-only access to the committed state, for tests and responses.
  const State& committedState() const noexcept { return committed_; }
  /// Read-only access to the trial state.
  const State& trialState() const noexcept { return trial_; }

 protected:
  /// The virgin state; derived constructors must call `revertToStart()` once parameters are set.
  virtual State initialState() const = 0;

  State trial_{};
  State committed_{};
};

}  // namespace dabs::materials
