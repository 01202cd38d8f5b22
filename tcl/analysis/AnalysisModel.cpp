// SPDX-License-Identifier: MIT
// Over 400 lines: the numbering (DofNumberer), the constraints (ConstraintHandler) and the sparse
// pattern (AssemblyPattern) live in their own files; what stays here is what works on the
// per-element and per-node scatter records (ElementLink, NodeLink), which are private to this
// class: building them, the sleeping contact pairs and their resting faces (whose motion bound
// is MotionWatch's), gathering and updating, and assembling the residual and the tangent
// through them.
#include "tcl/analysis/AnalysisModel.h"

#include <algorithm>
#include <limits>
#include <map>
#include <span>
#include <string>

#include "tcl/analysis/AssemblyPattern.h"
#include "tcl/analysis/DofNumberer.h"

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
double restSlack(double bound, double distance, const Eigen::Vector3d& X) {
  return bound - distance - 1e-9 * (1.0 + std::abs(bound) + X.lpNorm<Eigen::Infinity>());
}
}  // namespace

AnalysisModel::AnalysisModel(domain::Domain& domain, ConstraintKind constraints,
                             NumbererKind numberer, double alphaSP, double alphaMP)
    : domain_(domain),
      constraints_(constraints),
      numberer_(numberer),
      alphaSP_(alphaSP),
      alphaMP_(alphaMP) {}

bool AnalysisModel::nonSymmetric() const {
  return std::any_of(elements_.begin(), elements_.end(),
                     [](const ElementLink& l) { return l.element->hasNonSymmetricTangent(); });
}

bool AnalysisModel::nonSymmetricNow() const {
  const auto awake = awakeLinks();
  return std::any_of(awake.begin(), awake.end(), [](const ElementLink& l) {
    return l.element->isActive() && l.element->hasNonSymmetricTangent();
  });
}

bool AnalysisModel::allLinear() const {
  return std::all_of(elements_.begin(), elements_.end(),
                     [](const ElementLink& l) { return l.element->isLinear(); });
}

void AnalysisModel::build() {
  numberEquations();
  buildScatter();
  buildConstantDynamics();
  builtVersion_ = domain_.modelVersion();
}

void AnalysisModel::numberEquations() {
  nodes_.clear();
  nodeIndex_.clear();
  std::vector<NodeDofs> nodeDofs;
  int ndofTotal = 0;
  for (auto& [tag, node] : domain_.nodes()) {
    nodeIndex_[tag] = static_cast<int>(nodes_.size());
    nodes_.push_back(NodeLink{&node, ndofTotal, {}, {}, {}, domain_.nodeAlphaM(tag)});
    nodeDofs.push_back(NodeDofs{&node, ndofTotal});
    ndofTotal += node.ndf();
  }
  const std::vector<int> order = DofNumberer(numberer_).order(domain_, nodeIndex_);
  DofMap map = ConstraintHandler(constraints_, alphaSP_, alphaMP_)
                   .apply(domain_, nodeDofs, nodeIndex_, order);
  neq_ = map.numEquations;
  dofTerms_ = std::move(map.dofTerms);
  directEq_ = std::move(map.directEq);
  slots_ = std::move(map.slots);
  patternSlots_ = std::move(map.patternSlots);
  imposedMotion_ = map.imposedMotion;
  eqDof_ = std::move(map.eqDof);
  penalties_ = std::move(map.penalties);
  supportMotion_.assign(patternSlots_.size(), domain::SupportMotion{});
}

