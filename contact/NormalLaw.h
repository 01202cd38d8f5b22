// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace dabs::contact {

/// The impact laws a contact pair can use (Tcl `-law`).
enum class ImpactLaw : std::uint8_t { Kelvin, Hertz, HertzDamp, Jankowski };

/// Normal contact law, a small const strategy chosen by ImpactLaw (one class, one switch: the
/// element's hot path stays one call templated on the AD scalar). Notation: delta = -g > 0 the
/// penetration, deltadot = -gdot its rate (compression positive), m = M1 M2 / (M1 + M2).
///
/// - kelvin (default; Zhu, Abe and Fujino 2002, EESD 31:1891, contact spring and dashpot):
///   N = K delta + C deltadot, C = 2 xi sqrt(K m), xi = -ln e / sqrt(pi^2 + ln^2 e)
///   (the exact xi(e) of a linear spring-dashpot that may pull, contact lasting half a damped
///   period: e = exp(-xi pi / sqrt(1 - xi^2))).
/// - hertz (Hertz contact of spheres, e.g. Goldsmith 1960): N = k_h delta^n, n = 1.5 by default;
///   k_h in force / length^n. Elastic: e = 1.
/// - hertzdamp (Muthukumar and DesRoches 2006, EESD 35:811, "Hertz contact model with non-linear
///   damping"): N = k_h delta^n + c_h delta^n deltadot with the Hunt-Crossley damping of
///   Lankarani and Nikravesh (1990, J. Mech. Des. 112:369, eq. 25), c_h = 3 k_h (1 - e^2) /
///   (4 v0), v0 the approach speed the damping is tuned to. Muthukumar and DesRoches build on
///   this relation. Its derivation assumes e near 1 (energy loss from the elastic path), so the
///   restitution it gives is approximate and, with the no-tension clip, above e: at v = v0 a
///   direct integration gives 0.756 for e = 0.6, 0.847 for 0.8, 0.913 for 0.9, 0.954 for 0.95
///   (NormalLawTest), and e falls as the impact speed exceeds v0 (Ye, Li and Zhu 2009, EESD
///   38:1135, point out the error and give a better c_h for low e). We could not read the paper
///   itself here, so this is the relation it is known to build on, not a transcription.
/// - jankowski (Jankowski 2005, EESD 34:595, non-linear viscoelastic model):
///   N = beta delta^1.5 + c(t) deltadot while approaching (deltadot > 0), N = beta delta^1.5
///   while separating, c(t) = 2 xi sqrt(beta sqrt(delta) m); xi from e by Jankowski (2006, EESD
///   35:517, eq. 17): xi = 9 sqrt(5) (1 - e^2) / (2 e (e (9 pi - 16) + 16)) (his analytical
///   relation for this model, within 0.006 of e for e in [0.5, 0.8] by direct integration, and
///   independent of the impact speed). We could not read the 2005 paper's own xi(e) here.
///
/// Sign conventions: gap g > 0 open, g < 0 penetration; gdot = dg/dt (< 0 approaching). N is
/// compressive-positive. No tension: where the law would pull (dashpot while separating) N = 0,
/// and N = 0 when open. closedForce() is the law without the clip (the element's held closed
/// branch); for the power laws it continues to g > 0 as the odd extension delta |delta|^(n-1)
/// (hertzdamp's damping term likewise; jankowski's coefficient c uses |delta|^(1/4)).
class NormalLaw {
 public:
  struct Params {
    double K = 0.0;   ///< K (kelvin, force/length) or k_h / beta (force/length^n), > 0
    double e = 1.0;   ///< coefficient of restitution: kelvin [0, 1]; hertzdamp, jankowski (0, 1]
    double M1 = 0.0;  ///< mass of body 1 (kelvin when e < 1, jankowski), > 0
    double M2 = 0.0;  ///< mass of body 2 (kelvin when e < 1, jankowski), > 0
    ImpactLaw law = ImpactLaw::Kelvin;  ///< which law
    double n = 1.5;                     ///< exponent of hertz and hertzdamp (jankowski: 1.5), > 0
    double v0 = 0.0;  ///< hertzdamp: approach speed the damping is tuned to (length/time), > 0
    /// Throws InputError{field, reason} (fields K, e, M1, M2, n, v0).
    void validate() const;
  };

  explicit NormalLaw(const Params& p);

