// SPDX-License-Identifier: MIT
#include "materials/Parallel.h"

#include <cmath>
#include <string>

#include "materials/InputError.h"

namespace dabs::materials {

void Parallel::Params::validate() const {
  if (components.empty()) throw InputError("materials", "at least one material is required");
  for (const auto* c : components)
    if (c == nullptr) throw InputError("materials", "a component material is missing");
  if (!factors.empty() && factors.size() != components.size())
    throw InputError("-factors", "needs one factor per material (" +
                                     std::to_string(components.size()) + "), got " +
                                     std::to_string(factors.size()));
  for (double f : factors)
    if (!std::isfinite(f)) throw InputError("-factors", "must be finite numbers");
}

Parallel::Parallel(int tag, const Params& params) : UniaxialMaterial(tag) {
  components_.reserve(params.components.size());
  for (const auto* c : params.components) components_.push_back(c->clone());
  factors_ = params.factors.empty() ? std::vector<double>(components_.size(), 1.0) : params.factors;
  revertToStart();
}

Parallel::Parallel(const Parallel& other)
    : UniaxialMaterial(other),
      factors_(other.factors_),
      trial_(other.trial_),
      committed_(other.committed_) {
  components_.reserve(other.components_.size());
  for (const auto& c : other.components_) components_.push_back(c->clone());
}

void Parallel::gather() {
  trial_.stress = trial_.tangent = trial_.dampTangent = 0.0;
  for (std::size_t i = 0; i < components_.size(); ++i) {
    trial_.stress += factors_[i] * components_[i]->getStress();
    trial_.tangent += factors_[i] * components_[i]->getTangent();
    trial_.dampTangent += factors_[i] * components_[i]->getDampTangent();
  }
}

Status Parallel::setTrialStrain(double strain, double strainRate) {
  trial_.strain = strain;
  trial_.strainRate = strainRate;
  Status result = Status::Ok;
  for (auto& c : components_) {
    const Status s = c->setTrialStrain(strain, strainRate);
    if (!ok(s) && ok(result)) result = s;
  }
  gather();
  return result;
}

double Parallel::getInitialTangent() const {
  double k = 0.0;
  for (std::size_t i = 0; i < components_.size(); ++i)
    k += factors_[i] * components_[i]->getInitialTangent();
  return k;
}

void Parallel::commitState() {
  for (auto& c : components_) c->commitState();
  committed_ = trial_;
}

void Parallel::revertToLastCommit() {
  for (auto& c : components_) c->revertToLastCommit();
  trial_ = committed_;
}

void Parallel::revertToStart() {
  for (auto& c : components_) c->revertToStart();
  trial_ = State{};
  gather();
  committed_ = trial_;
}

std::unique_ptr<UniaxialMaterial> Parallel::clone() const {
  return std::make_unique<Parallel>(*this);
}

}  // namespace dabs::materials
