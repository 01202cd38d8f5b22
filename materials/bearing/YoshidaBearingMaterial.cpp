// SPDX-License-Identifier: MIT
#include "materials/bearing/YoshidaBearingMaterial.h"

#include <Eigen/LU>
#include <cassert>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

namespace {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;
using Row2 = Eigen::RowVector2d;

constexpr int kMaxSubsteps = 100000;  // more than this means a nonsensical trial deformation
constexpr int kMaxLocalIterations = 100;
constexpr double kLocalTolerance = 1e-15;  // relative change of |z| that ends the local Newton

void requireFinite(double v, const char* field) {
  if (!std::isfinite(v)) throw InputError(field, "must be a finite number");
}

/// Result of one backward Euler sub-step and its partial derivatives.
struct SubStep {
  Vec2 f1, s, z;
  double umax = 0.0;
  Mat2 dF_dU, dF_dDelta, dF_dFprev;  // d F1 / d(U, dU, F1_prev)
  Vec2 dF_dMprev;                    // d F1 / d Umax_prev
  Row2 dM_dU;                        // d Umax / d U
  double dM_dMprev = 0.0;            // d Umax / d Umax_prev
  bool converged = true;
};

/// One backward Euler sub-step from (F1_prev, Umax_prev) with end deformation `u` and increment
/// `delta`; `dir` is the unit direction used for d|delta|/d delta (delta/|delta|, or the defined
/// direction when delta = 0, or zero for the elastic one-sided derivative).
SubStep subStep(const YoshidaBearingMaterial::Params& p, const Vec2& u, const Vec2& delta,
                const Vec2& dir, const Vec2& fPrev, double mPrev, double& lastRatio,
                double& lastRatioQ) {
  SubStep r;
  const double un = u.norm();
  const bool umaxGrows = un > mPrev;
  r.umax = umaxGrows ? un : mPrev;
  r.dM_dU = umaxGrows ? Row2(u.transpose() / un) : Row2::Zero();
  r.dM_dMprev = umaxGrows ? 0.0 : 1.0;

  // Back-force factor a = max(0, alpha0 - beta (Umax/U0)^q): clipped at zero (class comment).
  const double ratio = r.umax / p.U0;
  // One pow for both: d(ratio^q)/d Umax = q ratio^q / ratio / U0. (lastRatio, lastRatioQ):
  // the material's cache of this pow, whose argument seldom changes.
  if (ratio > 0.0 && ratio != lastRatio) {
    lastRatio = ratio;
    lastRatioQ = std::pow(ratio, p.q);
  }
  const double ratioQ = ratio > 0.0 ? lastRatioQ : 0.0;
  double a = p.alpha0 - p.beta * ratioQ;
  double da_dM = (ratio > 0.0) ? -p.beta * p.q * ratioQ / ratio / p.U0 : 0.0;
  if (a <= 0.0) {
    a = 0.0;
    da_dM = 0.0;
  }
  const double Y = p.Y0 * (1.0 + p.gamma * (un / p.U0) * (un / p.U0));  // Yoshida hardening
  const Row2 dY_dU = 2.0 * p.Y0 * p.gamma * u.transpose() / (p.U0 * p.U0);
  const double d = delta.norm() / p.U0;
  const double opa = 1.0 + a;

  // Backward Euler: F1 = F1_prev + Y [delta/U0 - d |z|^(n-1) z], with F1 = Y (z + a U/U0)/(1+a)
  // from the back-force definition. Divided by Y: z/(1+a) + d |z|^(n-1) z = b.
  const Vec2 b = fPrev / Y + delta / p.U0 - a * u / (p.U0 * opa);
  const double bn = b.norm();
  Vec2 e = Vec2::Zero();
  double zeta = 0.0;
  // The last |z|^(n-1) the iteration formed and its zeta: the iteration usually stops on a step
  // it does not take, at the zeta the derivatives below need again.
  double lastZeta = -1.0, lastZn1 = 0.0;
  if (bn > 0.0) {
    e = b / bn;
    // Scalar equation phi(zeta) = zeta/(1+a) + d zeta^n - |b| = 0, phi increasing. For n >= 1 it
    // is convex, so Newton from an upper bound (each term alone reaching |b|) decreases
    // monotonically to the root; for n < 1 it is concave, so Newton from a lower bound (each term
    // at most |b|/2) increases monotonically to it.
    const double share = p.n >= 1.0 ? 1.0 : 0.5;
    zeta = share * bn * opa;
    if (p.n == 1.0) {
      // phi is linear: zeta (1/(1+a) + d) = |b|, solved without iteration or pow.
      zeta = bn / (1.0 / opa + d);
    } else if (d > 0.0) {
      zeta = std::min(zeta, std::pow(share * bn / d, 1.0 / p.n));
    }
    r.converged = p.n == 1.0;
    for (int it = 0; it < kMaxLocalIterations && !r.converged; ++it) {
      const double zn1 = std::pow(zeta, p.n - 1.0);
      lastZeta = zeta;
      lastZn1 = zn1;
      const double phi = zeta / opa + d * zn1 * zeta - bn;
      const double dphi = 1.0 / opa + p.n * d * zn1;
      const double step = phi / dphi;
      // The exact iteration moves one way only (down for n >= 1, up for n < 1): a step the other
      // way, or none, is round-off at the root.
      if (p.n >= 1.0 ? step <= 0.0 : step >= 0.0) {
        r.converged = true;
        break;
      }
      zeta = std::max(zeta - step, 0.0);
      if (std::abs(step) <= kLocalTolerance * (zeta + 1e-300)) {
        r.converged = true;
        break;
      }
    }
  }
  r.z = zeta * e;
  r.f1 = Y * (r.z + a * u / p.U0) / opa;
  r.s = a * (Y * u / p.U0 - r.f1);

  // Implicit differentiation of res(z; U, delta, F1_prev, Umax_prev) = z/(1+a) + d g(z) - b = 0.
  // For n < 1, dg/dz is unbounded at z = 0: there (b = 0, a point of no interest but reachable)
  // z does not move to first order, J^-1 = 0.
  const bool singular = p.n < 1.0 && zeta == 0.0;
  const double zn1 = singular           ? 0.0
                     : p.n == 1.0       ? 1.0
                     : zeta == lastZeta ? lastZn1
                                        : std::pow(zeta, p.n - 1.0);
  const Vec2 g = zn1 * r.z;                                                   // |z|^(n-1) z
  const Mat2 G = zn1 * (Mat2::Identity() + (p.n - 1.0) * e * e.transpose());  // dg/dz
  const Mat2 J = Mat2::Identity() / opa + d * G;
  // J is symmetric positive definite (eigenvalues 1/(1+a) + d |z|^(n-1) {n, 1})
  const Mat2 Jinv = (singular && d > 0.0) ? Mat2::Zero() : Mat2(J.inverse());
  const Vec2 res_a = (u / p.U0 - r.z) / (opa * opa);
  const Vec2 res_Y = fPrev / (Y * Y);
  const Mat2 res_U = a / (p.U0 * opa) * Mat2::Identity() + res_a * da_dM * r.dM_dU + res_Y * dY_dU;
  const Mat2 res_delta = (-Mat2::Identity() + g * dir.transpose()) / p.U0;
  const Mat2 res_F = -Mat2::Identity() / Y;
  const Vec2 res_M = res_a * da_dM * r.dM_dMprev;

  // F1 = Phi(z, U, a, Y) = Y (z + a U/U0)/(1+a).
  const double phi_z = Y / opa;
  const Vec2 phi_a = Y * res_a;
  const Vec2 phi_Y = r.f1 / Y;
  r.dF_dU = -phi_z * Jinv * res_U + (Y * a / (p.U0 * opa)) * Mat2::Identity() +
            phi_a * da_dM * r.dM_dU + phi_Y * dY_dU;
  r.dF_dDelta = -phi_z * Jinv * res_delta;
  r.dF_dFprev = -phi_z * Jinv * res_F;
  r.dF_dMprev = -phi_z * Jinv * res_M + phi_a * da_dM * r.dM_dMprev;
  return r;
}

}  // namespace

