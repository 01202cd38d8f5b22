// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <memory>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials {

/// The response of a material point: all a fiber section keeps of a fiber's trial state.
struct StressTangent {
  double stress = 0.0, tangent = 0.0;
};

/// The responses of an array of fibers: stresses and tangents in two arrays, so that four fibers'
/// stresses (or tangents) are one vector in memory.
struct Responses {
  double* stress = nullptr;
  double* tangent = nullptr;

  void set(std::size_t i, double s, double t) const {
    stress[i] = s;
    tangent[i] = t;
  }
  /// The responses from fiber k on.
  Responses from(std::size_t k) const { return {stress + k, tangent + k}; }
};

/// Keeps a material's whole history in one value struct, so commit, revert and revertToStart are
/// one assignment each and adding a history variable means editing one struct (style.md section 2;
/// compare peer-open-source/xara BoucWenMG `cState = tState`).
///
/// `State` must be a copyable aggregate holding `strain`, `stress`, `tangent` (unless the stress
/// does not depend on the strain) and every history
/// variable. The derived class fills `trial_` in setTrialStrain, starting from `committed_`.
/// `Derived` is the material itself (it names the type `clone` copies), so the trial getters and
/// `clone` are written here once for every material with a value state.
template <class Derived, class State>
class StatefulUniaxial : public UniaxialMaterial {
 public:
  using UniaxialMaterial::UniaxialMaterial;

  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  /// A state without a `tangent` member (a pure dashpot) has no stiffness.
  double getTangent() const override {
    if constexpr (requires(const State& s) { s.tangent; }) {
      return trial_.tangent;
    } else {
      return 0.0;
    }
  }

  void commitState() final { committed_ = trial_; }
  void revertToLastCommit() final { trial_ = committed_; }
  void revertToStart() final { trial_ = committed_ = initialState(); }

  /// A copy of the material with its parameters and its trial and committed states.
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<Derived>(static_cast<const Derived&>(*this));
  }

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