  /// Damping ratio for a restitution coefficient e in [0, 1]: -ln e / sqrt(pi^2 + ln^2 e).
  static double dampingRatio(double e);
  /// Effective restitution of an SDOF impact with damping ratio xi when the force cannot pull.
  static double effectiveRestitution(double xi);
  /// Jankowski's (2006, eq. 17) impact damping ratio for restitution e in (0, 1].
  static double jankowskiDampingRatio(double e);
  /// Lankarani and Nikravesh's (1990) hysteresis damping factor 3 k (1 - e^2) / (4 v0).
  static double hysteresisDamping(double k, double e, double v0);
  /// Lower-case Tcl name of a law (kelvin, hertz, hertzdamp, jankowski).
  static const char* name(ImpactLaw law) noexcept;

  ImpactLaw law() const noexcept { return law_; }
  /// K (kelvin) or k_h / beta (power laws).
  double stiffness() const noexcept { return K_; }
  /// Power of the spring: 1 for kelvin, n for hertz and hertzdamp, 1.5 for jankowski.
  double exponent() const noexcept { return n_; }
  /// Kelvin's dashpot C; hertzdamp's c_h; jankowski's 2 xi sqrt(beta m) (c = that x delta^1/4).
  double damping() const noexcept { return C_; }
  /// True when N depends on the gap rate (the damping tangent is then nonzero).
  bool velocityDependent() const noexcept { return C_ > 0.0; }

  /// Elastic part of N at gap g: K delta^n for delta > 0, else 0.
  double elasticForce(double g) const {
    if (law_ == ImpactLaw::Kelvin) return K_ * std::max(-g, 0.0);
    return g < 0.0 ? K_ * std::pow(-g, n_) : 0.0;
  }
  /// Energy the spring holds at gap g: K delta^(n+1) / (n+1).
  double storedEnergy(double g) const {
    return g < 0.0 ? K_ * std::pow(-g, n_ + 1.0) / (n_ + 1.0) : 0.0;
  }

  /// The law without the no-tension clip (any sign of g; see the class comment).
  template <class T>
  T closedForce(const T& g, const T& gdot) const {
    if (law_ == ImpactLaw::Kelvin) return -K_ * g - C_ * gdot;
    const T delta = -g;
    const T s = signedPower(delta, n_);
    T n = K_ * s;
    if (law_ == ImpactLaw::HertzDamp) {
      n -= C_ * s * gdot;  // Muthukumar and DesRoches (2006): k_h delta^n (1 + c_h deltadot / k_h)
    } else if (law_ == ImpactLaw::Jankowski && gdot < 0.0 && delta != 0.0) {
      using std::abs;
      using std::pow;
      n -= C_ * pow(abs(delta), 0.25) * gdot;  // Jankowski (2005): c(t) deltadot, approach only
    }
    return n;
  }

  /// Length of Newton's step, as a multiple of the step it took, that Newton on the force
  /// variable w = delta |delta|^(n-1) would have taken (n the spring's exponent), for an iterate
  /// that shrank a closed pair's penetration from `delta` (> 0) by `-change` (> 0); outside the
  /// face, on a held closed force's odd continuation, the distance to the face and its change.
  /// On a spring k delta^n with n > 1, Newton from a penetration far deeper than the end
  /// state's removes only 1/n of it an iteration (two thirds for n = 1.5, leaving a third: 12
  /// to 14 iterations from a step's trial penetration of 1e-3 m to an end state of 1e-7 to
  /// 1e-9 m). In w the spring is linear, and Newton's step in w is dw = n delta^(n-1) change
  /// exactly, whatever else the residual holds (d/dw = d/ddelta delta / (n w)), so the
  /// penetration it gives is delta^((n-1)/n) (delta + n change)^(1/n) when delta + n change > 0.
  /// Otherwise the step in w crosses the face: for a force smooth across it (`smoothAcross`:
  /// the spring's odd continuation, hertzdamp's damping c_h delta^n gdot) to the same distance
  /// on the other side; where it is not (Jankowski's damping c |delta|^(1/4) gdot, concave in
  /// w, whose cusp at the face makes Newton in w overshoot) to a tenth of the penetration
  /// (Newton's own step leaves a third of it for n = 1.5). Returns 1 (no opinion) for n <= 1
  /// and where Newton removed less than three quarters of the 1/n it removes far from the end
  /// state (half of the penetration for n = 1.5); otherwise the scale, in [1, n].
  double forceVariableStepScale(double delta, double change, bool smoothAcross) const {
    if (!(n_ > 1.0) || !(delta > 0.0) || !slowShrink(delta, change)) return 1.0;
    const double rest = delta + n_ * change;
    const double size = std::pow(delta, (n_ - 1.0) / n_) * std::pow(std::abs(rest), 1.0 / n_);
    const double target = rest > 0.0 ? size : smoothAcross ? -size : 0.1 * delta;
    return std::clamp((target - delta) / change, 1.0, n_);
  }
  /// True when a Newton step that changed a penetration `delta` (> 0) by `change` removed at
  /// least three quarters of delta / n (n > 1): the step of Newton far from the end state on a
  /// spring k delta^n (forceVariableStepScale).
  bool slowShrink(double delta, double change) const {
    return n_ > 1.0 && change <= -0.75 * delta / n_;
  }