void AnalysisModel::buildScatter() {
  // Pattern: every equation pair coupled by an element, a nodal mass, a penalty row or the
  // diagonal.
  AssemblyPattern pattern;
  auto eqsOfDof = [&](int g, std::vector<std::pair<int, double>>& out) {
    out.clear();
    for (const Term& t : dofTerms_[static_cast<std::size_t>(g)])
      if (t.index >= 0) out.emplace_back(t.index, t.coef);
  };

  elements_.clear();
  std::vector<std::vector<std::pair<int, double>>> localEqs;
  std::vector<std::pair<int, double>> scratch;
  sleeping_ = 0;
  pairLinks_.clear();
  for (const auto& [etag, e] : domain_.elements()) {
    ElementLink link;
    link.element = e.get();
    link.rayleigh = domain_.elementRayleigh(etag);
    link.rayleighOn = link.rayleigh.any();
    const int n = e->numDof();
    link.far = e->farPair();
    link.asleep = wantsSleep(link);
    if (link.asleep) ++sleeping_;
    // A sleeper gets its buffers when it wakes (they would spread the awake links' data).
    if (!link.asleep) allocateBuffers(link, n);
    localEqs.assign(static_cast<std::size_t>(n), {});
    int local = 0;
    for (int nt : e->nodeTags()) {
      NodeLink& nl = nodes_[static_cast<std::size_t>(nodeIndex_.at(nt))];
      link.nodes.push_back(nl.node);
      for (int d = 0; d < nl.node->ndf(); ++d, ++local) {
        eqsOfDof(nl.firstDof + d, scratch);
        localEqs[static_cast<std::size_t>(local)] = scratch;
        if (!link.asleep)  // a sleeper adds nothing to the residual
          for (auto [eq, c] : scratch) link.vec.push_back(VecEntry{local, eq, c});
      }
    }
    link.direct.assign(static_cast<std::size_t>(n), -1);
    for (const VecEntry& v : link.vec) {
      auto& d = link.direct[static_cast<std::size_t>(v.local)];
      if (d >= 0 || v.coef != 1.0) {
        link.direct.clear();
        break;
      }
      d = v.eq;
    }
    for (int i = 0; i < n && !link.asleep; ++i)
      for (auto [ea, ca] : localEqs[static_cast<std::size_t>(i)])
        for (int j = 0; j < n; ++j)
          for (auto [eb, cb] : localEqs[static_cast<std::size_t>(j)]) {
            pattern.couple(ea, eb);
            link.mat.push_back(MatEntry{j * n + i, -1, ca * cb});  // value fixed below
            link.rowCol.emplace_back(ea, eb);
          }
    link.rates = !e->isLinear() || imposedMotion_ || e->mayTurnInactive() ||
                 !e->dampingTangent().isZero(0.0);
    link.switching = e->switchesStatus();
    elements_.push_back(std::move(link));
  }
  for (NodeLink& nl : nodes_) {
    nl.mass.clear();
    nl.vec.clear();
    const int ndf = nl.node->ndf();
    localEqs.assign(static_cast<std::size_t>(ndf), {});
    for (int d = 0; d < ndf; ++d) {
      eqsOfDof(nl.firstDof + d, scratch);
      localEqs[static_cast<std::size_t>(d)] = scratch;
      for (auto [eq, c] : scratch) nl.vec.push_back(VecEntry{d, eq, c});
    }
    const Eigen::MatrixXd& m = nl.node->mass();
    for (int i = 0; i < ndf; ++i)
      for (int j = 0; j < ndf; ++j) {
        if (m(i, j) == 0.0) continue;
        for (auto [ea, ca] : localEqs[static_cast<std::size_t>(i)])
          for (auto [eb, cb] : localEqs[static_cast<std::size_t>(j)]) {
            pattern.couple(ea, eb);
            nl.mass.push_back(MatEntry{j * ndf + i, -1, ca * cb});
            nl.rowCol.emplace_back(ea, eb);
          }
      }
  }
  for (PenaltyRow& row : penalties_)
    for (auto [ea, ca] : row.eqs)
      for (auto [eb, cb] : row.eqs) pattern.couple(ea, eb);
  A_ = pattern.build(neq_);
  // Each entry's place in the value array, from the (row, column) noted beside it.
  auto fix = [&](std::vector<MatEntry>& entries, std::vector<std::pair<int, int>>& rowCol) {
    for (std::size_t k = 0; k < entries.size(); ++k)
      entries[k].value = AssemblyPattern::valueIndex(A_, rowCol[k].first, rowCol[k].second);
    rowCol.clear();
    rowCol.shrink_to_fit();
  };
  for (ElementLink& l : elements_) {
    fix(l.mat, l.rowCol);
    l.matSlots.clear();
    if (l.direct.empty() || l.mat.empty()) continue;
    for (const MatEntry& m : l.mat) l.matSlots.emplace_back(m.local, m.value);
    l.mat.clear();
    l.mat.shrink_to_fit();
  }
  // Sleepers after the awake links, each part in the domain's order (the assembly sums in the
  // same order as with every link in place); the pairs that may sleep with their far-test data.
  std::map<const elements::Element*, std::size_t> pairOrder;  // domain order of each pair
  for (const ElementLink& l : elements_)
    if (l.far) pairOrder.emplace(l.element, pairOrder.size());
  std::stable_partition(elements_.begin(), elements_.end(),
                        [](const ElementLink& l) { return !l.asleep; });
  awake_ = elements_.size() - static_cast<std::size_t>(sleeping_);
  pairLinks_.assign(pairOrder.size(), PairLink{});
  std::vector<FarFace> faceOf(pairOrder.size());
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    const ElementLink& l = elements_[k];
    if (!l.far) continue;
    const std::size_t i = pairOrder.at(l.element);
    PairLink& p = pairLinks_[i];
    const elements::FarPair::Geometry test = l.far->farGeometry();
    p.link = k;
    p.contactor = l.nodes[0];
    p.X = test.X[0];
    p.distance = test.distance;
    p.far = l.far;
    p.asleep = l.asleep;
    FarFace& f = faceOf[i];
    for (std::size_t j = 0; j < 4; ++j) {
      f.nodes[j] = l.nodes[j + 1];
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
  // Each pair's position in the domain's tag order (Domain::setDormant); no face rests yet.
  std::size_t index = 0;
  std::map<const elements::Element*, std::uint32_t> domainIndex;
  for (const auto& [tag, e] : domain_.elements()) {
    if (pairOrder.count(e.get()) != 0)
      domainIndex.emplace(e.get(), static_cast<std::uint32_t>(index));
    ++index;
  }
  for (PairLink& p : pairLinks_) p.domainIndex = domainIndex.at(elements_[p.link].element);
  domain_.clearDormant();
  markObserved();
  buildWatch();
  for (NodeLink& nl : nodes_) fix(nl.mass, nl.rowCol);
  constantFor_.reset();
  for (PenaltyRow& row : penalties_) {
    row.valueIndex.clear();
    for (auto [ea, ca] : row.eqs)
      for (auto [eb, cb] : row.eqs)
        row.valueIndex.push_back(AssemblyPattern::valueIndex(A_, ea, eb));
  }
  P_ = Eigen::VectorXd::Zero(neq_);
  influence_.clear();
  elementStatus_.assign(elements_.size(), Status::Ok);
  sleepWanted_.clear();
}

void AnalysisModel::allocateBuffers(ElementLink& l, int n) {
  if (l.u.size() == n) return;
  l.u = l.v = l.a = l.force = Eigen::VectorXd::Zero(n);
  l.work = Eigen::MatrixXd::Zero(n, n);
}

bool AnalysisModel::wantsSleep(const ElementLink& l) const {
  if (!l.far) return false;
  const auto it = sleepWanted_.find(l.element);
  if (it != sleepWanted_.end()) return it->second;
  return l.far->committedFar();
}

double AnalysisModel::slabTopAt(const FarFace& f, bool committed) {
  std::array<Eigen::Vector3d, 4> quad;
  for (std::size_t j = 0; j < 4; ++j) quad[j] = f.X[j] + translation(*f.nodes[j], committed);
  return elements::FarPair::slabTop(quad, f.n);
}

bool AnalysisModel::sleeperBound(const PairLink& p, const FarFace& f, double top, bool committed,
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

void AnalysisModel::buildWatch() {
  faceMotion_.clear();
  for (const FarFace& f : farFaces_) {
    faceMotion_.beginGroup();
    std::vector<const domain::Node*> nodes(f.nodes.begin(), f.nodes.end());
    for (std::uint32_t i = f.first; i < f.end; ++i) nodes.push_back(pairLinks_[i].contactor);
    for (const domain::Node* n : nodes) {
      const NodeLink& nl = nodes_[static_cast<std::size_t>(nodeIndex_.at(n->tag()))];
      for (int d = 0; d < 3; ++d) {
        const auto g = static_cast<std::size_t>(nl.firstDof + d);
        if (const int eq = directEq_[g]; eq >= 0)
          faceMotion_.addEquation(eq);
        else
          faceMotion_.addTranslation(dofTerms_[g]);
      }
    }
    faceMotion_.endGroup();
  }
  faceHorizon_.assign(farFaces_.size(), -kInfinity);
}

void AnalysisModel::startRest(std::size_t r, double reach) {
  if (responseU_ == nullptr || responseU_->size() != neq_) return;  // no motion bound: no rest
  faceMotion_.snapshot(r, *responseU_, slots_);
  const bool wasResting = faceHorizon_[r] > -kInfinity;
  faceHorizon_[r] = reach;
  if (wasResting) return;
  const FarFace& f = farFaces_[r];
  for (std::uint32_t i = f.first; i < f.end; ++i)
    domain_.setDormant(pairLinks_[i].domainIndex, true);
}

double AnalysisModel::faceMoved(std::size_t r) const {
  if (responseU_ == nullptr || responseU_->size() != neq_) return kInfinity;
  return faceMotion_.moved(r, *responseU_, slots_);
}

bool AnalysisModel::rerestFace(std::size_t r) {
  const FarFace& f = farFaces_[r];
  const double top = slabTopAt(f, false);
  double slack = kInfinity;
  for (std::uint32_t i = f.first; i < f.end; ++i) {
    const PairLink& p = pairLinks_[i];
    double bound = 0.0;
    ++farTests_;
    if (!sleeperBound(p, f, top, false, bound)) return false;
    slack = std::min(slack, restSlack(bound, p.distance, p.X));
  }
  startRest(r, slack / kBoundLipschitz);  // measured from here on
  return true;
}

void AnalysisModel::wakeFace(std::size_t r) {
  // The committed positions are within the face's horizon (the displacements the checks saw:
  // beginSteps lets no face rest under an integrator that checks at others), so every pair is
  // far there, and its bound there is the gap the check of every step would have committed.
  const FarFace& f = farFaces_[r];
  const double top = slabTopAt(f, true);
  for (std::uint32_t i = f.first; i < f.end; ++i) {
    const PairLink& p = pairLinks_[i];
    double bound = 0.0;
    sleeperBound(p, f, top, true, bound);
    p.far->setSettledGap(bound);
    domain_.setDormant(p.domainIndex, false);
  }
  faceHorizon_[r] = -kInfinity;
}

std::size_t AnalysisModel::restingFaces() const {
  return static_cast<std::size_t>(std::count_if(faceHorizon_.begin(), faceHorizon_.end(),
                                                [](double h) { return h > -kInfinity; }));
}

void AnalysisModel::beginSteps(bool observeAll) {
  endSteps();
  observeAll_ = observeAll;
  observedTags_ = observeAll ? std::vector<int>{} : domain_.recordedElements();
  markObserved();
}

void AnalysisModel::endSteps() {
  for (std::size_t r = 0; r < faceHorizon_.size(); ++r)
    if (faceHorizon_[r] > -kInfinity) wakeFace(r);
  responseU_ = nullptr;  // the vector may go (eigen's, a replaced integrator's)
}

void AnalysisModel::markObserved() {
  mayRest_ = false;
  for (PairLink& p : pairLinks_) {
    const int tag = elements_[p.link].element->tag();
    p.observed = observeAll_ || std::binary_search(observedTags_.begin(), observedTags_.end(), tag);
    mayRest_ = mayRest_ || !p.observed;
  }
}

AnalysisModel::SleepCheck AnalysisModel::checkSleepingPairs() {
  SleepCheck result = SleepCheck::Unchanged;
  const double dt = time_ - domain_.committedTime();
  // Broad phase per target face: the bounding volume of a master surface is formed once and
  // tested against each of its slave nodes, as in the global search of contact codes (the
  // slave-master search of Benson and Hallquist, CMAME 78 (1990) 141-163; bounding volumes per
  // contact surface, Yang and Laursen, Comput Mech 41 (2008) 189-205). Here the volume is the
  // face's slab along its normal: its top is formed once per run of pairs against the face, and
  // each of its contactors costs its height above it. The pairs are taken in the domain's order.
  //
  // Resting faces: a face whose pairs all sleep settled far and are read by nobody during the
  // steps (beginSteps: no recorder names them, no contact stepping, no script after each step,
  // more than one step, an integrator that checks at the committed displacements) is left alone
  // until its pairs' nodes could have moved far enough to bring one of them to its search distance:
  // how far they moved since the face's last exact test is bounded by the largest change since then
  // of the equations and support values their translations are formed from, and the face is due
  // when that reaches the smallest excess of its pairs' bounds over their distances at the test,
  // over the bound's Lipschitz constant. This is the neighbour list with a skin of molecular
  // dynamics (Verlet, Phys Rev 159 (1967) 98-103; the list is rebuilt when the largest displacement
  // since it was built could have closed the skin, Allen and Tildesley, Computer Simulation of
  // Liquids, 2nd ed. 2017, sec. 5.3). The face is tested exactly when its horizon is reached, so a
  // pair is woken at the same step as with the test of every step, and the results do not change. A
  // resting pair is not committed (Domain::setDormant); its gap is formed at the committed
  // positions when it is read again (wakeFace, endSteps).
  for (std::size_t r = 0; r < farFaces_.size(); ++r) {
    if (faceHorizon_[r] > -kInfinity) {
      if (faceMoved(r) < faceHorizon_[r]) continue;  // far for sure
      if (rerestFace(r)) continue;
      wakeFace(r);
    }
    const FarFace& f = farFaces_[r];
    double top = 0.0;
    bool topFormed = false;
    bool mayRest = mayRest_;
    double slack = kInfinity;
    for (std::uint32_t i = f.first; i < f.end; ++i) {
      const PairLink& p = pairLinks_[i];
      if (p.asleep) {
        if (!topFormed) {
          top = slabTopAt(f, false);
          topFormed = true;
        }
        double bound = 0.0;
        ++farTests_;
        if (sleeperBound(p, f, top, false, bound) && p.far->setFarTrial(bound, dt)) {
          if (mayRest) {
            mayRest = !p.observed && p.far->settledFar();
            slack = std::min(slack, restSlack(bound, p.distance, p.X));
          }
          continue;
        }
      }
      mayRest = false;
      ElementLink& l = elements_[p.link];
      if (l.asleep) {
        // Near: its full update for this trial state; with force the step missed it.
        allocateBuffers(l, l.element->numDof());
        const Status st = updateElement(l, dt);
        ++elementUpdates_;
        sleepWanted_[l.element] = false;
        if (!ok(st) || l.element->isActive()) return SleepCheck::RedoStep;
        result = SleepCheck::PatternChange;
      } else if (l.far->trialFarBeyond(2.0)) {
        sleepWanted_[l.element] = true;
        if (result == SleepCheck::Unchanged) result = SleepCheck::PatternChange;
      }
    }
    if (mayRest && f.end > f.first) startRest(r, slack / kBoundLipschitz);
  }
  return result;
}

void AnalysisModel::applySleepChanges() {
  const Eigen::VectorXd P = P_;           // the external load of the current time stays
  for (const ElementLink& l : elements_)  // pairs without a change keep their state
    if (l.far) sleepWanted_.emplace(l.element, l.asleep);
  // Resting faces rest on (a new pattern moves no node): their pairs' gaps are formed now, and
  // a face with the same pairs, all still asleep, watching the same equations, rests again with
  // its motion bound and horizon.
  struct Carried {
    MotionWatch::Saved motion;
    double horizon;
    std::uint32_t pairs;
  };
  std::map<const elements::Element*, Carried> carried;  // by the face's first pair
  for (std::size_t r = 0; r < farFaces_.size(); ++r) {
    if (!(faceHorizon_[r] > -kInfinity)) continue;
    carried.emplace(
        elements_[pairLinks_[farFaces_[r].first].link].element,
        Carried{faceMotion_.save(r), faceHorizon_[r], farFaces_[r].end - farFaces_[r].first});
    wakeFace(r);
  }
  buildScatter();
  buildConstantDynamics();
  P_ = P;
  for (std::size_t r = 0; r < farFaces_.size() && !carried.empty(); ++r) {
    const FarFace& f = farFaces_[r];
    const auto it = carried.find(elements_[pairLinks_[f.first].link].element);
    if (it == carried.end()) continue;
    bool same = f.end - f.first == it->second.pairs;
    for (std::uint32_t i = f.first; i < f.end && same; ++i)
      same = pairLinks_[i].asleep && !pairLinks_[i].observed;
    if (!same || !faceMotion_.restore(r, it->second.motion)) continue;
    faceHorizon_[r] = it->second.horizon;
    for (std::uint32_t i = f.first; i < f.end; ++i)
      domain_.setDormant(pairLinks_[i].domainIndex, true);
  }
}

double AnalysisModel::termValue(const std::vector<Term>& terms, const Eigen::VectorXd& x,
                                int which) const {
  double value = 0.0;
  for (const Term& t : terms) {
    if (t.index >= 0) {
      value += t.coef * x(t.index);
    } else {
      const Slot& s = slots_[static_cast<std::size_t>(-t.index - 1)];
      value += t.coef * (which == 0 ? s.disp : which == 1 ? s.vel : s.accel);
    }
  }
  return value;
}

void AnalysisModel::applyLoad(double t) {
  time_ = t;
  domain_.setTime(t);
  // Support values.
  for (Slot& s : slots_) s.disp = s.vel = s.accel = 0.0;
  // Pattern supports in the order the constraint handler gave them slots.
  std::size_t k = 0;
  for (const auto& [ptag, p] : domain_.patterns()) {
    const std::size_t count = p->supportCount();
    if (count == 0) continue;
    const std::span<domain::SupportMotion> motion(supportMotion_.data() + k, count);
    p->supportMotion(t, motion);
    for (const domain::SupportMotion& m : motion) {
      Slot& s = slots_[static_cast<std::size_t>(patternSlots_[k++])];
      s.disp = m.disp;
      s.vel = m.vel;
      s.accel = m.accel;
    }
  }
  externalLoadAt(t, P_);
}

const Eigen::VectorXd& AnalysisModel::influence(int dir) {
  auto it = influence_.find(dir);
  if (it != influence_.end()) return it->second;
  // M r with r = 1 at every translational dof `dir` (nodal and element masses).
  Eigen::VectorXd mr = Eigen::VectorXd::Zero(neq_);
  for (const NodeLink& nl : nodes_) {
    if (dir >= nl.node->ndf()) continue;
    const Eigen::VectorXd col = nl.node->mass().col(dir);
    for (const VecEntry& v : nl.vec) mr(v.eq) += v.coef * col(v.local);
  }
  for (const ElementLink& l : elements_) {
    const auto m = l.element->mass();
    if (m.isZero(0.0)) continue;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(l.element->numDof());
    int offset = 0;
    for (const domain::Node* n : l.nodes) {
      if (dir < n->ndf()) r(offset + dir) = 1.0;
      offset += n->ndf();
    }
    const Eigen::VectorXd emr = m * r;
    for (const VecEntry& v : l.vec) mr(v.eq) += v.coef * emr(v.local);
  }
  return influence_[dir] = std::move(mr);
}

Eigen::VectorXd AnalysisModel::externalLoadAt(double t) {
  Eigen::VectorXd P;
  externalLoadAt(t, P);
  return P;
}

void AnalysisModel::externalLoadAt(double t, Eigen::VectorXd& P) {
  if (P.size() != neq_) P.resize(neq_);
  P.setZero();
  for (const auto& [ptag, p] : domain_.patterns()) {
    if (!p->nodalLoads().empty()) {
      const double f = p->factor(t);
      for (const domain::NodalLoad& load : p->nodalLoads()) {
        const NodeLink& nl = nodes_[static_cast<std::size_t>(nodeIndex_.at(load.node))];
        for (const VecEntry& v : nl.vec) P(v.eq) += v.coef * f * load.values(v.local);
      }
    }
    // Effective earthquake load -M r a_g (OpenSees EarthquakePattern::applyLoad).
    if (const auto ground = p->groundAcceleration(t); ground && ground->value != 0.0)
      P.noalias() -= ground->value * influence(ground->dof);
  }
}

void AnalysisModel::setResponse(const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                                const Eigen::VectorXd& A) {
  responseU_ = &U;
  for (NodeLink& nl : nodes_) {
    domain::Node& n = *nl.node;
    for (int d = 0; d < n.ndf(); ++d) {
      const auto g = static_cast<std::size_t>(nl.firstDof + d);
      if (const int eq = directEq_[g]; eq >= 0) {  // the dof is an equation
        n.disp(d) = U(eq);
        n.vel(d) = V(eq);
        n.accel(d) = A(eq);
        continue;
      }
      const auto& terms = dofTerms_[g];
      n.disp(d) = termValue(terms, U, 0);
      n.vel(d) = termValue(terms, V, 1);
      n.accel(d) = termValue(terms, A, 2);
    }
  }
}

void AnalysisModel::getResponse(Eigen::VectorXd& U, Eigen::VectorXd& V, Eigen::VectorXd& A,
                                bool committed) const {
  U = V = A = Eigen::VectorXd::Zero(neq_);
  for (const NodeLink& nl : nodes_) {
    const domain::Node& n = *nl.node;
    for (int d = 0; d < n.ndf(); ++d) {
      const auto& terms = dofTerms_[static_cast<std::size_t>(nl.firstDof + d)];
      if (terms.size() == 1 && terms[0].index >= 0 && terms[0].coef == 1.0) {
        const int eq = terms[0].index;
        U(eq) = committed ? n.committedDisp(d) : n.disp(d);
        V(eq) = committed ? n.committedVel(d) : n.vel(d);
        A(eq) = committed ? n.committedAccel(d) : n.accel(d);
      }
    }
  }
}

Status AnalysisModel::updateElement(ElementLink& l, double dt) const {
  double* u = l.u.data();
  double* v = l.v.data();
  double* a = l.a.data();
  // x * 0 is 0 for a finite x and NaN for an infinite or NaN one, so `check` is 0 exactly when
  // every displacement and velocity is finite (one pass, no branch per value).
  double check = 0.0;
  for (const domain::Node* n : l.nodes) {
    const int ndf = n->ndf();
    const double* nu = n->disp.data();
    for (int d = 0; d < ndf; ++d) {
      u[d] = nu[d];
      check += nu[d] * 0.0;
    }
    u += ndf;
    if (l.rates) {
      const double* nv = n->vel.data();
      const double* na = n->accel.data();
      for (int d = 0; d < ndf; ++d) {
        v[d] = nv[d];
        a[d] = na[d];
        check += nv[d] * 0.0;
      }
      v += ndf;
      a += ndf;
    }
  }
  if (check != 0.0) return Status::NonFinite;
  return l.element->update(elements::Kinematics{l.u, l.v, l.a, time_, dt});
}

Status AnalysisModel::updateElements() {
  const double dt = time_ - domain_.committedTime();
  const auto count = static_cast<std::ptrdiff_t>(awake_);
  // Every element is updated even when one fails, so each element's trial state (a force-based
  // element starts its next update from its own) is the same whatever the order and the number of
  // threads: elements share nothing, read only their nodes, and the assembly stays serial, so
  // results are bit-identical at any thread count.
  // Sleeping contact pairs (far apart) are skipped: checkSleepingPairs looks at them once a step.
  if (threads_ > 1 && count > 1) {
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads_)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      ElementLink& l = elements_[static_cast<std::size_t>(k)];
      if (!l.asleep) elementStatus_[static_cast<std::size_t>(k)] = updateElement(l, dt);
    }
  } else {
    for (std::ptrdiff_t k = 0; k < count; ++k) {
      ElementLink& l = elements_[static_cast<std::size_t>(k)];
      if (!l.asleep) elementStatus_[static_cast<std::size_t>(k)] = updateElement(l, dt);
    }
  }
  elementUpdates_ += count;
  // The awake links' statuses (a sleeper's entry is never written).
  for (std::size_t k = 0; k < awake_; ++k)
    if (const Status s = elementStatus_[k]; !ok(s)) return s;
  return Status::Ok;
}

