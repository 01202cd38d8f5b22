// SPDX-License-Identifier: MIT
#include "elements/link/KumarVertical.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::elements {

namespace {

constexpr double kPi = std::numbers::pi;

void requireFinite(double v, const char* field) {
  if (!std::isfinite(v)) throw InputError(field, "must be a finite number");
}

}  // namespace

void KumarVertical::Params::validate() const {
  requireFinite(G, "G");
  requireFinite(Kbulk, "Kbulk");
  requireFinite(Di, "Di");
  requireFinite(Do, "Do");
  requireFinite(ts, "ts");
  requireFinite(tr, "tr");
  requireFinite(n, "n");
  requireFinite(tc, "tc");
  requireFinite(kc, "kc");
  requireFinite(phi, "phi");
  requireFinite(ac, "ac");
  if (G <= 0.0) throw InputError("G", "(shear modulus) must be positive");
  if (Kbulk <= 0.0) throw InputError("Kbulk", "(bulk modulus) must be positive");
  if (Do <= 0.0) throw InputError("Do", "(outer diameter) must be positive");
  if (Di < 0.0) throw InputError("Di", "(inner diameter) must not be negative");
  if (Di >= Do) throw InputError("Di", "(inner diameter) must be less than Do");
  if (ts < 0.0) throw InputError("ts", "(shim thickness) must not be negative");
  if (tr <= 0.0) throw InputError("tr", "(rubber layer thickness) must be positive");
  if (n < 1.0 || n != std::floor(n))
    throw InputError("n", "(number of rubber layers) must be a whole number >= 1");
  if (tc < 0.0) throw InputError("tc", "(cover thickness) must not be negative");
  if (kc <= 0.0) throw InputError("kc", "(cavitation parameter) must be positive");
  if (phi < 0.0 || phi >= 1.0) throw InputError("phi", "(damage index) must be in [0, 1)");
  if (ac <= 0.0) throw InputError("ac", "(damage rate) must be positive");
}

KumarVertical::KumarVertical(const Params& p) : p_(p) {
  assert(p.G > 0.0 && p.Kbulk > 0.0 && p.Do > p.Di && p.tr > 0.0 && p.n >= 1.0);
  const double dOut = p.Do + p.tc;
  A_ = 0.25 * kPi * (dOut * dOut - p.Di * p.Di);
  const double inertia = kPi / 64.0 * (std::pow(dOut, 4) - std::pow(p.Di, 4));
  r_ = std::sqrt(inertia / A_);
  // Shape factor of an annular layer and the modification factor F for the central hole
  // (Kumar et al. 2014 and Constantinou et al. 2011, MCEER-11-0004, for F).
  const double S = (p.Do - p.Di) / (4.0 * p.tr);
  double F = 1.0;
  if (p.Di > 0.0) {
    const double a = p.Do / p.Di;
    F = (a * a + 1.0) / ((a - 1.0) * (a - 1.0)) + (1.0 + a) / ((1.0 - a) * std::log(a));
  }
  // Compression modulus with the bulk compressibility of the rubber (Kumar et al. 2014).
  Ec_ = 1.0 / (1.0 / (6.0 * p.G * S * S * F) + 4.0 / (3.0 * p.Kbulk));
  Tr_ = p.n * p.tr;
  h_ = Tr_ + (p.n - 1.0) * p.ts;
  Kv0_ = Ec_ * A_ / Tr_;
  Fc_ = 3.0 * p.G * A_;  // cavitation at a mean tensile stress of 3G (Gent; Kumar et al. 2014)
  // Critical load of Koh and Kelly's two-spring model as used by Kumar et al. (2014): the Euler
  // load of the bearing with the rotation modulus Ec/3 and the shear-adjusted area and inertia.
  const double pe = kPi * kPi * (Ec_ / 3.0) * (inertia * h_ / Tr_) / (h_ * h_);
  Pcr0_ = std::sqrt(pe * p.G * A_ * h_ / Tr_);
}

void KumarVertical::stiffness(double uh, double& kv, double& dkv) const {
  if (!p_.kvShear) {
    kv = Kv0_;
    dkv = 0.0;
    return;
  }
  // Kumar et al. (2014), after Warn et al. (2007): Kv = Kv0 / (1 + 3/pi^2 (uh/r)^2).
  const double c = 3.0 / (kPi * kPi);
  const double den = 1.0 + c * (uh / r_) * (uh / r_);
  kv = Kv0_ / den;
  dkv = -Kv0_ * 2.0 * c * uh / (r_ * r_) / (den * den);
}

