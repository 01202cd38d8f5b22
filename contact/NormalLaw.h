// SPDX-License-Identifier: MIT
#pragma once

#include <limits>

namespace dabs::contact {

/// Normal contact law of Zhu, Abe and Fujino (2002, EESD 31:1891, eqs. for the contact spring and
/// dashpot): a penalty spring K (= EA/L of the contactor body) in parallel with a dashpot whose
/// damping ratio reproduces a coefficient of restitution e for a head-on impact of masses M1, M2:
///   xi = -ln e / sqrt(pi^2 + ln^2 e),   C = 2 xi sqrt(K M1 M2 / (M1 + M2)).
/// (The xi(e) relation is the exact one for a linear spring-dashpot that may pull, contact lasting
/// half a damped period: e = exp(-xi pi / sqrt(1 - xi^2)).)
///
/// Sign conventions: gap g > 0 open, g < 0 penetration; gdot = dg/dt (< 0 approaching). The normal
/// force N is compressive-positive: N = -K g - C gdot while g < 0.
///
/// No tension: when the spring plus dashpot force would pull (N < 0, which happens while the
/// bodies separate), N = 0. Contact therefore ends when the force reaches zero, before the
/// penetration does, so the effective restitution is larger than e: for an SDOF with damping
/// ratio xi, contact ends at omega_d t* = pi - atan(2 xi sqrt(1 - xi^2) / (1 - 2 xi^2)) and
///   e_eff = exp(-xi omega t*) (xi / sqrt(1 - xi^2) sin(omega_d t*) - cos(omega_d t*))
/// (effectiveRestitution() evaluates it; the tests check it against a direct integration).
class NormalLaw {
 public:
  struct Params {
    double K = 0.0;   ///< penalty stiffness (force/length), > 0
    double e = 1.0;   ///< coefficient of restitution in [0, 1]; 1 = no dashpot
    double M1 = 0.0;  ///< mass of body 1 (needed when e < 1), > 0
    double M2 = 0.0;  ///< mass of body 2 (needed when e < 1), > 0
    /// Throws InputError{field, reason}.
    void validate() const;
  };

  explicit NormalLaw(const Params& p);

  /// Damping ratio for a restitution coefficient e in [0, 1]: -ln e / sqrt(pi^2 + ln^2 e).
  static double dampingRatio(double e);
  /// Effective restitution of an SDOF impact with damping ratio xi when the force cannot pull.
  static double effectiveRestitution(double xi);

  double stiffness() const noexcept { return K_; }
  /// Dashpot coefficient C (force per velocity).
  double damping() const noexcept { return C_; }

  /// Compressive normal force for gap g and gap rate gdot; zero when open or when it would pull.
  template <class T>
  T force(const T& g, const T& gdot) const {
    if (!(g < 0.0)) return T(0.0);
    T n = -K_ * g - C_ * gdot;
    if (!(n > 0.0)) return T(0.0);
    return n;
  }

 private:
  double K_;
  double C_;
};

}  // namespace dabs::contact