bool AnalysisModel::holdStatuses() {
  bool any = false;
  for (std::size_t k = 0; k < awake_; ++k)
    if (ElementLink& l = elements_[k]; l.switching && !l.asleep) {
      l.element->holdStatus();
      any = true;
    }
  return any;
}

elements::Element::HeldStatus AnalysisModel::checkHeldStatuses() {
  using Held = elements::Element::HeldStatus;
  Held result = Held::Agrees;
  // Every element is checked (each one that disagrees switches now, not one per round).
  for (std::size_t k = 0; k < awake_; ++k) {
    ElementLink& l = elements_[k];
    if (!l.switching || l.asleep) continue;
    const Held h = l.element->checkHeldStatus();
    if (h == Held::Conflict) result = Held::Conflict;
    if (h == Held::Switched && result == Held::Agrees) result = Held::Switched;
  }
  return result;
}

void AnalysisModel::addElementMatrix(double* values, const ElementLink& l,
                                     const Eigen::MatrixXd& m) const {
  const double* local = m.data();
  if (l.matSlots.empty()) {
    for (const MatEntry& e : l.mat) values[e.value] += e.coef * local[e.local];
    return;
  }
  for (const auto& [offset, value] : l.matSlots) values[value] += local[offset];
}

void AnalysisModel::buildConstantDynamics() {
  const auto nnz = static_cast<std::size_t>(A_.nonZeros());
  std::vector<double> mass(nnz, 0.0), damping(nnz, 0.0);
  rayleighLeft_.assign(elements_.size(), 0);
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    ElementLink& l = elements_[k];
    const elements::Element& e = *l.element;
    const Eigen::MatrixXd m = e.mass();
    l.ownDynamics = e.mayTurnInactive() && (l.rayleighOn || !m.isZero(0.0));
    if (l.ownDynamics) continue;
    addElementMatrix(mass.data(), l, m);
    if (!l.rayleighOn) continue;
    const auto& r = l.rayleigh;
    Eigen::MatrixXd c = r.alphaM * m + r.betaK0 * e.initialStiff();
    if (e.isLinear()) {
      c += (r.betaK + r.betaKc) * e.initialStiff();
    } else if (r.betaK != 0.0 || r.betaKc != 0.0) {
      rayleighLeft_[k] = 1;
    }
    addElementMatrix(damping.data(), l, c);
  }
  for (const NodeLink& nl : nodes_) {
    const double* m = nl.node->mass().data();
    for (const MatEntry& me : nl.mass) {
      const double v = me.coef * m[me.local];
      mass[static_cast<std::size_t>(me.value)] += v;
      damping[static_cast<std::size_t>(me.value)] += nl.alphaM * v;
    }
  }
  massGlobal_ = A_;
  dampingGlobal_ = A_;
  std::copy(mass.begin(), mass.end(), massGlobal_.valuePtr());
  std::copy(damping.begin(), damping.end(), dampingGlobal_.valuePtr());
  massGlobal_.prune(0.0);
  dampingGlobal_.prune(0.0);
  eqVel_ = eqAcc_ = Eigen::VectorXd::Zero(neq_);
}