  /// Compressive normal force for gap g and gap rate gdot; zero when open or when it would pull.
  template <class T>
  T force(const T& g, const T& gdot) const {
    if (!(g < 0.0)) return T(0.0);
    T n = closedForce(g, gdot);
    if (!(n > 0.0)) return T(0.0);
    return n;
  }

  /// Force of the release step (closed at the last commit with gap gn < 0 and normal force Nn,
  /// open at gap g >= 0), chosen so that the step's trapezoid work 0.5 (Nn + N) (delta_n + g)
  /// equals the energy of unloading along the law's spring from N_r = min(Nn, K delta_n^n),
  /// N_r delta_n / (n + 1) (= K delta_n^(n+1) / (n+1) when Nn is the spring force):
  ///   N = -N_r g / (g - gn) - N_r (n - 1)/(n + 1) delta_n / (g - gn)
  /// (for n = 1 the Kelvin release force, zero at g = 0; for n > 1 tensile already at g = 0,
  /// N = -tail, tail = N_r (n - 1) / (n + 1): with the committed force at the start of the
  /// step, the trapezoid gives back the stored energy only if the end force pulls). `held`
  /// continues it inside the face (g < 0; the formula has a pole at gn): Kelvin along its
  /// tangent at g = 0, N_r g / gn (so does a power law with n <= 1, whose release force has no
  /// jump at the face); a power law with n > 1 along the ramp N = -tail (1 + g / w),
  /// w = kRampWidth |gn|, which bridges the jump from the closed force (zero at the face) to
  /// the release force (-tail there). A release step whose end state lies in that jump, at the
  /// face with a tension between 0 and tail (Filippov's set-valued selection), has no end state
  /// on the closed force nor on the release force; Newton converged inside the face on the
  /// release force's tangent continuation and outside it on the closed force's, in turn, until
  /// the step failed. On the ramp (onReleaseRamp) the held release branch holds that end state,
  /// within w of the face. Its work then exceeds the stored energy by at most
  /// 0.5 tail delta_n (0.1 N_r delta_n for n = 1.5), in a step that does not resolve the
  /// contact.
  template <class T>
  T releaseForce(const T& g, double gn, double Nn, bool held) const {
    if (law_ == ImpactLaw::Kelvin) {
      const double Nr = std::min(Nn, -K_ * gn);
      if (held && g < 0.0) return Nr * g / gn;
      return -Nr * g / (g - gn);
    }
    const double Nr = std::min(Nn, elasticForce(gn));
    const double tail = Nr * (n_ - 1.0) / (n_ + 1.0);  // -N at g = 0
    if (held && g < 0.0) {
      if (n_ > 1.0) return -tail * (1.0 - g / (kRampWidth * gn));
      return -tail + 2.0 * Nr / (n_ + 1.0) * g / gn;  // n <= 1: no jump, its tangent at g = 0
    }
    return (-Nr * g + tail * gn) / (g - gn);
  }
  /// Width of the held release force's ramp inside the face, as a fraction of the committed
  /// penetration |gn|. For n = 1.5: an end state on the ramp starts the next step with at most
  /// 0.1 % of the released force (0.01^1.5) in the closed law, and the ramp's slope,
  /// 0.2 N_r / (0.01 |gn|), is 20 times the spring's secant N_r / |gn| (the tangent
  /// continuation the held branch had before, zero at (n - 1) / 2 |gn|, was a ramp 25 times as
  /// wide: an end state there would start the next step with 12.5 % of it).
  static constexpr double kRampWidth = 0.01;
  /// True when a power law's (n > 1) held release force N at gap g lies on its ramp inside the
  /// face (-w <= g < 0, -tail <= N <= 0): the end state in the jump (releaseForce).
  bool onReleaseRamp(double g, double N) const {
    return law_ != ImpactLaw::Kelvin && n_ > 1.0 && g < 0.0 && N <= 0.0;
  }

 private:
  /// delta |delta|^(p-1) with a zero (and zero derivative) at delta = 0.
  template <class T>
  static T signedPower(const T& delta, double p) {
    using std::abs;
    using std::pow;
    if (delta == 0.0) return T(0.0);
    const T a = pow(abs(delta), p);
    return delta > 0.0 ? a : T(-a);
  }

  ImpactLaw law_;
  double K_;
  double C_;
  double n_;
};

}  // namespace dabs::contact
