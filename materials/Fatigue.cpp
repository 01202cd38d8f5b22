// SPDX-License-Identifier: MIT
#include "materials/Fatigue.h"

#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

namespace {
/// A failed material keeps this fraction of the wrapped stress and initial tangent
/// (OpenSees FatigueMaterial::getStress/getTangent).
constexpr double kFailedFraction = 1e-8;
/// Open ranges below this strain add no pseudo damage: OpenSees filters them so that tiny
/// oscillations do not add round-off (its note: not meant for high-cycle fatigue).
constexpr double kSmallestOpenRange = 1e-10;

int signOf(double x) { return (x > 0.0) - (x < 0.0); }
}  // namespace

void Fatigue::Params::validate() const {
  if (material == nullptr) throw InputError("matTag", "the wrapped material is missing");
  if (!std::isfinite(Dmax) || Dmax <= 0.0 || Dmax > 1.0)
    throw InputError("Dmax", "must be in (0, 1]");
  if (!std::isfinite(E0) || E0 <= 0.0) throw InputError("E0", "must be positive");
  if (!std::isfinite(m) || m >= 0.0) throw InputError("m", "must be negative");
  if (std::isnan(minStrain)) throw InputError("min", "must be a number");
  if (std::isnan(maxStrain)) throw InputError("max", "must be a number");
  if (maxStrain <= minStrain) throw InputError("max", "must be greater than min");
}

Fatigue::Fatigue(int tag, const Params& params)
    : UniaxialMaterial(tag), params_(params), material_(params.material->clone()) {
  params_.material = nullptr;  // the prototype may go away; the clone is ours
  revertToStart();
}

Fatigue::Fatigue(const Fatigue& other)
    : UniaxialMaterial(other),
      params_(other.params_),
      material_(other.material_->clone()),
      trial_(other.trial_),
      committed_(other.committed_) {}

double Fatigue::cycleDamage(double cycles, double range) const {
  // Coffin-Manson range = E0 * N^m gives N = (range / E0)^(1/m); Miner adds cycles / N.
  return cycles / std::fabs(std::pow(range / params_.E0, 1.0 / params_.m));
}

Fatigue::State Fatigue::advance(double strain, double wrappedStress) const {
  State s = committed_;
  s.strain = strain;
  if (s.failed) return s;

  // Strain limits: failure whatever the cycle count (damage set to Dmax as OpenSees does).
  if (strain >= params_.maxStrain || strain <= params_.minStrain) {
    s.failed = true;
    s.damage = s.pseudoDamage = params_.Dmax;
    return s;
  }

  if (!s.started) {
    s.started = true;
    s.a = strain;
    s.lastStrain = strain;
  }

  // A step without movement keeps the previous direction, so a pause is not a reversal.
  const double slope = strain == s.lastStrain ? s.lastSlope : strain - s.lastStrain;

  // The previous strain was a peak when the direction changed (Uriz 2005, modified rainflow).
  if (signOf(s.lastSlope) != signOf(slope) && signOf(s.lastSlope) != 0) {
    const double peak = s.lastStrain;
    switch (s.phase) {
      case Phase::First:
        s.b = peak;
        s.y = std::fabs(s.b - s.a);
        s.phase = Phase::OneRange;
        break;
      case Phase::OneRange: {
        const double x = std::fabs(peak - s.b);
        if (x < s.y) {
          // A smaller range follows: it may be the inner cycle of the waiting one.
          s.c = peak;
          s.y = x;
          s.phase = Phase::TwoRanges;
        } else {
          // The waiting range is not enclosed by the next one: it is a half cycle.
          s.damage += cycleDamage(0.5, s.y);
          s.a = s.b;
          s.b = peak;
          s.y = x;
        }
        break;
      }
      case Phase::TwoRanges: {
        const double x = std::fabs(peak - s.c);
        if (x < s.y) {
          // The newest range is the smaller: it closes as a full cycle.
          s.damage += cycleDamage(1.0, x);
        } else {
          // The range B-C is enclosed by its neighbours: a full cycle; its end point moves on.
          s.damage += cycleDamage(1.0, s.y);
          s.b = peak;
        }
        s.y = std::fabs(s.b - s.a);
        s.phase = Phase::OneRange;
        break;
      }
    }
    s.pseudoDamage = s.damage;
    if (s.damage >= params_.Dmax) s.failed = true;
  }

  if (!s.failed) {
    // The damage if the current strain were the next peak: the waiting ranges close as the
    // count would close them.
    auto open = [&](double cycles, double range) {
      return std::fabs(range) < kSmallestOpenRange ? 0.0 : cycleDamage(cycles, range);
    };
    double pseudo = s.damage;
    switch (s.phase) {
      case Phase::First: pseudo += open(0.5, std::fabs(strain - s.a)); break;
      case Phase::OneRange:
        pseudo += open(0.5, std::fabs(strain - s.b));
        pseudo += open(0.5, s.y);
        break;
      case Phase::TwoRanges:
        if (std::fabs(s.a - strain) > std::fabs(s.a - s.b)) {
          // The current half cycle from A encloses B-C, which closes as a full cycle.
          pseudo += open(1.0, s.y);
          pseudo += open(0.5, std::fabs(strain - s.a));
        } else {
          // C to the current strain closes as a full cycle; A-B stays a half cycle.
          pseudo += open(1.0, std::fabs(s.c - strain));
          pseudo += open(0.5, std::fabs(s.a - s.b));
        }
        break;
    }
    s.pseudoDamage = pseudo;
    // Failure between peaks only under tensile wrapped stress (the rule of OpenSees
    // FatigueMaterial::commitState); in compression failure waits for tension or a counted peak.
    if (pseudo > params_.Dmax && wrappedStress > 0.0) {
      s.damage = pseudo;
      s.failed = true;
    }
  }

  s.lastSlope = slope;
  s.lastStrain = strain;
  return s;
}

Status Fatigue::setTrialStrain(double strain, double strainRate) {
  const Status st = material_->setTrialStrain(strain, strainRate);
  trial_ = advance(strain, material_->getStress());
  trial_.strainRate = strainRate;
  return st;
}

double Fatigue::getStress() const {
  const double s = material_->getStress();
  return trial_.failed ? kFailedFraction * s : s;
}

double Fatigue::getTangent() const {
  return trial_.failed ? kFailedFraction * material_->getInitialTangent() : material_->getTangent();
}

double Fatigue::getDampTangent() const { return trial_.failed ? 0.0 : material_->getDampTangent(); }

void Fatigue::commitState() {
  // The wrapped material stops at its last state before failure (OpenSees commits it no more).
  if (!trial_.failed) material_->commitState();
  committed_ = trial_;
}

void Fatigue::revertToLastCommit() {
  material_->revertToLastCommit();
  trial_ = committed_;
  // After failure the wrapped commit lags behind: its trial at the committed strain (from that
  // same frozen state) gives back the committed getters.
  if (committed_.failed) (void)material_->setTrialStrain(committed_.strain, committed_.strainRate);
}

void Fatigue::revertToStart() {
  material_->revertToStart();
  trial_ = committed_ = State{};
}

std::unique_ptr<UniaxialMaterial> Fatigue::clone() const {
  return std::make_unique<Fatigue>(*this);
}

std::optional<double> Fatigue::response(std::string_view name) const {
  if (name == "damage") return trial_.damage;
  if (name == "failure") return trial_.failed ? 1.0 : 0.0;
  return std::nullopt;
}

}  // namespace dabs::materials