void AnalysisModel::subtractForce(const ElementLink& l, const Eigen::Ref<const Eigen::VectorXd>& f,
                                  Eigen::VectorXd& B) {
  if (l.direct.empty()) {
    for (const VecEntry& v : l.vec) B(v.eq) -= v.coef * f(v.local);
    return;
  }
  const auto n = static_cast<Eigen::Index>(l.direct.size());
  for (Eigen::Index i = 0; i < n; ++i)
    if (const int eq = l.direct[static_cast<std::size_t>(i)]; eq >= 0) B(eq) -= f(i);
}

void AnalysisModel::formResidual(const AssemblyCoefficients& c, Eigen::VectorXd& B) const {
  B = P_;
  // Dynamic forces from the constant global matrices unless a support moves with an imposed
  // velocity, whose damping and inertia coupling only the element-level forces carry.
  const bool global = c.dynamic && !imposedMotion_;
  for (std::size_t k = 0; k < awake_; ++k) {
    const ElementLink& l = elements_[k];
    const elements::Element& e = *l.element;
    if (!e.isActive()) continue;
    if (global && !l.ownDynamics) {
      if (rayleighLeft_[k] == 0) {
        subtractForce(l, e.resistingForce(), B);
        continue;
      }
      Eigen::VectorXd& f = l.force;
      f = e.resistingForce();
      const auto& r = l.rayleigh;
      if (r.betaK != 0.0) f.noalias() += r.betaK * (e.tangentStiff() * l.v);
      if (r.betaKc != 0.0) f.noalias() += r.betaKc * (e.committedStiff() * l.v);
      subtractForce(l, f, B);
    } else if (c.dynamic) {
      // (also an element with its own dynamics under the global matrices: its rates are
      // gathered, as for every nonlinear element or one with a damping tangent)
      Eigen::VectorXd& f = l.force;
      f = e.resistingForce();
      const auto m = e.mass();
      f.noalias() += m * l.a;
      if (l.rayleighOn) {
        const auto& r = l.rayleigh;
        if (r.alphaM != 0.0) f.noalias() += r.alphaM * (m * l.v);
        if (r.betaK != 0.0) f.noalias() += r.betaK * (e.tangentStiff() * l.v);
        if (r.betaK0 != 0.0) f.noalias() += r.betaK0 * (e.initialStiff() * l.v);
        if (r.betaKc != 0.0) f.noalias() += r.betaKc * (e.committedStiff() * l.v);
      }
      subtractForce(l, f, B);
    } else {
      subtractForce(l, e.resistingForce(), B);
    }
  }
  if (c.dynamic) {
    if (global || hasModalDamping()) {
      for (int eq = 0; eq < neq_; ++eq) {
        const auto& [node, dof] = eqDof_[static_cast<std::size_t>(eq)];
        eqVel_(eq) = node->vel(dof);
        eqAcc_(eq) = node->accel(dof);
      }
    }
    if (global) {
      B.noalias() -= massGlobal_ * eqAcc_;
      B.noalias() -= dampingGlobal_ * eqVel_;
    } else {
      for (const NodeLink& nl : nodes_) {
        if (nl.mass.empty()) continue;
        const domain::Node& n = *nl.node;
        // At most 6 dofs a node: on the stack, no allocation in the iteration.
        const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> f =
            n.mass() * (n.accel + nl.alphaM * n.vel);
        for (const VecEntry& v : nl.vec) B(v.eq) -= v.coef * f(v.local);
      }
    }
    if (hasModalDamping())
      B.noalias() -=
          modalMphi_ * (modalCoefficients_.asDiagonal() * (modalMphi_.transpose() * eqVel_));
  }
  for (const PenaltyRow& row : penalties_) {
    // Penalty force alpha c (g - c.u) (OpenSees PenaltySP_FE / PenaltyMP_FE).
    double cu = 0.0;
    for (auto [eq, coef] : row.eqs) {
      const auto& [node, dof] = eqDof_[static_cast<std::size_t>(eq)];
      cu += coef * node->disp(dof);
    }
    const double g = row.slot >= 0 ? slots_[static_cast<std::size_t>(row.slot)].disp : 0.0;
    for (auto [eq, coef] : row.eqs) B(eq) += row.alpha * coef * (g - cu);
  }
}