void YoshidaBearingMaterial::Params::validate() const {
  requireFinite(Y0, "Y0");
  requireFinite(U0, "U0");
  requireFinite(n, "n");
  requireFinite(alpha0, "alpha0");
  requireFinite(beta, "beta");
  requireFinite(q, "q");
  requireFinite(gamma, "gamma");
  requireFinite(k, "k");
  requireFinite(eta, "eta");
  requireFinite(maxSubIncrement, "subIncrement");
  if (Y0 <= 0.0) throw InputError("Y0", "must be positive");
  if (U0 <= 0.0) throw InputError("U0", "must be positive");
  if (n <= 0.0) throw InputError("n", "must be positive");
  if (alpha0 < 0.0) throw InputError("alpha0", "must not be negative");
  if (beta < 0.0) throw InputError("beta", "must not be negative");
  if (q <= 0.0) throw InputError("q", "must be positive");
  if (gamma < 0.0) throw InputError("gamma", "must not be negative");
  if (k < 0.0) throw InputError("k", "must not be negative");
  if (eta < 0.0) throw InputError("eta", "must not be negative");
  if ((k > 0.0) != (eta > 0.0))
    throw InputError("eta", "and k must both be positive (Maxwell part) or both zero (none)");
  if (maxSubIncrement <= 0.0) throw InputError("subIncrement", "must be positive");
}

