// SPDX-License-Identifier: MIT
#include "elements/beam/ForceBeamColumn.h"

#include <Eigen/LU>
#include <cmath>

namespace dabs::elements {

namespace {
/// Inverse of a section tangent; false when singular or not finite.
bool invert(const SectionMatrix& k, SectionMatrix& f) {
  Eigen::PartialPivLU<SectionMatrix> lu(k);
  const double det = lu.determinant();
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
  f = lu.inverse();
  return f.allFinite();
}
}  // namespace

template <int Ndm>
void ForceBeamColumn<Ndm>::initialize(const NodalCoordinates& x) {
  if (this->points_.empty() || static_cast<int>(this->points_.size()) > kMaxPoints)
    throw InputError("integration", "needs 1 to 20 integration points");
  this->initializeGeometry(x);
  const double length = this->transf_->initialLength();
  bmat_.clear();
  fe_.setZero();
  State s;
  for (std::size_t i = 0; i < this->points_.size(); ++i) {
    const auto& p = this->points_[i];
    bmat_.push_back(forceInterpolation<kBasic>(p.section->type(), p.xi, length));
    SectionMatrix f;
    if (!invert(p.section->getInitialTangent(), f))
      throw InputError("section", std::to_string(p.section->tag()) +
                                      " has a singular initial tangent (missing -GJ?)");
    s.fs[i] = f;
    s.e[i] = p.section->getDeformation();
    s.sr[i] = p.section->getStressResultant();
    fe_ += p.weight * length * bmat_[i].transpose() * f * bmat_[i];
  }
  const Eigen::FullPivLU<BasicMatrix> lu(fe_);
  if (!lu.isInvertible())
    throw InputError("integration", "gives a singular element flexibility (too few points?)");
  s.kb = lu.inverse();
  committed_ = trial_ = s;
  this->k0_ = this->transf_->initialGlobalStiffness(s.kb);
  this->uTrial_.setZero();
  this->uCommitted_.setZero();
  this->transf_->update(this->uTrial_);
  finish();
}

// One solve from state s (which holds the start point) to basic deformations `target`.
template <int Ndm>
Status ForceBeamColumn<Ndm>::iterate(State& s, const Basic& target) const {
  const double length = this->transf_->initialLength();
  const int n = static_cast<int>(this->points_.size());
  s.q += s.kb * (target - s.v);
  for (int it = 0; it < maxIter_; ++it) {
    BasicMatrix flex = BasicMatrix::Zero();
    Basic vr = Basic::Zero();
    for (int i = 0; i < n; ++i) {
      auto& sec = *this->points_[i].section;
      const auto& b = bmat_[i];
      const SectionVector force = b * s.q;
      s.e[i] += s.fs[i] * (force - s.sr[i]);
      const Status st = sec.setTrialDeformation(s.e[i]);
      if (!ok(st)) return st;
      s.sr[i] = sec.getStressResultant();
      if (!invert(sec.getSectionTangent(), s.fs[i])) return Status::NotConverged;
      const double wl = this->points_[i].weight * length;
      flex += wl * b.transpose() * s.fs[i] * b;
      // Compatible deformations plus the residual (unbalanced) section deformations.
      vr += wl * b.transpose() * (s.e[i] + s.fs[i] * (force - s.sr[i]));
    }
    const Eigen::PartialPivLU<BasicMatrix> lu(flex);
    if (!(std::abs(lu.determinant()) > 0.0)) return Status::NotConverged;
    s.kb = lu.inverse();
    const Basic dv = target - vr;
    const Basic dq = s.kb * dv;
    s.q += dq;
    if (!s.q.allFinite()) return Status::NonFinite;
    const double work = std::abs(dv.dot(dq));
    if (work <= tol_ * std::max(1.0, std::abs(target.dot(s.q)))) {
      s.v = target;
      return Status::Ok;
    }
  }
  return Status::NotConverged;
}

template <int Ndm>
Status ForceBeamColumn<Ndm>::solve(const Basic& target) {
  Status last = Status::NotConverged;
  for (int parts : {1, 4, 16}) {
    work_ = committed_;
    const Basic start = committed_.v;
    last = Status::Ok;
    for (int k = 1; k <= parts && ok(last); ++k)
      last = iterate(work_, start + (target - start) * (double(k) / parts));
    if (ok(last)) {
      trial_ = work_;
      return last;
    }
  }
  return last;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::finish() {
  this->q_ = trial_.q;
  this->f_ = this->transf_->globalForce(trial_.q);
  this->k_ = this->transf_->globalStiffness(trial_.kb, trial_.q);
}

template <int Ndm>
Status ForceBeamColumn<Ndm>::update(const Kinematics& trial) {
  this->uTrial_ = trial.u;
  this->transf_->update(this->uTrial_);
  const Status s = solve(this->transf_->basicDeformation());
  if (!ok(s)) return s;
  finish();
  return this->f_.allFinite() ? Status::Ok : Status::NonFinite;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::commitState() {
  this->transf_->commitState();
  for (auto& p : this->points_) p.section->commitState();
  committed_ = trial_;
  this->uCommitted_ = this->uTrial_;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::revertToLastCommit() {
  this->transf_->revertToLastCommit();
  for (auto& p : this->points_) p.section->revertToLastCommit();
  trial_ = committed_;
  this->uTrial_ = this->uCommitted_;
  this->transf_->update(this->uTrial_);
  finish();
}

template <int Ndm>
void ForceBeamColumn<Ndm>::revertToStart() {
  this->transf_->revertToStart();
  for (auto& p : this->points_) p.section->revertToStart();
  State s;
  const double length = this->transf_->initialLength();
  for (std::size_t i = 0; i < this->points_.size(); ++i) {
    SectionMatrix f;
    (void)invert(this->points_[i].section->getInitialTangent(), f);
    s.fs[i] = f;
    s.e[i] = this->points_[i].section->getDeformation();
    s.sr[i] = this->points_[i].section->getStressResultant();
  }
  (void)length;
  s.kb = fe_.inverse();
  committed_ = trial_ = s;
  this->uTrial_.setZero();
  this->uCommitted_.setZero();
  this->transf_->update(this->uTrial_);
  finish();
}

template <int Ndm>
std::optional<Eigen::VectorXd> ForceBeamColumn<Ndm>::response(
    std::span<const std::string> args) const {
  if (args.size() == 1 && (args[0] == "plasticDeformation" || args[0] == "plasticDeformations"))
    return Eigen::VectorXd(this->transf_->basicDeformation() - fe_ * trial_.q);
  return Super::response(args);
}

template class ForceBeamColumn<2>;
template class ForceBeamColumn<3>;

}  // namespace dabs::elements