void AnalysisModel::addElementTangent(double* values, ElementLink& l, const AssemblyCoefficients& c,
                                      TangentTerms terms) const {
  const elements::Element& e = *l.element;
  Eigen::MatrixXd& local = l.work;
  const bool varying = terms != TangentTerms::Constant;
  const bool constant = terms != TangentTerms::Varying;
  const auto& r = l.rayleigh;
  if (varying) {
    const auto k = c.stiffness == StiffnessKind::Current ? e.tangentStiff() : e.initialStiff();
    local.noalias() = c.cK * k;
    if (c.cC != 0.0) {
      local.noalias() += c.cC * e.dampingTangent();
      if (l.rayleighOn) {
        if (r.betaK != 0.0) local.noalias() += (c.cC * r.betaK) * e.tangentStiff();
        if (r.betaKc != 0.0) local.noalias() += (c.cC * r.betaKc) * e.committedStiff();
      }
    }
  } else {
    const bool damped = c.cC != 0.0 && l.rayleighOn && (r.alphaM != 0.0 || r.betaK0 != 0.0);
    if (!damped && c.cM == 0.0) return;
    local.setZero(e.numDof(), e.numDof());
  }
  if (constant) {
    if (c.cC != 0.0 && l.rayleighOn) {
      if (r.alphaM != 0.0) local.noalias() += (c.cC * r.alphaM) * e.mass();
      if (r.betaK0 != 0.0) local.noalias() += (c.cC * r.betaK0) * e.initialStiff();
    }
    if (c.cM != 0.0) local.noalias() += c.cM * e.mass();
  }
  addElementMatrix(values, l, local);
}

