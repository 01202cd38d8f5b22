// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/SleepingPairs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dabs::analysis {

namespace {
const double kInfinity = std::numeric_limits<double>::infinity();
// A node's translations, trial or committed.
Eigen::Vector3d translation(const domain::Node& n, bool committed) {
  return committed ? Eigen::Vector3d(n.committedDisp.head<3>()) : Eigen::Vector3d(n.disp.head<3>());
}
// The far test's bound, max(slab, sphere), changes by at most 4 mu when each of the five nodes
// moves by at most mu: the slab bound n.x_k - max_j n.x_j by 2 mu (|n| = 1), the sphere bound
// |x_k - c| - r (c the corners' centroid, r the largest corner distance from it) by
// |dx_k - dc| + |dr| <= 2 mu + 2 mu.
constexpr double kBoundLipschitz = 4.0;
// How far a pair may be brought towards its search distance before its exact test is due: its
// bound's excess over the distance, less a margin for the round-off of the bound (coordinates of
// a long viaduct reach 1e3 m, where one ulp is 1e-13 m; the margin is micrometres).
double farSlack(double bound, double distance, const Eigen::Vector3d& X) {
  return bound - distance - 1e-9 * (1.0 + std::abs(bound) + X.lpNorm<Eigen::Infinity>());
}
}  // namespace

bool SleepingPairs::wantsSleep(const elements::FarPair& far) const {
  const auto it = sleepWanted_.find(&far);
  if (it != sleepWanted_.end()) return it->second;
  return far.committedFar();
}

void SleepingPairs::build(std::vector<Pair> pairs, const DofSource& dofs) {
  pairs_.assign(pairs.size(), PairLink{});
  tags_.assign(pairs.size(), 0);
  sleeping_ = 0;
  std::vector<FarFace> faceOf(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Pair& in = pairs[i];
    PairLink& p = pairs_[i];
    const elements::FarPair::Geometry test = in.far->farGeometry();
    p.link = in.link;
    p.contactor = in.contactor;
    p.X = test.X[0];
    p.distance = test.distance;
    p.far = in.far;
    p.domainIndex = in.domainIndex;
    p.sleeping = in.sleeping;
    tags_[i] = in.tag;
    if (in.sleeping) ++sleeping_;
    FarFace& f = faceOf[i];
    for (std::size_t j = 0; j < 4; ++j) {
      f.nodes[j] = in.face[j];
      f.X[j] = test.X[j + 1];
    }
    f.n = test.n;
  }
  // Runs of consecutive pairs against the same face (bitwise the same data, so the slab top the
  // run forms once is the one each pair would form).
  farFaces_.clear();
  for (std::size_t i = 0; i < faceOf.size(); ++i) {
    const FarFace& f = faceOf[i];
    if (!farFaces_.empty()) {
      FarFace& last = farFaces_.back();
      if (last.nodes == f.nodes && last.X == f.X && last.n == f.n) {
        last.end = static_cast<std::uint32_t>(i + 1);
        continue;
      }
    }
    farFaces_.push_back(f);
    farFaces_.back().first = static_cast<std::uint32_t>(i);
    farFaces_.back().end = static_cast<std::uint32_t>(i + 1);
  }
  domain_.clearStateKept();
  markObserved();
  buildMotionBounds(dofs);
  sleepWanted_.clear();
  haveU_ = false;
}

double SleepingPairs::slabTopAt(const FarFace& f, bool committed) {
  std::array<Eigen::Vector3d, 4> quad;
  for (std::size_t j = 0; j < 4; ++j) quad[j] = f.X[j] + translation(*f.nodes[j], committed);
  return elements::FarPair::slabTop(quad, f.n);
}

bool SleepingPairs::sleeperBound(const PairLink& p, const FarFace& f, double top, bool committed,
                                 double& bound) {
  // The same arithmetic as the pair's own test (which takes the slab first), so
  // the bound, and with it the gap the pair reports, is the same to the bit; when the slab does
  // not show the pair far, the pair's whole test decides. A finite slab bound needs a finite
  // position (a non-finite coordinate makes n.x non-finite), which the pair's test asks for.
  const Eigen::Vector3d x = p.X + translation(*p.contactor, committed);
  const double slab = elements::FarPair::slabBound(x, f.n, top);
  if (slab > p.distance && slab < kInfinity) {
    bound = slab;
    return true;
  }
  std::array<Eigen::Vector3d, 5> u;
  u[0] = translation(*p.contactor, committed);
  for (std::size_t j = 0; j < 4; ++j) u[j + 1] = translation(*f.nodes[j], committed);
  return p.far->isFarAt(u, bound);
}