YoshidaBearingMaterial::YoshidaBearingMaterial(int tag, const Params& p)
    : BiaxialMaterial(tag), p_(p) {
  assert(p.Y0 > 0.0 && p.U0 > 0.0 && p.n > 0.0 && p.maxSubIncrement > 0.0);
  revertToStart();
}

YoshidaBearingMaterial::State YoshidaBearingMaterial::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  return s;
}

Eigen::Matrix2d YoshidaBearingMaterial::getInitialTangent() const {
  // Elastic slope of the hysteretic part is Y0/U0 for any back-force factor; the Maxwell part
  // acts as its spring k for an instantaneous change.
  return (p_.Y0 / p_.U0 + p_.k) * Mat2::Identity();
}

Status YoshidaBearingMaterial::setTrialStrain(const Eigen::Vector2d& strain,
                                              const Eigen::Vector2d& strainRate, double dt) {
  const State& c = committed_;
  State& t = trial_;
  if (!strain.allFinite() || !std::isfinite(dt)) return Status::NonFinite;
  const Vec2 du = strain - c.u;
  const double dun = du.norm();
  const double steps = std::ceil(dun / (p_.maxSubIncrement * p_.U0));
  if (steps > kMaxSubsteps) return Status::NotConverged;
  const int m = std::max(1, static_cast<int>(steps));

  // Direction of d|dU|/d dU: the increment itself, or a defined direction when it is zero.
  Vec2 dir = Vec2::Zero();
  if (dun > 0.0) {
    dir = du / dun;
  } else if (strainRate.allFinite() && strainRate.norm() > 0.0) {
    dir = strainRate.normalized();
  } else if (c.z.norm() > 0.0) {
    dir = c.z.normalized();
  }

  // Hysteretic part, sub-step by sub-step, with sensitivities to the trial deformation.
  Vec2 f = c.f1;
  double umax = c.umax;
  Mat2 dF = Mat2::Zero();  // d F1_j / d U_trial
  Row2 dM = Row2::Zero();  // d Umax_j / d U_trial
  const Vec2 delta = du / m;
  double work = c.work;
  SubStep r;
  for (int j = 1; j <= m; ++j) {
    const double frac = static_cast<double>(j) / m;
    const Vec2 uj = (j == m) ? Vec2(strain) : Vec2(c.u + frac * du);
    r = subStep(p_, uj, delta, dir, f, umax, ratioPower_.ratio, ratioPower_.power);
    if (!r.converged) return Status::NotConverged;
    const Mat2 dFnew = r.dF_dU * frac + r.dF_dDelta / m + r.dF_dFprev * dF + r.dF_dMprev * dM;
    dM = r.dM_dU * frac + r.dM_dMprev * dM;
    dF = dFnew;
    work += 0.5 * (f + r.f1).dot(delta);
    f = r.f1;
    umax = r.umax;
  }

  // Maxwell part: exact for a constant rate over the step.
  Vec2 f2 = Vec2::Zero();
  double k2 = 0.0;
  if (p_.k > 0.0) {
    if (dt > 0.0) {
      const double h = dt * p_.k / p_.eta;
      const double oneMinusE = -std::expm1(-h);
      k2 = p_.k * oneMinusE / h;
      f2 = (1.0 - oneMinusE) * c.f2 + k2 * du;
    } else {
      k2 = p_.k;
      f2 = c.f2 + k2 * du;
    }
  }
  work += 0.5 * (c.f2 + f2).dot(du);

  t.u = strain;
  t.f1 = f;
  t.f2 = f2;
  t.s = r.s;
  t.z = r.z;
  t.umax = umax;
  t.work = work;
  t.tangent = dF + k2 * Mat2::Identity();
  if (!t.f1.allFinite() || !t.tangent.allFinite()) return Status::NonFinite;
  return Status::Ok;
}

std::unique_ptr<BiaxialMaterial> YoshidaBearingMaterial::clone() const {
  return std::make_unique<YoshidaBearingMaterial>(*this);
}

std::optional<Eigen::VectorXd> YoshidaBearingMaterial::response(std::string_view name) const {
  if (name == "hystereticForce") return Eigen::VectorXd(trial_.f1);
  if (name == "viscousForce") return Eigen::VectorXd(trial_.f2);
  if (name == "backForce") return Eigen::VectorXd(trial_.s);
  if (name == "z") return Eigen::VectorXd(trial_.z);
  if (name == "dissipatedEnergy") return Eigen::VectorXd::Constant(1, trial_.work);
  if (name == "maxDeformation") return Eigen::VectorXd::Constant(1, trial_.umax);
  return std::nullopt;
}

}  // namespace dabs::materials
