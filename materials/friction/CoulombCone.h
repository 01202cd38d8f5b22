// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>

namespace dabs::materials {

/// Coefficients of a Coulomb friction law with stick memory: the pure law shared by the contact
/// pair (dabs::contact::CoulombFriction, which adds the restitution dashpot's parameters) and the
/// seat of a dropped yoshidaBearing (elements/link). It lives in materials/ so that elements may
/// use it (dependencies point one way: materials <- elements <- contact).
///
/// A tangential spring Kt joins the contactor to its stick point and a dashpot Ct acts on the
/// relative tangential velocity v_t. With d the in-plane elastic displacement of the contactor
/// from the stick point (trial), the elastic predictor is F_tr = -Kt d - Ct v_t (force on the
/// contactor). Stick while |F_tr| <= mu N, with mu = mu_s when the last committed state was not
/// sliding and mu_k when it was (so steady sliding does not chatter between mu_s and mu_k); then
/// F = F_tr. Slide otherwise: F = mu_k N F_tr / |F_tr| and the stick point moves so that the
/// spring alone sits on the friction limit, d_new = -F / Kt (not reset to zero). The plastic slip
/// |d - d_new| times mu_k N is the dissipated work, >= 0.
struct CoulombCone {
  double Kt = 0.0;   ///< tangential penalty stiffness (force/length), > 0
  double Ct = 0.0;   ///< tangential dashpot (force time/length), >= 0
  double muS = 0.0;  ///< static coefficient, >= 0
  double muK = 0.0;  ///< kinetic coefficient, 0 <= muK <= muS

  /// False when both coefficients are zero (frictionless: no tangential force at all).
  bool active() const noexcept { return muS > 0.0 || muK > 0.0; }

  template <class T>
  struct Result {
    std::array<T, 2> force;  ///< tangential force on the contactor (in-plane frame)
    bool sliding;            ///< true when the return map slid (the cone, or a held slide)
    Eigen::Vector2d
        elasticAfter;       ///< elastic displacement d after the return (places the stick point)
    double plasticSlip;     ///< |d_trial - d_after| (length)
    bool coneExceeded;      ///< the trial force exceeded the cone (the state's own branch)
    bool aboveKinetic;      ///< the trial force is at least mu_k N (a slide may be held)
    Eigen::Vector2d trial;  ///< value of the trial (elastic predictor) force
  };

  /// Which branch the return map takes: the state's own (the cone decides), or a held one
  /// (held statuses of the contact pair, elements::Element::HeldStatus).
  enum class Branch { Natural, Stick, Slide };

  /// Return map for trial elastic displacement d, normal force N >= 0 and relative tangential
  /// velocity vt (for the dashpot). `wasSliding` is the committed status. T is double or an
  /// automatic-differentiation scalar with value(). With a held `branch` the force is the trial
  /// force (Stick) or mu_k N along it (Slide) whatever the cone says.
  template <class T>
  Result<T> returnMap(const std::array<T, 2>& d, const T& N, const std::array<T, 2>& vt,
                      bool wasSliding, Branch branch = Branch::Natural) const {
    using std::sqrt;
    Result<T> r{{T(0.0), T(0.0)},       true, Eigen::Vector2d::Zero(), 0.0, true, true,
                Eigen::Vector2d::Zero()};
    if (!active()) return r;
    const std::array<T, 2> trial{-Kt * d[0] - Ct * vt[0], -Kt * d[1] - Ct * vt[1]};
    const Eigen::Vector2d trialValue(value(trial[0]), value(trial[1]));
    const Eigen::Vector2d dValue(value(d[0]), value(d[1]));
    r.trial = trialValue;
    const double limit = (wasSliding ? muK : muS) * value(N);
    r.coneExceeded = trialValue.norm() > limit;
    r.aboveKinetic = trialValue.norm() >= muK * value(N);
    const bool slide = branch == Branch::Natural ? r.coneExceeded : branch == Branch::Slide;
    if (!slide || trialValue.norm() == 0.0) {
      r.force = trial;
      r.sliding = false;
      r.elasticAfter = dValue;
      return r;
    }
    const T norm = sqrt(trial[0] * trial[0] + trial[1] * trial[1]);
    r.force = {muK * N * trial[0] / norm, muK * N * trial[1] / norm};
    r.elasticAfter = -Eigen::Vector2d(value(r.force[0]), value(r.force[1])) / Kt;
    r.plasticSlip = (dValue - r.elasticAfter).norm();
    return r;
  }

 private:
  static double value(double x) noexcept { return x; }
  template <class T>
  static double value(const T& x) noexcept {
    return x.value();
  }
};

}  // namespace dabs::materials
