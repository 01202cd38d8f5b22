// SPDX-License-Identifier: MIT
#include "materials/Steel02.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

namespace {
/// Below this value of |eps*|^R the binomial series replaces pow(1 + t, 1/R).
constexpr double kSeriesLimit = 1e-4;
}  // namespace

void Steel02::Params::validate() const {
  auto positive = [](double v, const char* name) {
    if (!std::isfinite(v) || v <= 0.0) throw InputError(name, "must be positive");
  };
  auto nonNegative = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0) throw InputError(name, "must be >= 0");
  };
  positive(Fy, "Fy");
  positive(E, "E");
  if (!std::isfinite(b) || b < 0.0 || b >= 1.0) throw InputError("b", "must be in [0, 1)");
  positive(R0, "R0");
  if (!std::isfinite(cR1) || cR1 < 0.0 || cR1 >= 1.0) throw InputError("cR1", "must be in [0, 1)");
  positive(cR2, "cR2");
  nonNegative(a1, "a1");
  positive(a2, "a2");
  nonNegative(a3, "a3");
  positive(a4, "a4");
  if (!std::isfinite(sigInit) || std::fabs(sigInit) >= Fy)
    throw InputError("sigInit", "must be smaller than Fy in magnitude");
}

Steel02::Steel02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.Fy > 0.0 && params.E > 0.0 && params.b < 1.0);
  epsy_ = params.Fy / params.E;
  Esh_ = params.b * params.E;
  epsIni_ = params.sigInit / params.E;
  revertToStart();
}

void Steel02::setCurvature(State& s) const {
  const auto& p = params_;
  const double xi = std::fabs((s.epsPl - s.eps0) / epsy_);
  s.R = p.R0 * (1.0 - (p.cR1 * xi) / (p.cR2 + xi));
  s.invR = 1.0 / s.R;
  s.invSpan = 1.0 / (s.eps0 - s.epsR);
}

Steel02::State Steel02::initialState() const {
  State s;
  s.stress = params_.sigInit;
  s.tangent = params_.E;
  s.epsMax = params_.Fy / params_.E;
  s.epsMin = -s.epsMax;
  return s;
}

Status Steel02::setTrialStrain(double strain, double /*strainRate*/) {
  const auto& p = params_;
  const double Esh = Esh_;
  const double epsy = epsy_;
  // The curve works in strains shifted by the initial strain sigInit/E (C.-P. Lamarche's
  // extension in OpenSees), so the virgin state sits at (sigInit/E, sigInit).
  const double epsIni = epsIni_;
  const double eps = strain + epsIni;
  const double epsP = committed_.strain + epsIni;  // committed shifted strain
  const double sigP = committed_.stress;
  const double deps = eps - epsP;

  trial_ = committed_;
  trial_.strain = strain;

  if (trial_.kon == 0 || trial_.kon == 3) {
    if (std::fabs(deps) < 10.0 * DBL_EPSILON) {
      trial_.tangent = p.E;
      trial_.stress = p.sigInit;
      trial_.kon = 3;
      return Status::Ok;
    }
    // first excursion: asymptotes meet at (+-epsy, +-Fy); the curve starts at the origin
    trial_.epsMax = epsy;
    trial_.epsMin = -epsy;
    if (deps < 0.0) {
      trial_.kon = 2;
      trial_.eps0 = -epsy;
      trial_.sig0 = -p.Fy;
      trial_.epsPl = -epsy;
    } else {
      trial_.kon = 1;
      trial_.eps0 = epsy;
      trial_.sig0 = p.Fy;
      trial_.epsPl = epsy;
    }
    setCurvature(trial_);
  }

  if (trial_.kon == 2 && deps > 0.0) {
    // reversal towards tension: new origin at the last committed point; the hardening
    // asymptote is shifted by the isotropic term a3*((epsmax-epsmin)/(2*a4*epsy))^0.8
    trial_.kon = 1;
    trial_.epsR = epsP;
    trial_.sigR = sigP;
    if (epsP < trial_.epsMin) trial_.epsMin = epsP;
    const double d1 = (trial_.epsMax - trial_.epsMin) / (2.0 * p.a4 * epsy);
    const double shift = p.a3 == 0.0 ? 1.0 : 1.0 + p.a3 * std::pow(d1, 0.8);
    // intersection of sig = sigR + E*(eps-epsR) with sig = Fy*shift + Esh*(eps - epsy*shift)
    trial_.eps0 = (p.Fy * shift - Esh * epsy * shift - trial_.sigR + p.E * trial_.epsR) / (p.E - Esh);
    trial_.sig0 = p.Fy * shift + Esh * (trial_.eps0 - epsy * shift);
    trial_.epsPl = trial_.epsMax;
    setCurvature(trial_);
  } else if (trial_.kon == 1 && deps < 0.0) {
    // reversal towards compression, mirrored (a1, a2)
    trial_.kon = 2;
    trial_.epsR = epsP;
    trial_.sigR = sigP;
    if (epsP > trial_.epsMax) trial_.epsMax = epsP;
    const double d1 = (trial_.epsMax - trial_.epsMin) / (2.0 * p.a2 * epsy);
    const double shift = p.a1 == 0.0 ? 1.0 : 1.0 + p.a1 * std::pow(d1, 0.8);
    trial_.eps0 = (-p.Fy * shift + Esh * epsy * shift - trial_.sigR + p.E * trial_.epsR) / (p.E - Esh);
    trial_.sig0 = -p.Fy * shift + Esh * (trial_.eps0 + epsy * shift);
    trial_.epsPl = trial_.epsMin;
    setCurvature(trial_);
  }

  // Menegotto-Pinto curve (Filippou et al. 1983, eqs. 3-5) and its exact derivative.
  const double epsRat = (eps - trial_.epsR) * trial_.invSpan;
  const double t = std::pow(std::fabs(epsRat), trial_.R);
  const double dum1 = 1.0 + t;
  // (1 + t)^(1/R): near the elastic branch t is small and the binomial series to t^3 equals the
  // power to round-off (the next term is below 1e-17 for t < 1e-4 and R >= 1), at a fraction of
  // the cost of a second pow.
  const double a = trial_.invR;
  const double dum2 = t < kSeriesLimit && trial_.R >= 1.0
                          ? 1.0 + a * t * (1.0 + (a - 1.0) * t * (0.5 + (a - 2.0) * t / 6.0))
                          : std::pow(dum1, a);
  const double sigStar = p.b * epsRat + (1.0 - p.b) * epsRat / dum2;
  trial_.stress = sigStar * (trial_.sig0 - trial_.sigR) + trial_.sigR;
  const double eStar = p.b + (1.0 - p.b) / (dum1 * dum2);
  trial_.tangent = eStar * (trial_.sig0 - trial_.sigR) * trial_.invSpan;
  return std::isfinite(trial_.stress) && std::isfinite(trial_.tangent) ? Status::Ok
                                                                       : Status::NonFinite;
}

std::unique_ptr<UniaxialMaterial> Steel02::clone() const { return std::make_unique<Steel02>(*this); }

}  // namespace dabs::materials