const Eigen::SparseMatrix<double>& AnalysisModel::formTangent(const AssemblyCoefficients& c) {
  double* values = A_.valuePtr();
  const auto nnz = static_cast<std::size_t>(A_.nonZeros());
  // What cannot change between assemblies with the same coefficients is summed once and copied:
  // linear elements, nodal masses, penalty rows, and the mass and initial-stiffness damping of
  // the other elements; those are formed again for their tangent and other damping terms alone.
  // An element that turns active or inactive (a contact pair) makes the constant part anew.
  for (;;) {
    if (!constantFor_ || !constantFor_->sameMatrix(c)) {
      std::fill(values, values + nnz, 0.0);
      for (ElementLink& l : awakeLinks()) {
        const bool active = l.element->isActive();
        if (l.element->isLinear()) {
          if (active) addElementTangent(values, l, c);
        } else {
          l.constantActive = active;
          if (active) addElementTangent(values, l, c, TangentTerms::Constant);
        }
      }
      if (c.cM != 0.0 || c.cC != 0.0) {
        for (NodeLink& nl : nodes_) {
          const double f = c.cM + c.cC * nl.alphaM;
          const double* m = nl.node->mass().data();
          for (const MatEntry& me : nl.mass) values[me.value] += f * me.coef * m[me.local];
        }
      }
      for (const PenaltyRow& row : penalties_) {
        std::size_t idx = 0;
        for (const auto& a : row.eqs)
          for (const auto& b : row.eqs)
            values[row.valueIndex[idx++]] += c.cK * row.alpha * a.second * b.second;
      }
      constantValues_.assign(values, values + nnz);
      constantFor_ = c;
    } else {
      std::copy(constantValues_.begin(), constantValues_.end(), values);
    }
    bool activityChanged = false;
    for (ElementLink& l : awakeLinks()) {
      if (l.element->isLinear()) continue;
      const bool active = l.element->isActive();
      if (active != l.constantActive) {
        activityChanged = true;
        break;
      }
      if (active) addElementTangent(values, l, c, TangentTerms::Varying);
    }
    if (!activityChanged) return A_;
    constantFor_.reset();
  }
}

