// SPDX-License-Identifier: MIT
// Over 400 lines: the equations (numbering, the scatter records built from them) and what moves
// values through those records between the equations and the nodes (loads and support values,
// trial responses, the threaded element updates) stay together, since they share the records and
// the index tables; the residual (ResidualAssembler), the tangent (TangentAssembler) and the
// sleeping contact pairs (SleepingPairs) are classes of their own.
#include "tcl/analysis/model/AnalysisModel.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <string>

#include "tcl/analysis/model/AssemblyPattern.h"
#include "tcl/analysis/model/DofNumberer.h"

namespace dabs::analysis {

AnalysisModel::AnalysisModel(domain::Domain& domain, ConstraintKind constraints,
                             NumbererKind numberer, double alphaSP, double alphaMP)
    : domain_(domain),
      constraints_(constraints),
      numberer_(numberer),
      alphaSP_(alphaSP),
      alphaMP_(alphaMP),
      sleepers_(domain) {}

bool AnalysisModel::nonSymmetric() const {
  return std::any_of(elements_.begin(), elements_.end(),
                     [](const ElementScatter& l) { return l.element->hasNonSymmetricTangent(); });
}

bool AnalysisModel::nonSymmetricNow() const {
  const auto awake = awakeLinks();
  return std::any_of(awake.begin(), awake.end(), [](const ElementScatter& l) {
    return l.element->isActive() && l.element->hasNonSymmetricTangent();
  });
}

bool AnalysisModel::allLinear() const {
  return std::all_of(elements_.begin(), elements_.end(),
                     [](const ElementScatter& l) { return l.element->isLinear(); });
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
    nodes_.push_back(NodeScatter{&node, ndofTotal, {}, {}, {}, domain_.nodeAlphaM(tag)});
    nodeDofs.push_back(NodeDofs{&node, ndofTotal});
    ndofTotal += node.ndf();
  }
  updatedDisp_.assign(static_cast<std::size_t>(ndofTotal), 0.0);
  updatedDispKnown_ = false;
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
  updatedDispKnown_ = false;
  anyScalesSteps_ = false;
  std::vector<std::vector<std::pair<int, double>>> localEqs;
  std::vector<std::pair<int, double>> scratch;
  long sleeping = 0;
  // What keeps an element's force from being its stiffness times its equations' values: a
  // member load on it, or a support value a pattern drives (imposed motion, sp) among its dofs.
  std::set<int> loaded;
  for (const auto& [ptag, p] : domain_.patterns())
    for (const domain::ElementLoad& l : p->elementLoads()) loaded.insert(l.element);
  std::vector<char> drivenSlot(slots_.size(), 0);
  for (const int slot : patternSlots_) drivenSlot[static_cast<std::size_t>(slot)] = 1;
  auto drivesSupport = [&](int g) {
    for (const Term& t : dofTerms_[static_cast<std::size_t>(g)])
      if (t.index < 0 && drivenSlot[static_cast<std::size_t>(-t.index - 1)]) return true;
    return false;
  };
  for (const auto& [etag, e] : domain_.elements()) {
    ElementScatter link;
    link.element = e.get();
    link.rayleigh = domain_.elementRayleigh(etag);
    link.rayleighOn = link.rayleigh.any();
    const int n = e->numDof();
    link.far = e->farPair();
    link.sleeping = link.far != nullptr && sleepers_.wantsSleep(*link.far);
    if (link.sleeping) ++sleeping;
    // A sleeper gets its buffers when it wakes (they would spread the awake links' data).
    if (!link.sleeping) link.allocateBuffers(n);
    link.deferred = !link.sleeping && link.far == nullptr && !imposedMotion_ &&
                    e->forceIsInitialStiffnessTimesDisplacements() && loaded.count(etag) == 0;
    localEqs.assign(static_cast<std::size_t>(n), {});
    int local = 0;
    for (int nt : e->nodeTags()) {
      NodeScatter& nl = nodes_[static_cast<std::size_t>(nodeIndex_.at(nt))];
      link.nodes.push_back(nl.node);
      for (int d = 0; d < nl.node->ndf(); ++d, ++local) {
        eqsOfDof(nl.firstDof + d, scratch);
        localEqs[static_cast<std::size_t>(local)] = scratch;
        if (!link.sleeping)  // a sleeper adds nothing to the residual
          for (auto [eq, c] : scratch) link.vec.push_back(VecEntry{local, eq, c});
        if (link.deferred && drivesSupport(nl.firstDof + d)) link.deferred = false;
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
    // An element that names where its matrices can be nonzero scatters those entries alone; the
    // pattern keeps every coupling of its dofs all the same (the same pattern, the same order
    // and factor), and the entries left out only ever added zeros.
    const std::span<const int> support = e->matrixSupport();
    std::vector<char> reaches(static_cast<std::size_t>(n) * static_cast<std::size_t>(n),
                              support.empty() ? 1 : 0);
    for (const int idx : support) reaches[static_cast<std::size_t>(idx)] = 1;
    for (int i = 0; i < n && !link.sleeping; ++i)
      for (auto [ea, ca] : localEqs[static_cast<std::size_t>(i)])
        for (int j = 0; j < n; ++j)
          for (auto [eb, cb] : localEqs[static_cast<std::size_t>(j)]) {
            pattern.couple(ea, eb);
            if (!reaches[static_cast<std::size_t>(j * n + i)]) continue;
            link.mat.push_back(MatEntry{j * n + i, -1, ca * cb});  // value fixed below
            link.rowCol.emplace_back(ea, eb);
          }
    link.linear = e->isLinear();
    link.rates =
        !link.linear || imposedMotion_ || e->mayTurnInactive() || !e->dampingTangent().isZero(0.0);
    link.switching = e->switchesStatus();
    link.scalesSteps = e->scalesNewtonSteps();
    anyScalesSteps_ = anyScalesSteps_ || link.scalesSteps;
    elements_.push_back(std::move(link));
  }
  for (NodeScatter& nl : nodes_) {
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
  for (ElementScatter& l : elements_) {
    fix(l.mat, l.rowCol);
    l.matSlots.clear();
    // Entries of one value side by side, each value's in their order: the assembly sums them in a
    // register (ElementScatter::addMatrix) in the order it summed them in memory, so the same
    // bits. An element on rigidly linked nodes sends each entry to the combinations of its
    // nodes' master dofs, and a value then takes many entries of one element.
    std::stable_sort(l.mat.begin(), l.mat.end(),
                     [](const MatEntry& a, const MatEntry& b) { return a.value < b.value; });
    if (l.direct.empty() || l.mat.empty()) continue;
    for (const MatEntry& m : l.mat) l.matSlots.emplace_back(m.local, m.value);
    l.mat.clear();
    l.mat.shrink_to_fit();
  }
  // Sleepers after the awake links, each part in the domain's order (the assembly sums in the
  // same order as with every link in place).
  std::stable_partition(elements_.begin(), elements_.end(),
                        [](const ElementScatter& l) { return !l.sleeping; });
  awake_ = elements_.size() - static_cast<std::size_t>(sleeping);
  deferredCount_ = 0;
  for (const ElementScatter& l : elements_) {
    domain_.setStateDeferred(l.element->tag(), l.deferred);
    if (l.deferred) ++deferredCount_;
  }
  buildSleepers();
  for (NodeScatter& nl : nodes_) fix(nl.mass, nl.rowCol);
  tangent_.reset();
  for (PenaltyRow& row : penalties_) {
    row.valueIndex.clear();
    for (auto [ea, ca] : row.eqs)
      for (auto [eb, cb] : row.eqs)
        row.valueIndex.push_back(AssemblyPattern::valueIndex(A_, ea, eb));
  }
  P_ = Eigen::VectorXd::Zero(neq_);
  influence_.clear();
  elementStatus_.assign(elements_.size(), Status::Ok);
  materialsAtBuild_.clear();
  for (std::size_t k = 0; k < awake_; ++k)
    materialsAtBuild_.push_back(elements_[k].element->materialUpdates());
  updateCalls_ = 0;
  unitsFormedAt_ = -1;
}

void AnalysisModel::buildSleepers() {
  // The pairs that may sleep in the domain's order, with their position in the domain's tag
  // order (Domain::setStateKept) and their index here.
  std::map<const elements::Element*, std::size_t> linkOf;
  for (std::size_t k = 0; k < elements_.size(); ++k)
    if (elements_[k].far) linkOf.emplace(elements_[k].element, k);
  std::vector<SleepingPairs::Pair> pairs;
  pairs.reserve(linkOf.size());
  std::uint32_t index = 0;
  for (const auto& [tag, e] : domain_.elements()) {
    const auto it = linkOf.find(e.get());
    if (it != linkOf.end()) {
      const ElementScatter& l = elements_[it->second];
      SleepingPairs::Pair p;
      p.link = it->second;
      p.tag = tag;
      p.far = l.far;
      p.contactor = l.nodes[0];
      for (std::size_t j = 0; j < 4; ++j) p.face[j] = l.nodes[j + 1];
      p.sleeping = l.sleeping;
      p.domainIndex = index;
      pairs.push_back(p);
    }
    ++index;
  }
  SleepingPairs::DofSource dofs{
      [this](int tag) { return nodes_[static_cast<std::size_t>(nodeIndex_.at(tag))].firstDof; },
      directEq_, dofTerms_};
  sleepers_.build(std::move(pairs), dofs);
}

AnalysisModel::SleepCheck AnalysisModel::checkSleepingPairs() {
  const double dt = time_ - domain_.committedTime();
  return sleepers_.check(dt, slots_, [this, dt](std::size_t link) {
    ElementScatter& l = elements_[link];
    l.allocateBuffers(l.element->numDof());
    const Status st = l.update(time_, dt);
    ++elementUpdates_;
    return !ok(st) || l.element->isActive();
  });
}

void AnalysisModel::applySleepChanges() {
  const Eigen::VectorXd P = P_;  // the external load of the current time stays
  const SleepingPairs::Carried carried = sleepers_.beforeRebuild();
  buildScatter();
  buildConstantDynamics();
  P_ = P;
  sleepers_.afterRebuild(carried);
}

std::array<double, 3> AnalysisModel::termValues(const std::vector<Term>& terms,
                                                const Eigen::VectorXd& U, const Eigen::VectorXd& V,
                                                const Eigen::VectorXd& A) const {
  double u = 0.0, v = 0.0, a = 0.0;
  for (const Term& t : terms) {
    if (t.index >= 0) {
      u += t.coef * U(t.index);
      v += t.coef * V(t.index);
      a += t.coef * A(t.index);
    } else {
      const Slot& s = slots_[static_cast<std::size_t>(-t.index - 1)];
      u += t.coef * s.disp;
      v += t.coef * s.vel;
      a += t.coef * s.accel;
    }
  }
  return {u, v, a};
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
  for (const NodeScatter& nl : nodes_) {
    if (dir >= nl.node->ndf()) continue;
    const Eigen::VectorXd col = nl.node->mass().col(dir);
    for (const VecEntry& v : nl.vec) mr(v.eq) += v.coef * col(v.local);
  }
  for (const ElementScatter& l : elements_) {
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
        const NodeScatter& nl = nodes_[static_cast<std::size_t>(nodeIndex_.at(load.node))];
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
  sleepers_.setDisplacements(U);
  for (NodeScatter& nl : nodes_) {
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
      const auto [u, v, a] = termValues(terms, U, V, A);
      n.disp(d) = u;
      n.vel(d) = v;
      n.accel(d) = a;
    }
  }
}

void AnalysisModel::getResponse(Eigen::VectorXd& U, Eigen::VectorXd& V, Eigen::VectorXd& A,
                                bool committed) const {
  U = V = A = Eigen::VectorXd::Zero(neq_);
  for (const NodeScatter& nl : nodes_) {
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

int AnalysisModel::availableThreads() noexcept {
#ifdef _OPENMP
  return omp_get_num_procs();  // the processors this process may run on (its affinity)
#else
  return 1;
#endif
}

Status AnalysisModel::updateElements() {
  const double dt = time_ - domain_.committedTime();
  const auto count = static_cast<std::ptrdiff_t>(awake_);
  // Every element is updated even when one fails, so each element's trial state (a force-based
  // element starts its next update from its own) is the same whatever the order and the number of
  // threads: elements share nothing, read only their nodes, and the assembly stays serial, so
  // results are bit-identical at any thread count.
  // Sleeping contact pairs (far apart) are skipped: checkSleepingPairs looks at them once a step.
  // So is an element whose state depends on its displacements alone and is current (a linear
  // elastic beam; a displacement-based beam or zeroLength whose laws keep their state at the same
  // strain) when no node has moved since the last pass, as after a transient step's predictor,
  // which moves only the rates: only the rates are gathered, for an element the residual reads
  // them of (Rayleigh terms with the current tangent). On the benchmark's linear frame (1,330
  // beams) that pass was about a sixth of the run.
  const bool unmoved = nodesUnmovedSinceLastUpdate();
  auto updateOne = [&](std::ptrdiff_t k) {
    ElementScatter& l = elements_[static_cast<std::size_t>(k)];
    if (l.sleeping || l.deferred) return;
    if (unmoved && l.element->keepsStateAtSameDisplacements()) {
      elementStatus_[static_cast<std::size_t>(k)] = l.rates ? l.gatherRates() : Status::Ok;
      return;
    }
    elementStatus_[static_cast<std::size_t>(k)] = l.update(time_, dt);
  };
  if (threads_ > 1 && count > 1) {
    // The costs are measured (material updates per update), so the lists are formed again after
    // the first update and whenever the updates since the build have grown sixteenfold. Each
    // thread runs its own list, then what is left of the others' (a list's items are taken one at
    // a time through its cursor, by its owner or by a thread done with its own), then takes light
    // items from the shared pool until it is empty. Taking the rest of another's list costs
    // nothing where the lists balance, and where the system stops one thread for a while (a
    // shared machine's other work, or its processors given to another guest) the other does that
    // thread's remaining elements instead of waiting for it at the pass's end.
    if (unitsFormedAt_ < 0 || updateCalls_ >= std::max(16 * unitsFormedAt_, 1L)) formUnits();
    const int units = units_.size();
    for (int u = 0; u < units; ++u) cursors_[u].next.store(0, std::memory_order_relaxed);
    const std::span<const int> pool = units_.shared();
    const auto poolSize = static_cast<int>(pool.size());
    constexpr int kChunk = WorkUnits::kSharedChunk;
    std::atomic<int> nextShared{0};
#pragma omp parallel num_threads(threads_)
    {
      // Its own list first (list t for thread t, as the lists were formed), then the next ones.
      int own = 0;
#ifdef _OPENMP
      own = omp_get_thread_num();
#endif
      for (int step = 0; step < units; ++step) {
        const int u = (own + step) % units;
        const std::span<const int> list = units_.unit(u);
        const auto size = static_cast<int>(list.size());
        std::atomic<int>& next = cursors_[u].next;
        for (int i = next.fetch_add(1, std::memory_order_relaxed); i < size;
             i = next.fetch_add(1, std::memory_order_relaxed))
          updateOne(list[static_cast<std::size_t>(i)]);
      }
      // The deferred elements' force, by the first thread done with the lists.
#pragma omp single nowait
      residual_.formDeferredForce(eqDof_);
      for (int b = nextShared.fetch_add(kChunk, std::memory_order_relaxed); b < poolSize;
           b = nextShared.fetch_add(kChunk, std::memory_order_relaxed))
        for (int i = b; i < std::min(b + kChunk, poolSize); ++i)
          updateOne(pool[static_cast<std::size_t>(i)]);
    }
  } else {
    for (std::ptrdiff_t k = 0; k < count; ++k) updateOne(k);
  }
  elementUpdates_ += count - deferredCount_;
  ++updateCalls_;
  // The awake links' statuses (a sleeper's entry is never written).
  for (std::size_t k = 0; k < awake_; ++k) {
    if (const Status s = elementStatus_[k]; !ok(s)) {
      // A failed pass may have left elements not updated to these displacements (a non-finite
      // one is not even passed on): the next pass must not take them as applied.
      updatedDispKnown_ = false;
      return s;
    }
  }
  return Status::Ok;
}

bool AnalysisModel::nodesUnmovedSinceLastUpdate() {
  // Bit for bit (a zero of the other sign counts as a move), over every node, so a displacement
  // set by any means (an imposed motion, a command between analyses) is seen.
  bool unmoved = updatedDispKnown_;
  for (const NodeScatter& nl : nodes_) {
    const domain::Node& n = *nl.node;
    const auto bytes = static_cast<std::size_t>(n.ndf()) * sizeof(double);
    double* kept = updatedDisp_.data() + nl.firstDof;
    if (std::memcmp(kept, n.disp.data(), bytes) != 0) {
      unmoved = false;
      std::memcpy(kept, n.disp.data(), bytes);
    }
  }
  updatedDispKnown_ = true;
  return unmoved;
}

void AnalysisModel::formUnits() {
  // An element's cost: the fibers (section materials) it evaluated per update since the build,
  // plus the rest of an update in fiber evaluations. On the 10-span benchmark bridge a girder,
  // bearing or gap update takes about 1/70 of a 1,700-fiber pier's (perf, 300 steps): about 25.
  constexpr double kUpdateInFibers = 25.0;
  const double calls = static_cast<double>(std::max(updateCalls_, 1L));
  costs_.assign(awake_, kUpdateInFibers);
  for (std::size_t k = 0; k < awake_; ++k) {  // materialsAtBuild_: one count per awake element
    if (elements_[k].deferred) {              // never updated by the analysis
      costs_[k] = 0.0;
      continue;
    }
    costs_[k] +=
        static_cast<double>(elements_[k].element->materialUpdates() - materialsAtBuild_[k]) / calls;
  }
  // One list per thread of the team OpenMP will give (OMP_THREAD_LIMIT may cap it below the
  // count asked for; every list runs whatever the team, but only a list per thread balances).
  int team = threads_;
#ifdef _OPENMP
  team = std::min(team, std::max(omp_get_thread_limit(), 1));
#endif
  units_.form(costs_, team);
  if (cursorCount_ < units_.size()) {
    cursors_ = std::make_unique<ListCursor[]>(static_cast<std::size_t>(units_.size()));
    cursorCount_ = units_.size();
  }
  unitsFormedAt_ = updateCalls_;
}

bool AnalysisModel::holdStatuses() {
  bool any = false;
  for (std::size_t k = 0; k < awake_; ++k)
    if (ElementScatter& l = elements_[k]; l.switching && !l.sleeping) {
      l.element->holdStatus();
      any = true;
    }
  return any;
}

double AnalysisModel::newtonStepScale() const {
  double scale = 1.0;
  if (!anyScalesSteps_) return scale;
  // The smallest scale of those that ask for one, so that no asking element is carried past its
  // own target (the whole increment is lengthened: elements that do not ask move with it).
  for (std::size_t k = 0; k < awake_; ++k)
    if (const ElementScatter& l = elements_[k]; l.scalesSteps && !l.sleeping)
      if (const double s = l.element->newtonStepScale(); s > 1.0)
        scale = scale > 1.0 ? std::min(scale, s) : s;
  return scale;
}

elements::Element::HeldStatus AnalysisModel::checkHeldStatuses() {
  using Held = elements::Element::HeldStatus;
  Held result = Held::Agrees;
  // Every element is checked (each one that disagrees switches now, not one per round).
  for (std::size_t k = 0; k < awake_; ++k) {
    ElementScatter& l = elements_[k];
    if (!l.switching || l.sleeping) continue;
    const Held h = l.element->checkHeldStatus();
    if (h == Held::Conflict) result = Held::Conflict;
    if (h == Held::Switched && result == Held::Agrees) result = Held::Switched;
  }
  return result;
}

void AnalysisModel::formResidual(const AssemblyCoefficients& c, Eigen::VectorXd& B) const {
  residual_.form(
      c, ResidualInputs{P_, awakeLinks(), nodes_, eqDof_, penalties_, slots_, imposedMotion_}, B);
}

const Eigen::SparseMatrix<double>& AnalysisModel::formTangent(const AssemblyCoefficients& c) {
  tangent_.form(c, A_.valuePtr(), static_cast<std::size_t>(A_.nonZeros()), awakeLinks(), nodes_,
                penalties_);
  return A_;
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
  const NodeScatter& nl = nodes_[static_cast<std::size_t>(it->second)];
  if (dof < 0 || dof >= nl.node->ndf()) return -1;
  const auto& terms = dofTerms_[static_cast<std::size_t>(nl.firstDof + dof)];
  if (terms.size() == 1 && terms[0].index >= 0 && terms[0].coef == 1.0) return terms[0].index;
  return -1;
}

void AnalysisModel::setEigenvectors(const Eigen::MatrixXd& phi) {
  for (NodeScatter& nl : nodes_) {
    domain::Node& n = *nl.node;
    n.eigenvectors = Eigen::MatrixXd::Zero(n.ndf(), phi.cols());
    for (int d = 0; d < n.ndf(); ++d)
      for (const Term& t : dofTerms_[static_cast<std::size_t>(nl.firstDof + d)])
        if (t.index >= 0) n.eigenvectors.row(d) += t.coef * phi.row(t.index);
  }
}

}  // namespace dabs::analysis