double KumarVertical::stiffness(double uh) const {
  double kv = 0.0, dkv = 0.0;
  stiffness(uh, kv, dkv);
  return kv;
}

void KumarVertical::criticalLoad(double uh, double& pcr, double& dpcr) const {
  pcr = kMinCriticalRatio * Pcr0_;
  dpcr = 0.0;
  if (uh >= p_.Do) return;
  // Overlap of the top and bottom bonded areas (Kumar et al. 2014, after Buckle and Liu 1994):
  // Ar / A = (d - sin d) / pi with d = 2 acos(uh / Do).
  const double d = 2.0 * std::acos(uh / p_.Do);
  const double ratio = (d - std::sin(d)) / kPi;
  if (ratio < kMinCriticalRatio) return;
  pcr = Pcr0_ * ratio;
  const double dd = -2.0 / std::sqrt(p_.Do * p_.Do - uh * uh);
  dpcr = Pcr0_ * (1.0 - std::cos(d)) * dd / kPi;
}

double KumarVertical::criticalLoad(double uh) const {
  double pcr = 0.0, dpcr = 0.0;
  criticalLoad(uh, pcr, dpcr);
  return pcr;
}

double KumarVertical::envelope(double u, double uc) const {
  // Post-cavitation tension (Kumar et al. 2014): slope Fc/Tr at uc, decaying at the rate kc.
  return Fc_ * (1.0 + (1.0 - std::exp(-p_.kc * (u - uc))) / (p_.kc * Tr_));
}

KumarVertical::Response KumarVertical::evaluate(double u, double uh, const State& committed) const {
  Response r;
  r.state = committed;
  r.state.branch = 0;
  double kv = 0.0, dkv = 0.0;
  stiffness(uh, kv, dkv);

  if (p_.buckling) {
    double pcr = 0.0, dpcr = 0.0;
    criticalLoad(uh, pcr, dpcr);
    const double ucr = -pcr / kv;
    if (u <= ucr) {
      // Past the critical load the force stays near -Pcr(uh) (Kumar et al. 2014).
      const double kpb = postBucklingStiffness();
      const double ducr = -(dpcr * kv - pcr * dkv) / (kv * kv);
      r.N = -pcr + kpb * (u - ucr);
      r.dNdu = kpb;
      r.dNduh = -dpcr - kpb * ducr;
      r.state.branch = 3;
      return r;
    }
  }
  auto elastic = [&] {
    r.N = kv * u;
    r.dNdu = kv;
    r.dNduh = dkv * u;
  };
  if (!p_.cavitation || u <= 0.0) {
    elastic();
    return r;
  }

  const double uc = Fc_ / kv;
  const double duc = -Fc_ * dkv / (kv * kv);
  const bool cavitated = committed.umax > uc;
  const double um = cavitated ? committed.umax : uc;
  if (u > um) {
    // On the envelope: the largest tension so far; it damages the cavitation strength
    // (Kumar et al. 2014): Fcn = Fc (1 - phi (1 - exp(-ac (umax - uc) / uc))).
    const double e = std::exp(-p_.kc * (u - uc));
    r.N = envelope(u, uc);
    r.dNdu = Fc_ / Tr_ * e;
    r.dNduh = -Fc_ / Tr_ * e * duc;
    r.state.umax = u;
    r.state.cavitationRatio = std::min(committed.cavitationRatio,
                                       1.0 - p_.phi * (1.0 - std::exp(-p_.ac * (u - uc) / uc)));
    r.state.branch = 1;
    return r;
  }
  const double fcn = committed.cavitationRatio * Fc_;
  const double ucn = fcn / kv;
  const double ducn = -fcn * dkv / (kv * kv);
  if (u <= ucn) {
    elastic();
    return r;
  }
  // Between (ucn, Fcn) and (umax, N(umax)): the unloading and reloading path after cavitation
  // (Kumar et al. 2014). ucn < uc <= um here, since Fcn <= Fc.
  const double fm = cavitated ? envelope(um, uc) : Fc_;
  const double dfm = cavitated ? -Fc_ / Tr_ * std::exp(-p_.kc * (um - uc)) * duc : 0.0;
  const double dum = cavitated ? 0.0 : duc;
  const double span = um - ucn;
  const double s = (fm - fcn) / span;
  const double ds = (dfm * span - (fm - fcn) * (dum - ducn)) / (span * span);
  r.N = fcn + s * (u - ucn);
  r.dNdu = s;
  r.dNduh = -s * ducn + ds * (u - ucn);
  r.state.branch = 2;
  return r;
}

}  // namespace dabs::elements