Eigen::SparseMatrix<double> AnalysisModel::formMass() {
  AssemblyCoefficients c;
  c.cK = 0.0;
  c.cM = 1.0;
  formTangent(c);
  Eigen::SparseMatrix<double> M = A_;
  return M;
}

int AnalysisModel::equationOf(int nodeTag, int dof) const {
  auto it = nodeIndex_.find(nodeTag);
  if (it == nodeIndex_.end()) return -1;
  const NodeLink& nl = nodes_[static_cast<std::size_t>(it->second)];
  if (dof < 0 || dof >= nl.node->ndf()) return -1;
  const auto& terms = dofTerms_[static_cast<std::size_t>(nl.firstDof + dof)];
  if (terms.size() == 1 && terms[0].index >= 0 && terms[0].coef == 1.0) return terms[0].index;
  return -1;
}

void AnalysisModel::setEigenvectors(const Eigen::MatrixXd& phi) {
  for (NodeLink& nl : nodes_) {
    domain::Node& n = *nl.node;
    n.eigenvectors = Eigen::MatrixXd::Zero(n.ndf(), phi.cols());
    for (int d = 0; d < n.ndf(); ++d)
      for (const Term& t : dofTerms_[static_cast<std::size_t>(nl.firstDof + d)])
        if (t.index >= 0) n.eigenvectors.row(d) += t.coef * phi.row(t.index);
  }
}

void AnalysisModel::setModalDamping(const Eigen::MatrixXd& Mphi,
                                    const Eigen::VectorXd& coefficients) {
  modalMphi_ = Mphi;
  modalCoefficients_ = coefficients;
}

}  // namespace dabs::analysis
