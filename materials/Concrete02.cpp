// SPDX-License-Identifier: MIT
#include "materials/Concrete02.h"

#include <cassert>
#include <cfloat>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

namespace {
/// Tangent used by OpenSees on the flat branches instead of an exact zero.
constexpr double kResidualTangent = 1.0e-10;
}  // namespace

Concrete02::Params Concrete02::Params::withDefaults(double fpc, double epsc0, double fpcu,
                                                    double epsU) {
  return Params{fpc, epsc0, fpcu, epsU, 0.1, 0.1 * std::fabs(fpc), 0.1 * fpc / epsc0};
}

void Concrete02::Params::validate() const {
  if (!std::isfinite(fpc) || fpc >= 0.0) throw InputError("fpc", "must be negative");
  if (!std::isfinite(epsc0) || epsc0 >= 0.0) throw InputError("epsc0", "must be negative");
  if (!std::isfinite(fpcu) || fpcu > 0.0 || fpcu < fpc)
    throw InputError("fpcu", "must be in [fpc, 0]");
  if (!std::isfinite(epsU) || epsU >= epsc0)
    throw InputError("epsU", "must be more negative than epsc0");
  if (!std::isfinite(lambda) || lambda < 0.0 || lambda >= 1.0)
    throw InputError("lambda", "must be in [0, 1)");
  if (!std::isfinite(ft) || ft < 0.0) throw InputError("ft", "must be >= 0");
  if (!std::isfinite(Ets) || Ets <= 0.0) throw InputError("Ets", "must be positive");
}

Concrete02::Concrete02(int tag, const Params& params) : StatefulUniaxial(tag), params_(params) {
  assert(params.fpc < 0.0 && params.epsc0 < 0.0 && params.Ets > 0.0);
  const auto& p = params_;
  Ec0_ = 2.0 * p.fpc / p.epsc0;
  epsR_ = (p.fpcu - p.lambda * Ec0_ * p.epsU) / (Ec0_ * (1.0 - p.lambda));
  sigR_ = Ec0_ * epsR_;
  epsCrack_ = p.ft / Ec0_;
  epsZero_ = p.ft * (1.0 / p.Ets + 1.0 / Ec0_);
  revertToStart();
}

Concrete02::State Concrete02::initialState() const {
  State s;
  s.tangent = getInitialTangent();
  setMinimumStrain(s, 0.0, 0.0);
  return s;
}

// Reloading from the largest compression reached (envelope stress sigMin there): the slope Er
// towards point R (EERC report eq. 2.35) and the strain ept where that line crosses zero stress
// (eq. 2.36).
void Concrete02::setMinimumStrain(State& s, double ecmin, double sigMin) const {
  s.ecmin = ecmin;
  s.sigMin = sigMin;
  s.Er = (s.sigMin - sigR_) / (ecmin - epsR_);
  s.ept = ecmin - s.sigMin / s.Er;
}

void Concrete02::compressionEnvelope(double eps, double& stress, double& tangent) const {
  const auto& p = params_;
  const double Ec0 = Ec0_;
  const double ratio = eps / p.epsc0;
  if (eps >= p.epsc0) {  // Hognestad/Kent-Park parabola
    stress = p.fpc * ratio * (2.0 - ratio);
    tangent = Ec0 * (1.0 - ratio);
  } else if (eps > p.epsU) {  // linear descending branch
    stress = (p.fpcu - p.fpc) * (eps - p.epsc0) / (p.epsU - p.epsc0) + p.fpc;
    tangent = (p.fpcu - p.fpc) / (p.epsU - p.epsc0);
  } else {  // residual strength
    stress = p.fpcu;
    tangent = kResidualTangent;
  }
}

void Concrete02::tensionEnvelope(double eps, double& stress, double& tangent) const {
  const auto& p = params_;
  const double Ec0 = Ec0_;
  const double epsCrack = epsCrack_;
  const double epsZero = epsZero_;
  if (eps <= epsCrack) {
    stress = eps * Ec0;
    tangent = Ec0;
  } else if (eps <= epsZero) {
    tangent = -p.Ets;
    stress = p.ft - p.Ets * (eps - epsCrack);
  } else {
    tangent = kResidualTangent;
    stress = 0.0;
  }
}

Status Concrete02::setTrialStrain(double strain, double /*strainRate*/) {
  const double Ec0 = Ec0_;
  trial_ = committed_;
  // Deliberate difference: OpenSees keeps the previous TRIAL stress here, which breaks trial
  // idempotence; the committed state is the consistent answer.
  const double deps = strain - committed_.strain;
  if (std::fabs(deps) < DBL_EPSILON) return Status::Ok;
  trial_.strain = strain;

  if (strain < trial_.ecmin) {
    compressionEnvelope(strain, trial_.stress, trial_.tangent);
    setMinimumStrain(trial_, strain, trial_.stress);
    return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
  }
  const double sigMin = trial_.sigMin, Er = trial_.Er, ept = trial_.ept;

  if (strain <= ept) {
    // between the reloading line (lower bound) and half its slope through ept (upper bound)
    const double lower = sigMin + Er * (strain - trial_.ecmin);
    const double upper = 0.5 * Er * (strain - ept);
    trial_.stress = committed_.stress + Ec0 * deps;
    trial_.tangent = Ec0;
    if (trial_.stress <= lower) {
      trial_.stress = lower;
      trial_.tangent = Er;
    }
    if (trial_.stress >= upper) {
      trial_.stress = upper;
      trial_.tangent = 0.5 * Er;
    }
  } else {
    // tension: reload towards the largest previous tensile strain (eqs. 2.42, 2.43), then
    // follow the tension envelope shifted by ept
    const double epn = ept + trial_.dept;
    if (strain <= epn) {
      double sicn = 0.0;
      tensionEnvelope(trial_.dept, sicn, trial_.tangent);
      trial_.tangent = trial_.dept != 0.0 ? sicn / trial_.dept : Ec0;
      trial_.stress = trial_.tangent * (strain - ept);
    } else {
      tensionEnvelope(strain - ept, trial_.stress, trial_.tangent);
      trial_.dept = strain - ept;
    }
  }
  return std::isfinite(trial_.stress) ? Status::Ok : Status::NonFinite;
}

std::unique_ptr<UniaxialMaterial> Concrete02::clone() const {
  return std::make_unique<Concrete02>(*this);
}

}  // namespace dabs::materials
