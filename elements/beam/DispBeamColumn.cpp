// SPDX-License-Identifier: MIT
#include "elements/beam/DispBeamColumn.h"

#include "elements/beam/SectionPointView.h"

namespace dabs::elements {

template <int Ndm>
void DispBeamColumn<Ndm>::initialize(const NodalCoordinates& x) {
  this->initializeGeometry(x);
  const double length = this->transf_->initialLength();
  bmat_.clear();
  for (const auto& p : this->points_)
    bmat_.push_back(deformationInterpolation<Super::kBasic>(p.section->type(), p.xi, length));
  (void)formState(true);
  this->k0_ = this->transf_->initialGlobalStiffness(kb_);
  this->uTrial_.setZero();
  this->uCommitted_.setZero();
  (void)formState(false);
  this->kc_ = this->k_;
  keepsState_ = this->transf_->isLinear();
  for (const auto& p : this->points_)
    keepsState_ = keepsState_ && p.section->keepsStateAtSameDeformation();
  stateCurrent_ = false;
}

template <int Ndm>
Status DispBeamColumn<Ndm>::formState(bool initial) {
  // Fiber sections (P-Mz in 2D, P-Mz-My-T in 3D) on fixed-size matrices.
  if (this->uniformOrder_ == 2) return formStateWith<2>(initial);
  if (this->uniformOrder_ == 4) return formStateWith<4>(initial);
  return formStateWith<Eigen::Dynamic>(initial);
}

template <int Ndm>
template <int Order>
Status DispBeamColumn<Ndm>::formStateWith(bool initial) {
  using View = SectionPointView<Order, Super::kBasic>;
  const double length = this->transf_->initialLength();
  if (!initial) this->transf_->update(this->uTrial_);
  const Basic& v = this->transf_->basicDeformation();
  Status status = Status::Ok;
  this->q_.setZero();
  kb_.setZero();
  for (std::size_t i = 0; i < this->points_.size(); ++i) {
    auto& sec = *this->points_[i].section;
    const auto& b = View::interp(bmat_[i]);
    const double wl = this->points_[i].weight * length;
    if (initial) {
      const typename View::Mat ks = sec.getInitialTangent();
      kb_ += wl * b.transpose() * ks * b;
      continue;
    }
    const typename View::Vec e = b * v;
    const Status s = sec.setTrialDeformation(e);
    if (!ok(s)) status = s;
    const typename View::Vec sr = sec.getStressResultant();
    const typename View::Mat ks = sec.getSectionTangent();
    this->q_ += wl * b.transpose() * sr;
    kb_ += wl * b.transpose() * ks * b;
  }
  if (!initial) {
    if (!this->loads_.empty()) this->q_ += this->loads_.fixedEndForces();
    this->f_ = this->endForces(this->q_);
    this->k_ = this->transf_->globalStiffness(kb_, this->q_);
  }
  return status;
}

template <int Ndm>
Status DispBeamColumn<Ndm>::update(const Kinematics& trial) {
  this->uTrial_ = trial.u;
  stateCurrent_ = false;
  const Status s = formState(false);
  if (!ok(s)) return s;
  if (!this->f_.allFinite()) return Status::NonFinite;
  stateCurrent_ = true;
  return Status::Ok;
}

template <int Ndm>
void DispBeamColumn<Ndm>::commitState() {
  this->transf_->commitState();
  for (auto& p : this->points_) p.section->commitState();
  this->uCommitted_ = this->uTrial_;
  this->kc_ = this->k_;
}

template <int Ndm>
void DispBeamColumn<Ndm>::revertToLastCommit() {
  this->transf_->revertToLastCommit();
  for (auto& p : this->points_) p.section->revertToLastCommit();
  this->uTrial_ = this->uCommitted_;
  (void)formState(false);
  stateCurrent_ = false;
}

template <int Ndm>
void DispBeamColumn<Ndm>::revertToStart() {
  this->transf_->revertToStart();
  for (auto& p : this->points_) p.section->revertToStart();
  this->uTrial_.setZero();
  this->uCommitted_.setZero();
  (void)formState(false);
  this->kc_ = this->k_;
  stateCurrent_ = false;
}

template class DispBeamColumn<2>;
template class DispBeamColumn<3>;

}  // namespace dabs::elements
