// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

#include "materials/friction/CoulombCone.h"

namespace dabs::contact {

/// Coulomb friction as a return map with stick memory (style.md section 3; Zhu, Abe and Fujino
/// 2002 for the stick/slide split and the static/kinetic coefficients). The return map itself is
/// materials::CoulombCone, shared with the seat of a dropped yoshidaBearing; this class adds the
/// contact's parameters (restitution and masses for the dashpot).
///
/// A tangential spring Kt joins the contactor to its stick point, a material point of the target
/// kept in the element's committed state, and a dashpot Ct acts on the relative tangential
/// velocity v_t. With d the in-plane elastic displacement of the contactor from the stick point
/// (trial), the elastic predictor is F_tr = -Kt d - Ct v_t (force on the contactor). Stick while
/// |F_tr| <= mu N, with mu = mu_s when the last committed state was not sliding and mu_k when it
/// was (so steady sliding does not chatter between mu_s and mu_k); then F = F_tr. Slide otherwise:
/// F = mu_k N F_tr / |F_tr| and the stick point moves so that the spring alone sits on the
/// friction limit, d_new = -F / Kt (not reset to zero). The plastic slip |d - d_new| times mu_k N
/// is the dissipated work, >= 0.
///
/// Differences from Zhu, Abe and Fujino (2002), stated because they change results: (1) the cone
/// bounds the whole tangential force, spring plus dashpot (Zhu et al. test the spring force only,
/// so a fast-sliding contactor could stick with a dashpot force far above mu N); (2) N is the
/// compressive normal force of NormalLaw (spring plus dashpot, never negative), so the friction
/// impulse over a sliding impact is mu times the normal impulse (Zhu et al. use |F_k|n|); (3) the
/// slide direction is that of the trial force, not of the relative velocity (the two agree in the
/// limit of small steps).
class CoulombFriction {
 public:
  struct Params {
    double Kt = 0.0;   ///< tangential penalty stiffness (force/length), > 0
    double et = 1.0;   ///< tangential restitution in [0, 1]; 1 = no tangential dashpot
    double muS = 0.0;  ///< static coefficient, >= 0
    double muK = 0.0;  ///< kinetic coefficient, 0 <= muK <= muS
    double M1 = 0.0;   ///< body masses for the dashpot (needed when et < 1)
    double M2 = 0.0;
    /// Throws InputError{field, reason}.
    void validate() const;
  };

  explicit CoulombFriction(const Params& p);

  /// False when both coefficients are zero (frictionless contact: no tangential force at all).
  bool active() const noexcept { return cone_.active(); }
  double stiffness() const noexcept { return cone_.Kt; }
  double damping() const noexcept { return cone_.Ct; }
  double staticCoefficient() const noexcept { return cone_.muS; }
  double kineticCoefficient() const noexcept { return cone_.muK; }

  template <class T>
  using Result = materials::CoulombCone::Result<T>;

  using Branch = materials::CoulombCone::Branch;

  /// Return map for trial elastic displacement d, normal force N >= 0 and relative tangential
  /// velocity vt (for the dashpot). `wasSliding` is the committed status; `branch` a held one.
  template <class T>
  Result<T> returnMap(const std::array<T, 2>& d, const T& N, const std::array<T, 2>& vt,
                      bool wasSliding, Branch branch = Branch::Natural) const {
    return cone_.returnMap(d, N, vt, wasSliding, branch);
  }

 private:
  materials::CoulombCone cone_;  ///< the pure law (materials/friction/CoulombCone.h)
};

}  // namespace dabs::contact