void SleepingPairs::buildMotionBounds(const DofSource& dofs) {
  faceMotion_.clear();
  for (const FarFace& f : farFaces_) {
    faceMotion_.beginGroup();
    std::vector<const domain::Node*> nodes(f.nodes.begin(), f.nodes.end());
    for (std::uint32_t i = f.first; i < f.end; ++i) nodes.push_back(pairs_[i].contactor);
    for (const domain::Node* n : nodes) {
      const int first = dofs.firstDof(n->tag());
      for (int d = 0; d < 3; ++d) {
        const auto g = static_cast<std::size_t>(first + d);
        if (const int eq = dofs.directEq[g]; eq >= 0)
          faceMotion_.addEquation(eq);
        else
          faceMotion_.addTranslation(dofs.dofTerms[g]);
      }
    }
    faceMotion_.endGroup();
  }
  faceHorizon_.assign(farFaces_.size(), -kInfinity);
}

void SleepingPairs::setDisplacements(const Eigen::VectorXd& U) {
  // Read only to defer a face's test, which needs an unobserved pair: with every pair observed
  // (contact stepping, a script after each step) no copy is made in the Newton iterations.
  if (!mayDefer_) return;
  U_ = U;
  haveU_ = true;
}

void SleepingPairs::deferFace(std::size_t r, double reach, std::span<const SupportSlot> slots) {
  if (!haveU_) return;  // no motion bound: no deferral
  faceMotion_.snapshot(r, U_, slots);
  const bool wasDeferred = faceHorizon_[r] > -kInfinity;
  faceHorizon_[r] = reach;
  if (wasDeferred) return;
  const FarFace& f = farFaces_[r];
  for (std::uint32_t i = f.first; i < f.end; ++i) domain_.setStateKept(pairs_[i].domainIndex, true);
}

double SleepingPairs::faceMoved(std::size_t r, std::span<const SupportSlot> slots) const {
  if (!haveU_) return kInfinity;
  return faceMotion_.moved(r, U_, slots);
}

bool SleepingPairs::retestFace(std::size_t r, std::span<const SupportSlot> slots) {
  const FarFace& f = farFaces_[r];
  const double top = slabTopAt(f, false);
  double slack = kInfinity;
  for (std::uint32_t i = f.first; i < f.end; ++i) {
    const PairLink& p = pairs_[i];
    double bound = 0.0;
    ++farTests_;
    if (!sleeperBound(p, f, top, false, bound)) return false;
    slack = std::min(slack, farSlack(bound, p.distance, p.X));
  }
  deferFace(r, slack / kBoundLipschitz, slots);  // measured from here on
  return true;
}

void SleepingPairs::endDeferral(std::size_t r) {
  // The committed positions are within the face's horizon (the displacements the checks saw:
  // beginSteps defers no test under an integrator that checks at others), so every pair is
  // far there, and its bound there is the gap the check of every step would have committed.
  const FarFace& f = farFaces_[r];
  const double top = slabTopAt(f, true);
  for (std::uint32_t i = f.first; i < f.end; ++i) {
    const PairLink& p = pairs_[i];
    double bound = 0.0;
    sleeperBound(p, f, top, true, bound);
    p.far->setGapInBothStates(bound);
    domain_.setStateKept(p.domainIndex, false);
  }
  faceHorizon_[r] = -kInfinity;
}

std::size_t SleepingPairs::deferredFaces() const {
  return static_cast<std::size_t>(std::count_if(faceHorizon_.begin(), faceHorizon_.end(),
                                                [](double h) { return h > -kInfinity; }));
}

void SleepingPairs::beginSteps(bool observeAll) {
  endSteps();
  observeAll_ = observeAll;
  observedTags_ = observeAll ? std::vector<int>{} : domain_.recordedElements();
  markObserved();
}

void SleepingPairs::endSteps() {
  for (std::size_t r = 0; r < faceHorizon_.size(); ++r)
    if (faceHorizon_[r] > -kInfinity) endDeferral(r);
  haveU_ = false;
}

void SleepingPairs::markObserved() {
  mayDefer_ = false;
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    PairLink& p = pairs_[i];
    p.observed =
        observeAll_ || std::binary_search(observedTags_.begin(), observedTags_.end(), tags_[i]);
    mayDefer_ = mayDefer_ || !p.observed;
  }
}

