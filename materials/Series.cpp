// SPDX-License-Identifier: MIT
#include "materials/Series.h"

#include <algorithm>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

namespace {
/// A component tangent smaller than this fraction of its initial tangent is treated as this
/// fraction (a yielded or open component then takes almost all further strain).
constexpr double kMinTangentRatio = 1e-10;
/// Stresses below this multiple of the largest initial tangent count as zero in the test.
constexpr double kStressFloorStrain = 1e-8;
}  // namespace

void Series::Params::validate() const {
  if (components.size() < 2) throw InputError("materials", "at least two materials are required");
  for (const auto* c : components)
    if (c == nullptr) throw InputError("materials", "a component material is missing");
  if (maxIterations < 1) throw InputError("maxIterations", "must be at least 1");
  if (!std::isfinite(tolerance) || tolerance <= 0.0)
    throw InputError("tolerance", "must be positive");
}

Series::Series(int tag, const Params& params)
    : UniaxialMaterial(tag), maxIterations_(params.maxIterations), tolerance_(params.tolerance) {
  const std::size_t n = params.components.size();
  components_.reserve(n);
  double maxE0 = 0.0;
  for (const auto* c : params.components) {
    components_.push_back(c->clone());
    maxE0 = std::max(maxE0, std::fabs(c->getInitialTangent()));
  }
  minTangent_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double e0 = std::fabs(components_[i]->getInitialTangent());
    minTangent_[i] = kMinTangentRatio * (e0 > 0.0 ? e0 : (maxE0 > 0.0 ? maxE0 : 1.0));
  }
  stressFloor_ = kStressFloorStrain * (maxE0 > 0.0 ? maxE0 : 1.0);
  stress_.assign(n, 0.0);
  flex_.assign(n, 0.0);
  trial_.componentStrains.assign(n, 0.0);
  committed_.componentStrains.assign(n, 0.0);
  revertToStart();
}

Series::Series(const Series& other)
    : UniaxialMaterial(other),
      minTangent_(other.minTangent_),
      stress_(other.stress_),
      flex_(other.flex_),
      stressFloor_(other.stressFloor_),
      maxIterations_(other.maxIterations_),
      tolerance_(other.tolerance_),
      trial_(other.trial_),
      committed_(other.committed_) {
  components_.reserve(other.components_.size());
  for (const auto& c : other.components_) components_.push_back(c->clone());
}

double Series::flexibility(std::size_t i, double tangent) const {
  if (std::fabs(tangent) >= minTangent_[i]) return 1.0 / tangent;
  return tangent < 0.0 ? -1.0 / minTangent_[i] : 1.0 / minTangent_[i];
}

Status Series::setTrialStrain(double strain, double /*strainRate*/) {
  const std::size_t n = components_.size();
  trial_.strain = strain;
  auto& e = trial_.componentStrains;
  e = committed_.componentStrains;  // same size: no allocation

  for (int iter = 0; iter < maxIterations_; ++iter) {
    // Evaluate every component at its current strain.
    double totalFlex = 0.0;
    double offset = 0.0;  // sum (e_i - f_i*sig_i)
    double sigMax = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Status st = components_[i]->setTrialStrain(e[i], 0.0);
      if (!ok(st)) return st;
      stress_[i] = components_[i]->getStress();
      flex_[i] = flexibility(i, components_[i]->getTangent());
      totalFlex += flex_[i];
      offset += e[i] - flex_[i] * stress_[i];
      sigMax = std::max(sigMax, std::fabs(stress_[i]));
    }
    // Linearised compatibility sum_i (e_i + f_i*(s - sig_i)) = strain gives the common stress.
    const double s = (strain - offset) / totalFlex;
    if (!std::isfinite(s)) return Status::NonFinite;
    double unbalance = 0.0;
    for (std::size_t i = 0; i < n; ++i) unbalance = std::max(unbalance, std::fabs(s - stress_[i]));
    if (unbalance <= tolerance_ * std::max({std::fabs(s), sigMax, stressFloor_})) {
      trial_.stress = s;
      trial_.tangent = 1.0 / totalFlex;
      return Status::Ok;
    }
    for (std::size_t i = 0; i < n; ++i) e[i] += flex_[i] * (s - stress_[i]);
  }
  return Status::NotConverged;
}

double Series::getInitialTangent() const {
  double flex = 0.0;
  for (const auto& c : components_) {
    const double k = c->getInitialTangent();
    if (k == 0.0) return 0.0;
    flex += 1.0 / k;
  }
  return flex != 0.0 ? 1.0 / flex : 0.0;
}

void Series::commitState() {
  for (auto& c : components_) c->commitState();
  committed_ = trial_;
}

void Series::revertToLastCommit() {
  for (auto& c : components_) c->revertToLastCommit();
  trial_ = committed_;
}

void Series::revertToStart() {
  for (auto& c : components_) c->revertToStart();
  std::fill(trial_.componentStrains.begin(), trial_.componentStrains.end(), 0.0);
  trial_.strain = 0.0;
  trial_.stress = 0.0;
  trial_.tangent = getInitialTangent();
  committed_ = trial_;
}

std::unique_ptr<UniaxialMaterial> Series::clone() const { return std::make_unique<Series>(*this); }

}  // namespace dabs::materials
