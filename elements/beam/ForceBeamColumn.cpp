// SPDX-License-Identifier: MIT
#include "elements/beam/ForceBeamColumn.h"

#include "elements/beam/SectionPointView.h"

#include <Eigen/LU>
#include <cfloat>
#include <cmath>

namespace dabs::elements {

namespace {
/// Inverse of a fixed-size matrix by Eigen's closed form (cofactors up to 4x4); false when the
/// determinant is zero or not finite.
template <int N, class Result>
bool invertFixed(const Eigen::Ref<const Eigen::MatrixXd>& k, Result&& f) {
  const Eigen::Matrix<double, N, N> a = k;
  Eigen::Matrix<double, N, N> inverse;
  double det = 0.0;
  bool invertible = false;
  a.computeInverseAndDetWithCheck(inverse, det, invertible, 0.0);
  if (!invertible || !std::isfinite(det)) return false;
  f = inverse;
  return f.allFinite();
}

/// Inverse of a small fixed-size matrix by Gauss-Jordan elimination with partial pivoting, in
/// place of Eigen's blocked LU (whose triangular solves cost several times more at 6 x 6); false
/// when a pivot is zero or the result is not finite.
template <int N>
bool invertSmall(const Eigen::Matrix<double, N, N>& m, Eigen::Matrix<double, N, N>& inverse) {
  Eigen::Matrix<double, N, N> a = m;
  inverse.setIdentity();
  for (int c = 0; c < N; ++c) {
    int pivot = c;
    for (int r = c + 1; r < N; ++r)
      if (std::abs(a(r, c)) > std::abs(a(pivot, c))) pivot = r;
    if (!(std::abs(a(pivot, c)) > 0.0)) return false;
    if (pivot != c) {
      a.row(c).swap(a.row(pivot));
      inverse.row(c).swap(inverse.row(pivot));
    }
    const double scale = 1.0 / a(c, c);
    a.row(c) *= scale;
    inverse.row(c) *= scale;
    for (int r = 0; r < N; ++r) {
      if (r == c) continue;
      const double f = a(r, c);
      if (f == 0.0) continue;
      a.row(r) -= f * a.row(c);
      inverse.row(r) -= f * inverse.row(c);
    }
  }
  return inverse.allFinite();
}

/// Inverse of a section tangent; false when singular or not finite. Orders 2 to 4 (the fiber
/// sections' P-Mz and P-Mz-My-T) take the closed form, which is several times cheaper for these
/// sizes than a general LU, run twice per section and local iteration.
bool invert(const SectionMatrix& k, SectionMatrix& f) {
  f.resize(k.rows(), k.cols());
  switch (k.rows()) {
    case 2: return invertFixed<2>(k, f);
    case 3: return invertFixed<3>(k, f);
    case 4: return invertFixed<4>(k, f);
    default: break;
  }
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
  virgin_ = s;
  this->k0_ = this->transf_->initialGlobalStiffness(s.kb);
  startFromVirginState();
}

template <int Ndm>
void ForceBeamColumn<Ndm>::startFromVirginState() {
  committed_ = trial_ = virgin_;
  trialIsCommitted_ = true;
  updated_ = false;
  this->uTrial_.setZero();
  this->uCommitted_.setZero();
  this->transf_->update(this->uTrial_);
  finish();
  this->kc_ = this->k_;
}

namespace {
/// Inverse of a section tangent into the point's flexibility: the closed form for a fixed
/// order, the general invert() otherwise.
template <int Order, class Flexibility>
bool invertTangent(const Eigen::Ref<const Eigen::MatrixXd>& k, Flexibility& f) {
  if constexpr (Order == Eigen::Dynamic)
    return invert(k, f);
  else
    return invertFixed<Order>(k, f);
}
}  // namespace

// One solve from state s (which holds the start point) to basic deformations `target`.
template <int Ndm>
Status ForceBeamColumn<Ndm>::iterate(State& s, const Basic& target, Correction c) const {
  // Fiber sections (P-Mz in 2D, P-Mz-My-T in 3D) on fixed-size matrices: the section loop is
  // most of the element's own work.
  if (this->uniformOrder_ == 2) return iterateWith<2>(s, target, c);
  if (this->uniformOrder_ == 4) return iterateWith<4>(s, target, c);
  return iterateWith<Eigen::Dynamic>(s, target, c);
}

template <int Ndm>
template <int Order>
Status ForceBeamColumn<Ndm>::iterateWith(State& s, const Basic& target, Correction c) const {
  using View = SectionPointView<Order, kBasic>;
  const double length = this->transf_->initialLength();
  const int n = static_cast<int>(this->points_.size());
  s.q += s.kb * (target - s.v);
  // OpenSees allows the initial-flexibility iteration, which converges linearly, ten times the
  // iterations.
  const int iterations = c == Correction::Initial ? 10 * maxIter_ : maxIter_;
  for (int it = 0; it < iterations; ++it) {
    const bool initial = c == Correction::Initial || (c == Correction::InitialFirst && it == 0);
    BasicMatrix flex = BasicMatrix::Zero();
    Basic vr = Basic::Zero();
    for (int i = 0; i < n; ++i) {
      auto& sec = *this->points_[i].section;
      const auto& b = View::interp(bmat_[i]);
      auto&& e = View::vec(s.e[i]);
      auto&& sr = View::vec(s.sr[i]);
      auto&& fs = View::mat(s.fs[i]);
      typename View::Vec force = b * s.q;
      if (!sp_.empty()) force += View::vec(sp_[static_cast<std::size_t>(i)]);
      if (initial)
        e += View::mat(virgin_.fs[i]) * (force - sr);  // the initial flexibility
      else
        e += fs * (force - sr);
      const Status st = sec.setTrialDeformation(s.e[i]);
      if (!ok(st)) return st;
      sr = sec.getStressResultant();
      if (!invertTangent<Order>(sec.getSectionTangent(), fs)) return Status::NotConverged;
      const double wl = this->points_[i].weight * length;
      flex += wl * b.transpose() * fs * b;
      // Compatible deformations plus the residual (unbalanced) section deformations.
      vr += wl * b.transpose() * (e + fs * (force - sr));
    }
    if constexpr (kBasic <= 4) {
      double det = 0.0;
      bool invertible = false;
      flex.computeInverseAndDetWithCheck(s.kb, det, invertible, 0.0);
      if (!invertible || !std::isfinite(det)) return Status::NotConverged;
    } else if (!invertSmall<kBasic>(flex, s.kb)) {
      return Status::NotConverged;
    }
    const Basic dv = target - vr;
    const Basic dq = s.kb * dv;
    s.q += dq;
    if (!s.q.allFinite()) return Status::NonFinite;
    // OpenSees' test, absolute: the energy of the last correction below tol. (A test relative
    // to max(1, |v . q|) stopped earlier than OpenSees wherever |v . q| > 1: an RC frame with
    // Steel01 bars drifted 3.9e-3 from OpenSees' displacements, and the benchmark bridges
    // differed by 1e-10 where they now differ by 5e-13.)
    const double work = std::abs(dv.dot(dq));
    if (work < tol_) {
      s.v = target;
      return Status::Ok;
    }
  }
  return Status::NotConverged;
}

template <int Ndm>
Status ForceBeamColumn<Ndm>::solve(const Basic& target) {
  // First from the last trial state: within a global Newton iteration the change of the basic
  // deformations is small, so one or two local iterations converge (OpenSees'
  // ForceBeamColumn3d::update continues from its trial state too). The state struct holds section
  // deformations, forces and flexibilities that belong together, and the materials start every
  // update from their committed state, so any consistent trial state is a valid start.
  // The trial state is iterated in place; a failed attempt leaves it inconsistent, so each
  // strategy starts again from the update's start point, kept aside unless it is the committed
  // state. OpenSees' three strategies come first, so that where Newton on the current
  // flexibilities cycles (a bilinear Steel01 bar at its kink beside softening concrete) the
  // element finds the local solution OpenSees finds: the subdivisions alone found another one
  // there, 1.8e-5 of the displacements away, which an RC frame then carried on. Copies cover the
  // points in use only (the arrays hold room for 20).
  const int n = static_cast<int>(this->points_.size());
  const bool fromCommitted = trialIsCommitted_;
  if (!fromCommitted) attemptStart_.assign(trial_, n);
  const State& from = fromCommitted ? committed_ : attemptStart_;
  for (const Correction c : {Correction::Current, Correction::Initial, Correction::InitialFirst}) {
    if (ok(iterate(trial_, target, c))) {
      trialIsCommitted_ = false;
      return Status::Ok;
    }
    trial_.assign(from, n);
  }
  Status last = Status::NotConverged;
  for (int parts : {1, 4, 16}) {
    if (parts == 1 && fromCommitted) continue;  // the first strategy above
    trial_.assign(committed_, n);
    const Basic start = committed_.v;
    last = Status::Ok;
    for (int k = 1; k <= parts && ok(last); ++k)
      last = iterate(trial_, start + (target - start) * (double(k) / parts));
    if (ok(last)) {
      trialIsCommitted_ = false;
      return last;
    }
  }
  trial_.assign(committed_, n);
  trialIsCommitted_ = true;
  return last;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::loadsChanged() {
  updated_ = false;  // the state does not carry the new loads, even at the same deformations
  sp_.clear();
  if (this->loads_.empty()) return;
  for (const auto& p : this->points_)
    sp_.push_back(this->loads_.sectionForces(p.section->type(), p.xi));
}

template <int Ndm>
void ForceBeamColumn<Ndm>::finish() {
  this->q_ = trial_.q;
  this->f_ = this->endForces(trial_.q);
  this->k_ = this->transf_->globalStiffness(trial_.kb, trial_.q);
}

template <int Ndm>
Status ForceBeamColumn<Ndm>::update(const Kinematics& trial) {
  this->uTrial_ = trial.u;
  this->transf_->update(this->uTrial_);
  const Basic& v = this->transf_->basicDeformation();
  // As OpenSees' ForceBeamColumn3d::update (and 2d): once updated, without member loads, basic
  // deformations that moved by a norm of DBL_EPSILON at most since the state's (a transient
  // step's predictor leaves the displacements as committed) keep the state: no section is
  // evaluated, and only the end forces and the stiffness follow the transformation. Unlike
  // OpenSees, loads removed since the last update make it iterate (their section forces are in
  // the state).
  const bool unchanged = updated_ && this->loads_.empty() && (v - trial_.v).norm() <= DBL_EPSILON;
  if (!unchanged) {
    const Status s = solve(v);
    if (!ok(s)) {
      // The sections hold the failed iteration's deformations while trial_ is the committed
      // state: the next update must set them again, even at the committed deformations.
      updated_ = false;
      return s;
    }
  }
  updated_ = true;
  finish();
  return this->f_.allFinite() ? Status::Ok : Status::NonFinite;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::commitState() {
  this->transf_->commitState();
  for (auto& p : this->points_) p.section->commitState();
  committed_.assign(trial_, static_cast<int>(this->points_.size()));
  trialIsCommitted_ = true;
  this->uCommitted_ = this->uTrial_;
  this->kc_ = this->k_;
}

template <int Ndm>
void ForceBeamColumn<Ndm>::revertToLastCommit() {
  this->transf_->revertToLastCommit();
  for (auto& p : this->points_) p.section->revertToLastCommit();
  trial_.assign(committed_, static_cast<int>(this->points_.size()));
  trialIsCommitted_ = true;
  this->uTrial_ = this->uCommitted_;
  this->transf_->update(this->uTrial_);
  finish();
}

template <int Ndm>
void ForceBeamColumn<Ndm>::revertToStart() {
  this->transf_->revertToStart();
  for (auto& p : this->points_) p.section->revertToStart();
  // The sections are back at their virgin states, whose flexibilities initialize() inverted.
  startFromVirginState();
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
