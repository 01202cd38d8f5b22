// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string_view>

#include "materials/BiaxialMaterial.h"

namespace dabs::materials {

/// Bi-axial hysteresis of a laminated rubber bearing after Yoshida, Takesada, Abe and Fujino
/// (1999), in the form used by DABS. With U the shear deformation (2-vector in the bearing's shear
/// plane) and F = F1 + F2 the shear force:
///
///   dF1 / Y = dU / U0 - (|dU| / U0) |z|^(n-1) z,      z = (F1 - S) / Y           (hysteretic part)
///   S / Y   = (U / U0 - F1 / Y) a,   a = max(0, alpha0 - beta (Umax / U0)^q)      (back force)
///   Y       = Y0 (1 + gamma (|U| / U0)^2)                                          (hardening)
///   F2 = k U_spring = eta dU_dashpot / dt,  U_spring + U_dashpot = U              (Maxwell part)
///
/// Umax is the largest |U| reached so far. The back-force factor a is clipped at zero: a negative
/// alpha0 - beta (Umax/U0)^q would turn the back force against the deformation, so once Umax
/// passes U0 (alpha0/beta)^(1/q) the back force vanishes instead of changing sign.
///
/// Integration (setTrialStrain, always from the committed state):
/// - hysteretic part: backward Euler in sub-steps of at most `maxSubIncrement * U0` along the
///   straight path from the committed to the trial deformation, Y and a at the end of each
///   sub-step. Each sub-step is solved exactly by a local Newton iteration: the backward Euler
///   equation  z/(1+a) + (|dU|/U0) |z|^(n-1) z = b  makes z parallel to b, so only the scalar
///   |z| is unknown; that scalar equation is increasing, convex for n >= 1 and concave for n < 1,
///   so Newton started from an upper (n >= 1) or a lower (n < 1) bound converges monotonically.
/// - Maxwell part: exact solution of dF2/dt + F2/tau = k dU/dt (tau = eta/k) for a deformation
///   rate constant over the step, dU/dt = (U - U_committed)/dt. With dt = 0 (a static step) the
///   dashpot does not move and the Maxwell part is a spring k.
/// - tangent: the consistent algorithmic tangent of the discrete map above (sensitivities are
///   carried through the sub-steps). Where |dU| = 0 the map has a kink; the tangent returned there
///   is the one-sided derivative for motion in a defined direction: the given deformation rate when
///   it is non-zero, else the committed hysteretic state z (continued loading), else elastic.
///
/// Accuracy: first order in the sub-step size (backward Euler). On a figure-eight path of amplitude
/// 4 U0 (with back force and hardening) the largest force error against a 1e-4 U0 integration is
/// about 0.3-0.4 Y0 per unit sub-step/U0, i.e. below 1 % of Y0 at the default 0.02 U0
/// (YoshidaBearingMaterialTest.StepSizeStudyShowsFirstOrder).
///
/// Units: U, U0 length; Y0, F force; k force/length; eta force*time/length.
class YoshidaBearingMaterial final : public BiaxialMaterial {
 public:
  /// Model parameters (see the class comment for the equations).
  struct Params {
    double Y0 = 0.0;      ///< characteristic (yield) force at small strain (force)
    double U0 = 0.0;      ///< yield deformation; Y0/U0 is the initial stiffness (length)
    double n = 2.0;       ///< smoothness exponent, > 0 (n < 1: a long, gradual approach to yield)
    double alpha0 = 0.0;  ///< back-force factor in the virgin state, >= 0
    double beta = 0.0;    ///< decay of the back-force factor with Umax, >= 0
    double q = 1.0;       ///< exponent of that decay, > 0
    double gamma = 0.0;   ///< hardening of Y at large deformation, >= 0
    double k = 0.0;       ///< Maxwell spring stiffness (0 = no Maxwell part)
    double eta = 0.0;     ///< Maxwell dashpot coefficient (0 = no Maxwell part)
    /// Largest sub-step as a fraction of U0 (accuracy control of the hysteretic integration).
    double maxSubIncrement = 0.02;

    /// Throws InputError{field, reason} for a parameter set that cannot make a valid model.
    void validate() const;
  };

  /// Everything the material remembers; trial and committed copies (style.md section 2).
  struct State {
    Eigen::Vector2d u = Eigen::Vector2d::Zero();   ///< deformation U
    Eigen::Vector2d f1 = Eigen::Vector2d::Zero();  ///< hysteretic force F1
    Eigen::Vector2d f2 = Eigen::Vector2d::Zero();  ///< Maxwell (viscous) force F2
    Eigen::Vector2d s = Eigen::Vector2d::Zero();   ///< back force S
    Eigen::Vector2d z = Eigen::Vector2d::Zero();   ///< hysteretic variable z = (F1 - S)/Y
    double umax = 0.0;                             ///< largest |U| so far
    double work = 0.0;  ///< work of F on U (trapezoidal), = dissipated energy over closed cycles
    Eigen::Matrix2d tangent = Eigen::Matrix2d::Zero();  ///< dF/dU of the last trial
  };

  /// `p` must be valid (Params::validate()); the constructor only asserts.
  YoshidaBearingMaterial(int tag, const Params& p);

  [[nodiscard]] Status setTrialStrain(const Eigen::Vector2d& strain,
                                      const Eigen::Vector2d& strainRate, double dt) override;
  Eigen::Vector2d getStrain() const override { return trial_.u; }
  Eigen::Vector2d getStress() const override { return trial_.f1 + trial_.f2; }
  Eigen::Matrix2d getTangent() const override { return trial_.tangent; }
  Eigen::Matrix2d getInitialTangent() const override;

  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override { trial_ = committed_ = initialState(); }

  [[nodiscard]] std::unique_ptr<BiaxialMaterial> clone() const override;

  /// "hystereticForce", "viscousForce", "backForce" (2 values each), "z" (2),
  /// "dissipatedEnergy" (1), "maxDeformation" (1); trial values.
  std::optional<Eigen::VectorXd> response(std::string_view name) const override;

  const Params& params() const noexcept { return p_; }
  const State& trialState() const noexcept { return trial_; }
  const State& committedState() const noexcept { return committed_; }

 private:
  State initialState() const;

  Params p_;
  State trial_{};
  State committed_{};
  /// (Umax/U0)^q at the last ratio it was formed for: not state but a cache of a pure function.
  /// Umax stays at its committed value in most sub-steps (it grows only on a new largest
  /// deformation), and pow is much of this law's cost; the same ratio gives the same bits.
  struct RatioPower {
    double ratio = -1.0;
    double power = 0.0;
  } ratioPower_;
};

}  // namespace dabs::materials
