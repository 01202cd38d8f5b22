// SPDX-License-Identifier: MIT
// Just over 400 lines: the update and its tangents, the far test that lets a pair sleep and the
// responses all read the same private state, and each part is short.
#include "contact/NodeToSurfaceContact3d.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <unsupported/Eigen/AutoDiff>

#include "materials/InputError.h"

namespace dabs::contact {

namespace {

// Forward-mode derivatives with respect to the 15 translations (k, a, b, c, d) and then their
// 15 velocities; fixed size, so no heap allocation during update().
constexpr int kTrans = 15;
using Deriv = Eigen::Matrix<double, 2 * kTrans, 1>;
using AD = Eigen::AutoDiffScalar<Deriv>;
using Vec3 = std::array<AD, 3>;

AD dot(const Eigen::Vector3d& a, const Vec3& b) { return a(0) * b[0] + a(1) * b[1] + a(2) * b[2]; }

NormalLaw::Params normalParams(const NodeToSurfaceParams& p) {
  return {p.K, p.e, p.M1, p.M2, p.law, p.n, p.v0};
}
CoulombFriction::Params frictionParams(const NodeToSurfaceParams& p) {
  return {p.Kt > 0.0 ? p.Kt : p.K, p.et, p.muS, p.muK, p.M1, p.M2};
}

}  // namespace

void NodeToSurfaceParams::validate() const {
  const NodeToSurfaceParams& params = *this;
  normalParams(params).validate();
  if (!(Kt >= 0.0) || !std::isfinite(Kt))
    throw InputError("Kt", "must be positive and finite (0: the value of K)");
  try {
    frictionParams(*this).validate();
  } catch (const InputError& err) {
    if (err.field() == "Kt") throw InputError(params.Kt > 0.0 ? "Kt" : "K", err.reason());
    throw;
  }
  if (!(search > 0.0)) throw InputError("search", "must be positive");
}

template <int Ndf>
NodeToSurfaceContact3d<Ndf>::NodeToSurfaceContact3d(int tag, int contactor,
                                                    const std::array<int, 4>& target,
                                                    const NodeToSurfaceParams& params)
    : Base(tag, {contactor, target[0], target[1], target[2], target[3]}),
      params_(params),
      normal_(normalParams(params)),
      friction_(frictionParams(params)) {
  search_ = ContactSearch(params.search);
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::initialize(const elements::NodalCoordinates& x) {
  if (x.size() != 5) throw InputError("nodes", "nodeToSurface needs 5 nodes (k a b c d)");
  for (std::size_t i = 0; i < 5; ++i) X_[i] = x[i];
  const std::array<Eigen::Vector3d, 4> quad{X_[1], X_[2], X_[3], X_[4]};
  frame_ = makeSurfaceFrame(quad);
  origin_ = boundingSphere(quad).center;
  const double side = frame_.n.dot(X_[0] - origin_);
  if (side < -1e-9 * frame_.size)
    throw InputError("surface",
                     "outward normal (b-a)x(d-a) points away from the contactor node: "
                     "list the target nodes a b c d in the opposite order");
  // Evaluate the undeformed state once so gap and projection are known before the first step;
  // revertToStart returns to it.
  initial_ = NodeToSurfaceState{};
  revertToStart();
  // Fixed size, not a heap vector: a freed temporary here left a hole among the model's data
  // that the next definitions' small vectors (nodes') filled, spreading them over more memory.
  const typename Base::Vector zero = Base::Vector::Zero();
  if (ok(update(elements::Kinematics{zero, zero, zero, 0.0, 0.0}))) commitState();
  initial_ = committed_;
  revertToStart();
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::clearForces() {
  if (forcesZero_) return;
  this->f_.setZero();
  if (tangents_) {
    tangents_->k.setZero();
    tangents_->c.setZero();
  }
  forcesZero_ = true;
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::commitState() {
  releaseHold();
  if (farInBothStates_) {  // the states differ in the gap alone
    committed_.gap = trial_.gap;
    return;
  }
  committed_ = trial_;
  farInBothStates_ = forcesZero_ && quietFar(committed_);
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::revertToLastCommit() {
  releaseHold();
  powerClosed_ = false;  // the last update's state is gone: the next one takes no scale
  if (farInBothStates_) {
    trial_.gap = committed_.gap;
    return;
  }
  trial_ = committed_;
  farInBothStates_ = forcesZero_ && quietFar(committed_);
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::revertToStart() {
  trial_ = committed_ = initial_;
  farInBothStates_ = false;
  releaseHold();
  powerClosed_ = false;
  forcesZero_ = false;
  clearForces();
}

template <int Ndf>
void NodeToSurfaceContact3d<Ndf>::holdStatus() {
  if (holding_) return;
  holding_ = true;
  held_ = natural_;
  lastInside_ = trial_.gap < 0.0;
  // An open pair has no friction branch yet: its first update in contact takes the cone's.
  frictionHeld_ = inContact(held_.normal);
  slideDirection_ = trialFriction_;
  noteTried(held_);
}

template <int Ndf>
elements::Element::HeldStatus NodeToSurfaceContact3d<Ndf>::checkHeldStatus() {
  if (!holding_) return HeldStatus::Agrees;
  const bool contact = inContact(held_.normal);
  const bool normalAgrees = held_.normal == NormalBranch::Spring
                                ? springAgrees_
                                : held_.normal == natural_.normal || onRamp_;
  // A switch back to a branch held before in this step would cycle.
  const bool normalCycles = (triedNormal_ & bit(natural_.normal)) != 0;
  const bool frictionCycles = triedSliding_ == 3;
  const bool frictionAgrees = !contact || !friction_.active() ||
                              held_.sliding == natural_.sliding ||
                              (frictionCycles && held_.sliding && slideAgrees_);
  if (normalAgrees && frictionAgrees) return HeldStatus::Agrees;
  if (++switches_ > kMaxSwitches) return HeldStatus::Conflict;
  Branches next = natural_;
  if (normalAgrees) {
    next.normal = held_.normal;
  } else if (inContact(held_.normal) && natural_.normal == NormalBranch::Open && separating_ &&
             closedAtCommit() && committed_.gap < 0.0 && !(normal_.exponent() > 1.0) &&
             (triedNormal_ & bit(NormalBranch::Release)) == 0) {
    // Closed at the last commit, and the held contact's end state on the face separates with a
    // force that would pull: the contact ends in this step, its end state either outside the
    // face on the release force or inside it with none. The release force first: open is free
    // flight, which in a step much longer than the impact ends far outside the face and is
    // contradicted there by the release force, a branch more (Kelvin, 1e9 kN/m on 1 t, 0.1 ms
    // impacts under 10 ms steps: 12 Newton iterations in a release step; 9 this way). A release
    // end state inside the face is contradicted in turn (the release force continues there
    // along its tangent, compressive). Not for a power law with n > 1, whose held release force
    // inside the face is a ramp in tension that an end state may agree with.
    next.normal = NormalBranch::Release;
  } else if (normalCycles && normal_.velocityDependent()) {
    // Closed inside the face against no force (open) or the release force (which is zero at the
    // face) outside it: for kelvin the jump of the dashpot force at g = 0; for a power law with a
    // rate term (hertzdamp, jankowski), no jump, but in a step much longer than the impact no
    // end state lies on either branch. Either way the spring alone is held while approaching.
    const auto free = [](NormalBranch b) {
      return b == NormalBranch::Open || b == NormalBranch::Release;
    };
    const bool acrossTheJump = (free(held_.normal) && natural_.normal == NormalBranch::Kelvin) ||
                               (held_.normal == NormalBranch::Kelvin && free(natural_.normal));
    if (acrossTheJump && approaching_) next.normal = NormalBranch::Spring;
  }
  // Into contact from open or release: the friction branch is the cone's at the next update.
  frictionHeld_ = inContact(next.normal) && inContact(held_.normal);
  noteTried(next);
  if (next.sliding) slideDirection_ = trialFriction_;
  held_ = next;
  lastInside_ = trial_.gap < 0.0;
  return HeldStatus::Switched;
}

template <int Ndf>
bool NodeToSurfaceContact3d<Ndf>::hasNonSymmetricTangent() const {
  return friction_.active() || normal_.velocityDependent();
}

template <int Ndf>
Status NodeToSurfaceContact3d<Ndf>::update(const elements::Kinematics& kin) {
  farInBothStates_ = false;
  natural_ = Branches{};
  springAgrees_ = slideAgrees_ = approaching_ = separating_ = onRamp_ = false;
  // The last update's penetration on a closed power-law branch: this update's change from it
  // is the step Newton took (newtonStepScale).
  const double lastGap = trial_.gap;
  const bool lastPowerClosed = powerClosed_;
  const bool lastSmooth = smoothClosed_;
  powerClosed_ = false;  // until this update reaches the normal law (the open paths return early)
  stepScale_ = 1.0;
  NodeToSurfaceState t = committed_;
  t.force.setZero();
  t.dashpotPower = 0.0;
  const bool hasVelocity = kin.v.size() == Base::kNumDof;

  std::array<Eigen::Vector3d, 5> x;
  for (int j = 0; j < 5; ++j) x[j] = X_[j] + kin.u.template segment<3>(j * Ndf);
  for (const auto& p : x)
    if (!p.allFinite()) return Status::NonFinite;
  const std::array<Eigen::Vector3d, 4> quad{x[1], x[2], x[3], x[4]};

  // Leaves the trial state open with zero force (accumulators still integrate the last step).
  auto finishOpen = [&](double gap, bool projValid) {
    t.status = ContactStatus::Open;
    t.stickValid = false;
    t.projValid = projValid;
    t.gap = gap;
    clearForces();
  };
  auto finishAccumulators = [&]() {
    t.impulse = committed_.impulse + 0.5 * kin.dt * (committed_.force + t.force);
    t.dampingEnergy =
        committed_.dampingEnergy + 0.5 * kin.dt * (committed_.dashpotPower + t.dashpotPower);
    trial_ = t;
  };

  // Search: a distance bound when the pair is far (ContactSearch); never in the step after a
  // closed state, whose release force (below) ends the contact however far the step carries the
  // faces apart.
  double bound = 0.0;
  if (!closedAtCommit() && search_.isFar(x[0], quad, frame_.n, bound)) {
    finishOpen(bound, false);
    finishAccumulators();
    return Status::Ok;
  }

  // In-plane coordinates and heights, relative to the reference centroid (keeps them small).
  std::array<Eigen::Vector2d, 5> s;
  std::array<double, 5> z;
  for (int j = 0; j < 5; ++j) {
    const Eigen::Vector3d r = x[j] - origin_;
    s[j] = Eigen::Vector2d(frame_.t1.dot(r), frame_.t2.dot(r));
    z[j] = frame_.n.dot(r);
  }
  const std::array<Eigen::Vector2d, 4> sq{s[1], s[2], s[3], s[4]};
  const auto xi = inverseBilinear(sq, s[0], 1e-12 * frame_.size);
  if (!xi || !onQuad(*xi)) {  // off the quad (slid past an edge): no contact
    finishOpen(z[0] - 0.25 * (z[1] + z[2] + z[3] + z[4]), false);
    finishAccumulators();
    return Status::Ok;
  }
  const auto Nd = shapeFunctions(xi->x(), xi->y());
  const double gap = z[0] - (Nd[0] * z[1] + Nd[1] * z[2] + Nd[2] * z[3] + Nd[3] * z[4]);
  t.projXi = *xi;
  // Release step: the contact was closed at the last commit and opens in this step. With the
  // trapezoidal rule (Newmark average acceleration) a zero force at the step end would let the
  // committed force push across the whole step, returning more energy than the spring held
  // (0.5 N_n (delta_n + |g|) instead of 0.5 N_n delta_n); a large step on a stiff contact could
  // then gain energy. The release force below makes the step's trapezoid work equal to
  // 0.5 N_r delta_n, N_r = min(N_n, K delta_n), the energy of linear unloading from the committed
  // state, so a release never adds energy; it is continuous (zero) at g = 0 and briefly tensile.
  const bool releasing = gap >= 0.0 && committed_.status != ContactStatus::Open &&
                         committed_.gap < 0.0 && committed_.force(0) > 0.0;
  // The branch of the normal law: the state's own, or the held one (holdStatus). A held
  // contact branch is evaluated on the face whatever the sign of the gap.
  const NormalBranch heldNormal = holding_ ? held_.normal : NormalBranch::Open;
  if (releasing) natural_.normal = NormalBranch::Release;
  if (gap >= 0.0 && !releasing && (!holding_ || heldNormal == NormalBranch::Open)) {
    finishOpen(gap, true);
    finishAccumulators();
    return Status::Ok;
  }

  // --- contact: evaluate the forces with derivatives -------------------------------------
  std::array<Vec3, 5> xa, va;
  for (int j = 0; j < 5; ++j)
    for (int d = 0; d < 3; ++d) {
      xa[j][d] = AD(x[j](d) - origin_(d), 2 * kTrans, 3 * j + d);
      const double vel = hasVelocity ? kin.v(j * Ndf + d) : 0.0;
      va[j][d] = AD(vel, 2 * kTrans, kTrans + 3 * j + d);
    }
  std::array<std::array<AD, 2>, 5> sa;
  std::array<AD, 5> za;
  for (int j = 0; j < 5; ++j) {
    sa[j] = {dot(frame_.t1, xa[j]), dot(frame_.t2, xa[j])};
    za[j] = dot(frame_.n, xa[j]);
  }
  // Projection: one Newton step from the converged xi carries exact first derivatives,
  // dxi = -J^-1 dr (implicit function theorem).
  Eigen::Matrix2d J;
  {
    const auto dN = shapeDerivatives(xi->x(), xi->y());
    J.setZero();
    for (int i = 0; i < 4; ++i)
      for (int a = 0; a < 2; ++a) J.col(a) += dN[a][i] * s[i + 1];
  }
  const Eigen::Matrix2d Jinv = J.inverse();
  std::array<AD, 2> res;
  for (int m = 0; m < 2; ++m) {
    res[m] = -sa[0][m];
    for (int i = 0; i < 4; ++i) res[m] += Nd[i] * sa[i + 1][m];
  }
  const AD xiA = xi->x() - (Jinv(0, 0) * res[0] + Jinv(0, 1) * res[1]);
  const AD etaA = xi->y() - (Jinv(1, 0) * res[0] + Jinv(1, 1) * res[1]);
  const std::array<AD, 4> N = shapeFunctions(xiA, etaA);
  const auto dN = shapeDerivatives(xiA, etaA);

  // Gap and the scaled surface normal m = n - w1 t1 - w2 t2, w = J^-T h (h = dz/dxi).
  AD g = za[0];
  for (int i = 0; i < 4; ++i) g -= N[i] * za[i + 1];
  std::array<std::array<AD, 2>, 2> Ja;  // Ja[m][a] = d s_m / d xi_a
  std::array<AD, 2> h;
  for (int a = 0; a < 2; ++a) {
    h[a] = AD(0.0);
    for (int m = 0; m < 2; ++m) Ja[m][a] = AD(0.0);
    for (int i = 0; i < 4; ++i) {
      h[a] += dN[a][i] * za[i + 1];
      for (int m = 0; m < 2; ++m) Ja[m][a] += dN[a][i] * sa[i + 1][m];
    }
  }
  const AD det = Ja[0][0] * Ja[1][1] - Ja[0][1] * Ja[1][0];
  const AD w0 = (Ja[1][1] * h[0] - Ja[1][0] * h[1]) / det;
  const AD w1 = (-Ja[0][1] * h[0] + Ja[0][0] * h[1]) / det;
  Vec3 m;
  for (int d = 0; d < 3; ++d) m[d] = frame_.n(d) - w0 * frame_.t1(d) - w1 * frame_.t2(d);

  // Relative velocity of k with respect to the target point p.
  Vec3 vrel;
  for (int d = 0; d < 3; ++d) {
    vrel[d] = va[0][d];
    for (int i = 0; i < 4; ++i) vrel[d] -= N[i] * va[i + 1][d];
  }
  const AD gdot = m[0] * vrel[0] + m[1] * vrel[1] + m[2] * vrel[2];  // = dg/dt exactly
  AD Nn = normal_.force(g, gdot);
  if (!releasing && g.value() < 0.0 && Nn.value() > 0.0) natural_.normal = NormalBranch::Kelvin;
  approaching_ = gdot.value() <= 0.0;
  separating_ = !approaching_;
  springAgrees_ = g.value() <= 0.0 && approaching_;
  if (holding_ && heldNormal == NormalBranch::Kelvin && normal_.law() == ImpactLaw::Jankowski &&
      normal_.velocityDependent()) {
    // Jankowski's held closed force continues across the face with a damping coefficient that
    // rises from the touch with infinite slope, c |delta|^(1/4): a cusp at the face, compressive
    // on both sides while the pair approaches. An end state within that rise (a step much longer
    // than the impact may need the damping force at a penetration of 1e-14 m) is out of Newton's
    // reach: its iterates jumped back and forth across the face, or settled outside it on the
    // continuation's compression, which the state then contradicts. As at Kelvin's dashpot jump
    // (checkHeldStatus), the spring alone is held while the pair approaches once the iterates
    // cross the face. (Kelvin's held force is linear across the face, and hertzdamp's damping
    // c delta^n gdot is smooth there.)
    const bool inside = g.value() < 0.0;
    if (inside != lastInside_) ++crossings_;
    lastInside_ = inside;
    if (crossings_ >= kMaxCrossings && approaching_) {
      held_.normal = NormalBranch::Spring;
      noteTried(held_);
    }
  }
  NormalBranch branch = holding_ ? held_.normal : natural_.normal;
  switch (branch) {
    case NormalBranch::Open: Nn = AD(0.0); break;
    case NormalBranch::Kelvin:
      if (holding_) Nn = normal_.closedForce(g, gdot);
      break;
    case NormalBranch::Spring: Nn = normal_.closedForce(g, AD(0.0)); break;
    case NormalBranch::Release:
      // A held release branch inside the face goes on smooth and monotone (the release force
      // has a pole at g = g_n): kelvin along its tangent at g = 0, N = N_r g / g_n; a power law
      // along a ramp from its tension at the face to zero just inside it, the end state in the
      // jump from the closed force (NormalLaw::releaseForce, onReleaseRamp).
      Nn = normal_.releaseForce(g, committed_.gap, committed_.force(0), holding_);
      break;
  }
  const bool releaseForce = branch == NormalBranch::Release;
  onRamp_ = releaseForce && holding_ && normal_.onReleaseRamp(g.value(), Nn.value());
  t.gap = g.value();
  // A closed power law: inside the face, or held on either side (its odd continuation outside,
  // where Newton closes in on the face as slowly). Jankowski's damping has a cusp at the face;
  // the spring alone and the other laws are smooth across it (NormalLaw::forceVariableStepScale).
  powerClosed_ = normal_.exponent() > 1.0 && inContact(branch) &&
                 (holding_ || (g.value() < 0.0 && Nn.value() > 0.0));
  smoothClosed_ = branch == NormalBranch::Spring || normal_.law() != ImpactLaw::Jankowski;
  if (powerClosed_ && lastPowerClosed && lastGap != 0.0) {
    // Newton is slow on the spring where it removes about 1/n of the penetration in two updates
    // running (NormalLaw::slowShrink); one such step alone is often the inertia's (a touch
    // step's first iterate), where Newton's own step is the better one.
    const double side = lastGap < 0.0 ? 1.0 : -1.0;  // the sign of the last penetration
    const double delta = std::abs(lastGap), change = side * (lastGap - g.value());
    shrinks_ = normal_.slowShrink(delta, change) ? std::uint8_t(std::min(shrinks_ + 1, 2)) : 0;
    if (shrinks_ >= 2)
      stepScale_ = normal_.forceVariableStepScale(delta, change, lastSmooth && smoothClosed_);
  } else {
    shrinks_ = 0;
  }
  // Dashpot power: (N - spring force) times the approach rate -gdot; when N is clipped this is
  // the released spring energy, so the energy balance stays closed.
  t.dashpotPower = (Nn.value() - normal_.elasticForce(g.value())) * (-gdot.value());
  if (releaseForce) {
    t.status = ContactStatus::Open;
    t.stickValid = false;
  } else if (branch == NormalBranch::Open ||
             (!holding_ && !(Nn.value() > 0.0))) {  // the contact would pull: no force
    finishOpen(g.value(), true);
    finishAccumulators();
    return Status::Ok;
  }

  std::array<AD, 2> Ft{AD(0.0), AD(0.0)};
  if (!releaseForce) t.status = ContactStatus::Slide;  // frictionless contact slides freely
  t.stickValid = false;
  if (friction_.active() && !releaseForce) {
    const bool wasInContact = committed_.status != ContactStatus::Open && committed_.stickValid;
    const Eigen::Vector2d xiS =
        wasInContact ? committed_.stickXi : (committed_.projValid ? committed_.projXi : *xi);
    const auto Ns = shapeFunctions(xiS.x(), xiS.y());
    // A pair that comes onto the face from beyond its edge has no committed projection: its
    // stick point is the trial's own projection, so d is zero whatever the trial (zero
    // derivatives too; with the point's coordinates frozen the tangent would say Kt while the
    // force stays zero, and Newton converged linearly on a contactor sliding onto the next face).
    const bool stickAtTrial = !wasInContact && !committed_.projValid;
    std::array<AD, 2> d, vt;
    for (int a = 0; a < 2; ++a) {
      d[a] = stickAtTrial ? AD(0.0) : sa[0][a];
      if (!stickAtTrial)
        for (int i = 0; i < 4; ++i) d[a] -= Ns[i] * sa[i + 1][a];
    }
    vt[0] = dot(frame_.t1, vrel);
    vt[1] = dot(frame_.t2, vrel);
    using Branch = CoulombFriction::Branch;
    const bool wasSliding = committed_.status == ContactStatus::Slide;
    Branch held = !holding_ || held_.normal != branch || !frictionHeld_ ? Branch::Natural
                  : held_.sliding                                       ? Branch::Slide
                                                                        : Branch::Stick;
    auto r = friction_.returnMap(d, Nn, vt, wasSliding, held);
    if (holding_ && held_.normal == branch && !frictionHeld_) {
      // The first update of a held contact branch whose friction branch is not known (it was
      // open when held or switched): hold the cone's branch from here on.
      frictionHeld_ = true;
      held_.sliding = r.coneExceeded;
      slideDirection_ = r.trial;
      triedSliding_ = static_cast<std::uint8_t>(triedSliding_ | (r.coneExceeded ? 2u : 1u));
    }
    if (held == Branch::Slide && r.trial.dot(slideDirection_) < 0.0) {
      // The held slide reversed: the sliding force jumps from one side of the cone to the other
      // there, and an end state lies in the jump (the relative motion stops: stick). One way,
      // so the hold cannot cycle within the iterations.
      held_.sliding = false;
      ++switches_;
      triedSliding_ = static_cast<std::uint8_t>(triedSliding_ | 1u);
      held = Branch::Stick;
      r = friction_.returnMap(d, Nn, vt, wasSliding, held);
    }
    trialFriction_ = r.trial;
    natural_.sliding = r.coneExceeded;
    slideAgrees_ = r.aboveKinetic;
    Ft = r.force;
    t.status = r.sliding ? ContactStatus::Slide : ContactStatus::Stick;
    const Eigen::Vector2d dTrial(d[0].value(), d[1].value());
    if (r.sliding) {
      // New stick point: the target point whose in-plane position is s_k - d_after.
      const auto moved = inverseBilinear(sq, s[0] - r.elasticAfter, 1e-12 * frame_.size);
      t.stickXi = moved ? *moved : *xi;
      t.plasticSlip += dTrial - r.elasticAfter;
      t.slipLength += r.plasticSlip;
      t.frictionEnergy += Eigen::Vector2d(Ft[0].value(), Ft[1].value()).norm() * r.plasticSlip;
    } else {
      t.stickXi = xiS;
      t.dashpotPower +=
          friction_.damping() * (vt[0].value() * vt[0].value() + vt[1].value() * vt[1].value());
    }
    t.stickValid = true;
  }

  // Force on the contactor R = N m + F1 t1 + F2 t2; internal forces f_k = -R, f_i = N_i R.
  Vec3 R;
  for (int d = 0; d < 3; ++d) R[d] = Nn * m[d] + Ft[0] * frame_.t1(d) + Ft[1] * frame_.t2(d);
  if (!tangents_) tangents_ = std::make_unique<Tangents>();  // once: the first contact
  typename Base::Matrix& k = tangents_->k;
  typename Base::Matrix& c = tangents_->c;
  this->f_.setZero();
  k.setZero();
  c.setZero();
  forcesZero_ = false;
  for (int j = 0; j < 5; ++j)
    for (int d = 0; d < 3; ++d) {
      const AD fjd = j == 0 ? AD(-R[d]) : AD(N[j - 1] * R[d]);
      const int row = j * Ndf + d;
      this->f_(row) = fjd.value();
      for (int jj = 0; jj < 5; ++jj)
        for (int dd = 0; dd < 3; ++dd) {
          k(row, jj * Ndf + dd) = fjd.derivatives()(3 * jj + dd);
          c(row, jj * Ndf + dd) = fjd.derivatives()(kTrans + 3 * jj + dd);
        }
    }
  t.force = Eigen::Vector3d(Nn.value(), Ft[0].value(), Ft[1].value());
  t.projValid = true;
  finishAccumulators();
  return Status::Ok;
}

template <int Ndf>
std::optional<Eigen::VectorXd> NodeToSurfaceContact3d<Ndf>::response(
    std::span<const std::string> args) const {
  if (args.size() != 1) return Base::response(args);
  const std::string& name = args[0];
  const NodeToSurfaceState& s = trial_;
  if (name == "contactForce") return Eigen::VectorXd(s.force);
  if (name == "gap") return Eigen::VectorXd::Constant(1, s.gap);
  if (name == "status") return Eigen::VectorXd::Constant(1, static_cast<double>(s.status));
  if (name == "slip")
    return Eigen::Vector3d(s.slipLength, s.plasticSlip(0), s.plasticSlip(1)).eval();
  if (name == "dissipatedEnergy")
    return Eigen::Vector3d(s.frictionEnergy + s.dampingEnergy, s.frictionEnergy, s.dampingEnergy)
        .eval();
  if (name == "impulse") return Eigen::VectorXd(s.impulse);
  return Base::response(args);
}

template <int Ndf>
std::string NodeToSurfaceContact3d<Ndf>::describe() const {
  std::ostringstream out;
  out << Base::describe() << " law " << NormalLaw::name(params_.law) << " K " << params_.K;
  if (params_.law == ImpactLaw::Hertz || params_.law == ImpactLaw::HertzDamp)
    out << " n " << params_.n;
  if (params_.law == ImpactLaw::HertzDamp) out << " v0 " << params_.v0;
  if (params_.Kt > 0.0) out << " Kt " << params_.Kt;
  out << " e " << params_.e << " et " << params_.et << " mu_s " << params_.muS << " mu_k "
      << params_.muK << " C " << normal_.damping() << " Ct " << friction_.damping() << " search "
      << params_.search << " normal (" << frame_.n.transpose() << ")";
  return out.str();
}

bool FarTest::isFar(const std::array<Eigen::Vector3d, 5>& u, double& b) const noexcept {
  std::array<Eigen::Vector3d, 5> x;
  for (std::size_t j = 0; j < 5; ++j) x[j] = X[j] + u[j];
  const std::array<Eigen::Vector3d, 4> quad{x[1], x[2], x[3], x[4]};
  return x[0].allFinite() && search.isFar(x[0], quad, n, b);
}

template <int Ndf>
bool NodeToSurfaceContact3d<Ndf>::updateIfFar(const std::array<Eigen::Vector3d, 5>& u, double dt) {
  if (!search_.enabled() || closedAtCommit()) return false;
  double bound = 0.0;
  return farTest().isFar(u, bound) && setFarTrial(bound, dt);
}

template <int Ndf>
bool NodeToSurfaceContact3d<Ndf>::setFarTrialFromCommitted(double bound, double dt) {
  if (!search_.enabled()) return false;
  if (farInBothStates_) {  // the step of a far pair from a far committed state: the gap alone
                           // changes
    trial_.gap = bound;
    return true;
  }
  if (closedAtCommit()) return false;
  // What update() does for a far pair: open, no force, accumulators over the step. From a far
  // committed state (no force, no dashpot power) that is the committed state with the new bound,
  // and the trial state already equals the committed one but for the gap (commit and revert copy
  // the whole state, or the gap alone when the rest is equal; only update() and this function
  // write it otherwise).
  if (forcesZero_ && committed_.status == ContactStatus::Open && !committed_.projValid &&
      committed_.force.isZero(0.0) && committed_.dashpotPower == 0.0 &&
      trial_.status == ContactStatus::Open && !trial_.projValid && trial_.force.isZero(0.0) &&
      trial_.impulse == committed_.impulse && trial_.dampingEnergy == committed_.dampingEnergy) {
    trial_.gap = bound;
    return true;
  }
  NodeToSurfaceState t = committed_;
  t.force.setZero();
  t.dashpotPower = 0.0;
  t.status = ContactStatus::Open;
  t.stickValid = false;
  t.projValid = false;
  t.gap = bound;
  clearForces();
  t.impulse = committed_.impulse + 0.5 * dt * (committed_.force + t.force);
  t.dampingEnergy =
      committed_.dampingEnergy + 0.5 * dt * (committed_.dashpotPower + t.dashpotPower);
  trial_ = t;
  return true;
}

template <int Ndf>
double NodeToSurfaceContact3d<Ndf>::contactDuration(std::span<const double> nodeMasses,
                                                    double gapRate) const {
  double m1 = params_.M1, m2 = params_.M2;
  if (!(m1 > 0.0 && m2 > 0.0)) {
    m1 = nodeMasses.empty() ? 0.0 : nodeMasses[0];
    m2 = 0.0;
    for (std::size_t i = 1; i < nodeMasses.size(); ++i) m2 += nodeMasses[i];
  }
  // A face without mass is fixed (the contactor's mass alone); no contactor mass: no limit.
  if (!(m1 > 0.0)) return std::numeric_limits<double>::infinity();
  const double m = m2 > 0.0 ? m1 * m2 / (m1 + m2) : m1;
  const double n = normal_.exponent();
  if (n == 1.0) return std::numbers::pi * std::sqrt(m / params_.K);
  // Power law N = k delta^n, undamped: the energy m v^2 / 2 + k delta^(n+1) / (n+1) of the
  // relative motion is constant in contact, so the impact speed v follows from the committed
  // penetration and the gap rate, the largest penetration from m v^2 / 2 = k dmax^(n+1) / (n+1),
  // and the duration is 2 (dmax / v) I(n), I(n) = int_0^1 dx / sqrt(1 - x^(n+1))
  // = sqrt(pi) Gamma(1 + 1/(n+1)) / Gamma(1/2 + 1/(n+1)) (pi/2 for n = 1; 1.4716 for Hertz's 1.5,
  // the duration 2.94 dmax / v of Johnson, Contact Mechanics, 1985, section 11.4).
  const double k = params_.K;
  const double delta = committed_.gap < 0.0 ? -committed_.gap : 0.0;
  const double v2 = gapRate * gapRate + 2.0 * k * std::pow(delta, n + 1.0) / ((n + 1.0) * m);
  if (!(v2 > 0.0) || !std::isfinite(v2)) return std::numeric_limits<double>::infinity();
  const double v = std::sqrt(v2);
  const double dmax = std::pow(0.5 * (n + 1.0) * m * v2 / k, 1.0 / (n + 1.0));
  const double p = 1.0 / (n + 1.0);
  const double integral = std::sqrt(std::numbers::pi) * std::tgamma(1.0 + p) / std::tgamma(0.5 + p);
  return 2.0 * dmax / v * integral;
}

template <int Ndf>
double NodeToSurfaceContact3d<Ndf>::touchStep(double gapRate) const {
  const double m1 = params_.M1, m2 = params_.M2;
  const double c = normal_.damping();
  const bool rises = normal_.law() == ImpactLaw::Kelvin || normal_.law() == ImpactLaw::Jankowski;
  if (!rises || !(c > 0.0) || !(m1 > 0.0 && m2 > 0.0))
    return std::numeric_limits<double>::infinity();
  // The relative momentum m v against the impulse the trapezoid rule misplaces in the step that
  // holds the touch, about half the damping force at its end times the step (it credits the step
  // with half its end force whatever part of it the pair was closed): 1 %, the hard-impact
  // suite's xi omega h = 0.01 for Kelvin (verification/pounding/hard-impacts.md).
  constexpr double kMomentumShare = 0.01;
  const double m = m1 * m2 / (m1 + m2);
  if (normal_.law() == ImpactLaw::Kelvin) return 2.0 * kMomentumShare * m / c;
  // Jankowski: c (v h)^(1/4) v h / 2 = 0.01 m v.
  const double v = std::abs(gapRate);
  if (!(v > 0.0) || !std::isfinite(v)) return std::numeric_limits<double>::infinity();
  return std::pow(2.0 * kMomentumShare * m / (c * std::pow(v, 0.25)), 0.8);
}

template class NodeToSurfaceContact3d<3>;
template class NodeToSurfaceContact3d<6>;

}  // namespace dabs::contact
