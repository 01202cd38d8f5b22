// SPDX-License-Identifier: MIT
#include "materials/section/SectionAggregator.h"

#include <algorithm>
#include <string>

#include "materials/InputError.h"

namespace dabs::materials::section {

SectionAggregator::SectionAggregator(int tag, const std::vector<Part>& parts,
                                     const SectionForceDeformation* base)
    : SectionForceDeformation(tag) {
  const std::string who = "section Aggregator " + std::to_string(tag);
  if (parts.empty() && base == nullptr) throw InputError(who, "has no materials and no section");
  if (base != nullptr) {
    base_ = base->clone();
    base_->revertToStart();
    baseOrder_ = base_->order();
    codes_.assign(base_->type().begin(), base_->type().end());
  }
  for (const Part& p : parts) {
    if (p.material == nullptr) throw InputError(who, "material is missing");
    if (std::find(codes_.begin(), codes_.end(), p.code) != codes_.end())
      throw InputError(who, "resultant code " + std::to_string(int(p.code)) +
                                " appears twice (in the materials or the -section)");
    codes_.push_back(p.code);
    mats_.push_back(p.material->clone());
    mats_.back()->revertToStart();
  }
  if (codes_.size() > 6) throw InputError(who, "has more than 6 resultants");
  const int n = order();
  e_ = eCommitted_ = s_ = Eigen::VectorXd::Zero(n);
  k_ = k0_ = Eigen::MatrixXd::Zero(n, n);
  gather(true);
  gather(false);
}

SectionAggregator::SectionAggregator(const SectionAggregator& o)
    : SectionForceDeformation(o),
      base_(o.base_ ? o.base_->clone() : nullptr),
      baseOrder_(o.baseOrder_),
      codes_(o.codes_),
      e_(o.e_),
      eCommitted_(o.eCommitted_),
      s_(o.s_),
      k_(o.k_),
      k0_(o.k0_) {
  for (const auto& m : o.mats_) mats_.push_back(m->clone());
}

void SectionAggregator::gather(bool initial) {
  Eigen::MatrixXd& k = initial ? k0_ : k_;
  if (base_) {
    k.topLeftCorner(baseOrder_, baseOrder_) =
        initial ? base_->getInitialTangent() : base_->getSectionTangent();
    if (!initial) s_.head(baseOrder_) = base_->getStressResultant();
  }
  for (std::size_t i = 0; i < mats_.size(); ++i) {
    const int r = baseOrder_ + static_cast<int>(i);
    k(r, r) = initial ? mats_[i]->getInitialTangent() : mats_[i]->getTangent();
    if (!initial) s_(r) = mats_[i]->getStress();
  }
}

Status SectionAggregator::setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) {
  e_ = e;
  Status status = Status::Ok;
  if (base_) status = base_->setTrialDeformation(e_.head(baseOrder_));
  for (std::size_t i = 0; i < mats_.size(); ++i) {
    const Status s = mats_[i]->setTrialStrain(e_(baseOrder_ + static_cast<int>(i)));
    if (!ok(s)) status = s;
  }
  gather(false);
  if (ok(status) && !s_.allFinite()) status = Status::NonFinite;
  return status;
}

void SectionAggregator::commitState() {
  if (base_) base_->commitState();
  for (auto& m : mats_) m->commitState();
  eCommitted_ = e_;
}

void SectionAggregator::revertToLastCommit() {
  if (base_) base_->revertToLastCommit();
  for (auto& m : mats_) m->revertToLastCommit();
  e_ = eCommitted_;
  gather(false);
}

void SectionAggregator::revertToStart() {
  if (base_) base_->revertToStart();
  for (auto& m : mats_) m->revertToStart();
  e_.setZero();
  eCommitted_.setZero();
  gather(false);
}

std::optional<Eigen::VectorXd> SectionAggregator::response(
    std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  if (args.size() == 1 && (args[0] == "force" || args[0] == "forces")) return s_;
  if (args.size() == 1 && (args[0] == "deformation" || args[0] == "deformations")) return e_;
  return base_ ? base_->response(args) : std::nullopt;
}

bool SectionAggregator::keepsStateAtSameDeformation() const {
  if (base_ && !base_->keepsStateAtSameDeformation()) return false;
  for (const auto& m : mats_)
    if (!m->keepsStateAtSameStrain()) return false;
  return true;
}

}  // namespace dabs::materials::section