SleepingPairs::Check SleepingPairs::check(double dt, std::span<const SupportSlot> slots,
                                          const Waker& wake) {
  Check result = Check::Unchanged;
  // Broad phase per target face: the bounding volume of a master surface is formed once and
  // tested against each of its slave nodes, as in the global search of contact codes (the
  // slave-master search of Benson and Hallquist, CMAME 78 (1990) 141-163; bounding volumes per
  // contact surface, Yang and Laursen, Comput Mech 41 (2008) 189-205). Here the volume is the
  // face's slab along its normal: its top is formed once per run of pairs against the face, and
  // each of its contactors costs its height above it. The pairs are taken in the domain's order.
  //
  // Deferred tests: a face whose pairs all sleep far in both states and are read by nobody during
  // the steps (beginSteps: no recorder names them, no contact stepping, no script after each step,
  // more than one step, an integrator that checks at the committed displacements) is left untested
  // until its pairs' nodes could have moved far enough to bring one of them to its search distance:
  // how far they moved since the face's last exact test is bounded by the largest change since then
  // of the equations and support values their translations are formed from, and the face is due
  // when that reaches the smallest excess of its pairs' bounds over their distances at the test,
  // over the bound's Lipschitz constant. This is the neighbour list with a skin of molecular
  // dynamics (Verlet, Phys Rev 159 (1967) 98-103; the list is rebuilt when the largest displacement
  // since it was built could have closed the skin, Allen and Tildesley, Computer Simulation of
  // Liquids, 2nd ed. 2017, sec. 5.3). The face is tested exactly when its horizon is reached, so a
  // pair is woken at the same step as with the test of every step, and the results do not change. A
  // pair of a deferred face is not committed (Domain::setStateKept); its gap is formed at the
  // committed positions when it is read again (endDeferral, endSteps).
  for (std::size_t r = 0; r < farFaces_.size(); ++r) {
    if (faceHorizon_[r] > -kInfinity) {
      if (faceMoved(r, slots) < faceHorizon_[r]) continue;  // far for sure
      if (retestFace(r, slots)) continue;
      endDeferral(r);
    }
    const FarFace& f = farFaces_[r];
    double top = 0.0;
    bool topFormed = false;
    bool mayDefer = mayDefer_;
    double slack = kInfinity;
    for (std::uint32_t i = f.first; i < f.end; ++i) {
      const PairLink& p = pairs_[i];
      if (p.sleeping) {
        if (!topFormed) {
          top = slabTopAt(f, false);
          topFormed = true;
        }
        double bound = 0.0;
        ++farTests_;
        if (sleeperBound(p, f, top, false, bound) && p.far->setFarTrial(bound, dt)) {
          if (mayDefer) {
            mayDefer = !p.observed && p.far->farInBothStates();
            slack = std::min(slack, farSlack(bound, p.distance, p.X));
          }
          continue;
        }
      }
      mayDefer = false;
      if (p.sleeping) {
        // Near: its full update for this trial state; with force the step missed it.
        sleepWanted_[p.far] = false;
        if (wake(p.link)) return Check::RedoStep;
        result = Check::PatternChange;
      } else if (p.far->trialFarBeyond(2.0)) {
        sleepWanted_[p.far] = true;
        if (result == Check::Unchanged) result = Check::PatternChange;
      }
    }
    if (mayDefer && f.end > f.first) deferFace(r, slack / kBoundLipschitz, slots);
  }
  return result;
}

SleepingPairs::Carried SleepingPairs::beforeRebuild() {
  for (const PairLink& p : pairs_)  // pairs without a change keep their state
    sleepWanted_.emplace(p.far, p.sleeping);
  Carried carried;
  for (std::size_t r = 0; r < farFaces_.size(); ++r) {
    if (!(faceHorizon_[r] > -kInfinity)) continue;
    carried.faces.emplace(
        pairs_[farFaces_[r].first].far,
        Carried::Face{faceMotion_.save(r), faceHorizon_[r], farFaces_[r].end - farFaces_[r].first});
    endDeferral(r);
  }
  return carried;
}

void SleepingPairs::afterRebuild(const Carried& carried) {
  for (std::size_t r = 0; r < farFaces_.size() && !carried.faces.empty(); ++r) {
    const FarFace& f = farFaces_[r];
    const auto it = carried.faces.find(pairs_[f.first].far);
    if (it == carried.faces.end()) continue;
    bool same = f.end - f.first == it->second.pairs;
    for (std::uint32_t i = f.first; i < f.end && same; ++i)
      same = pairs_[i].sleeping && !pairs_[i].observed;
    if (!same || !faceMotion_.restore(r, it->second.motion)) continue;
    faceHorizon_[r] = it->second.horizon;
    for (std::uint32_t i = f.first; i < f.end; ++i)
      domain_.setStateKept(pairs_[i].domainIndex, true);
  }
}

}  // namespace dabs::analysis
