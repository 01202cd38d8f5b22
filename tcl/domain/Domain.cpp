// SPDX-License-Identifier: MIT
#include "tcl/domain/Domain.h"

#include <algorithm>
#include <limits>
#include <string>

#include "materials/InputError.h"

namespace dabs::domain {

Domain::Domain() = default;
Domain::~Domain() { recorders_.flush(); }

Node& Domain::addNode(int tag, int ndm, int ndf, const Eigen::Vector3d& coords) {
  if (nodes_.count(tag) != 0)
    throw InputError("", "node " + std::to_string(tag) + " already exists");
  if (ndf < 1 || ndf > 6) throw InputError("ndf", "must be 1 to 6");
  auto [it, inserted] = nodes_.emplace(tag, Node(tag, ndm, ndf, coords));
  (void)inserted;
  touch();
  return it->second;
}

elements::Element& Domain::addElement(std::unique_ptr<elements::Element> element) {
  if (!element) throw InputError("element", "is missing");
  const int tag = element->tag();
  if (elements_.count(tag) != 0)
    throw InputError("", "element " + std::to_string(tag) + " already exists");
  elements::NodalCoordinates x;
  for (int n : element->nodeTags()) {
    const Node* nd = findNode(n);
    if (nd == nullptr) throw InputError("node", std::to_string(n) + " does not exist");
    if (nd->ndf() != element->dofPerNode()) {
      throw InputError("node", std::to_string(n) + " has " + std::to_string(nd->ndf()) +
                                   " dofs but " + std::string(element->typeName()) + " needs " +
                                   std::to_string(element->dofPerNode()));
    }
    x.push_back(nd->coords());
  }
  element->initialize(x);  // throws InputError on bad geometry, before anything is stored
  auto& stored = *(elements_[tag] = std::move(element));
  touch();
  return stored;
}

const Node* Domain::findNode(int tag) const {
  auto it = nodes_.find(tag);
  return it == nodes_.end() ? nullptr : &it->second;
}
Node* Domain::findNode(int tag) {
  auto it = nodes_.find(tag);
  return it == nodes_.end() ? nullptr : &it->second;
}
const Node& Domain::node(int tag) const {
  const Node* n = findNode(tag);
  if (n == nullptr) throw InputError("node", std::to_string(tag) + " does not exist");
  return *n;
}
Node& Domain::node(int tag) {
  Node* n = findNode(tag);
  if (n == nullptr) throw InputError("node", std::to_string(tag) + " does not exist");
  return *n;
}
const elements::Element* Domain::findElement(int tag) const {
  auto it = elements_.find(tag);
  return it == elements_.end() ? nullptr : it->second.get();
}
elements::Element* Domain::findElement(int tag) {
  auto it = elements_.find(tag);
  return it == elements_.end() ? nullptr : it->second.get();
}

void Domain::removeElement(int tag) {
  if (elements_.count(tag) == 0)
    throw InputError("element", std::to_string(tag) + " does not exist");
  for (const auto& [ptag, p] : patterns_) {
    for (const ElementLoad& l : p->elementLoads())
      if (l.element == tag)
        throw InputError("element", std::to_string(tag) + " is loaded by pattern " +
                                        std::to_string(ptag) + "; remove the pattern first");
  }
  elements_.erase(tag);
  elementRayleigh_.erase(tag);
  deferred_.erase(tag);
  touch();
}

void Domain::removeNode(int tag) {
  if (nodes_.count(tag) == 0) throw InputError("node", std::to_string(tag) + " does not exist");
  for (const auto& [etag, e] : elements_) {
    const auto& nt = e->nodeTags();
    if (std::find(nt.begin(), nt.end(), tag) != nt.end())
      throw InputError("node", std::to_string(tag) + " is used by element " + std::to_string(etag));
  }
  for (const auto& mp : mps_) {
    if (mp.retainedNode == tag || mp.constrainedNode == tag)
      throw InputError("node", std::to_string(tag) + " is used by a multi-point constraint");
  }
  // A pattern still loading the node would make every later analysis fail; the user removes the
  // pattern first (OpenSees leaves the dangling load in the pattern).
  for (const auto& [ptag, p] : patterns_) {
    if (p->usesNode(tag))
      throw InputError("node", std::to_string(tag) + " is loaded by pattern " +
                                   std::to_string(ptag) + "; remove the pattern first");
  }
  fixes_.erase(std::remove_if(fixes_.begin(), fixes_.end(),
                              [tag](const SPConstraint& sp) { return sp.node == tag; }),
               fixes_.end());
  fixedDofs_.erase(fixedDofs_.lower_bound({tag, std::numeric_limits<int>::min()}),
                   fixedDofs_.upper_bound({tag, std::numeric_limits<int>::max()}));
  nodes_.erase(tag);
  nodeAlphaM_.erase(tag);
  touch();
}

void Domain::addFix(int nodeTag, int dof) {
  const Node& n = node(nodeTag);
  if (dof < 0 || dof >= n.ndf())
    throw InputError("dof", std::to_string(dof + 1) + " is outside 1.." + std::to_string(n.ndf()) +
                                " of node " + std::to_string(nodeTag));
  if (fixedDofs_.count({nodeTag, dof}) != 0)
    throw InputError("dof", std::to_string(dof + 1) + " of node " + std::to_string(nodeTag) +
                                " is already fixed");
  if (constrainedDofs_.count({nodeTag, dof}) != 0)
    throw InputError("dof", std::to_string(dof + 1) + " of node " + std::to_string(nodeTag) +
                                " is already constrained by a multi-point constraint");
  fixes_.push_back({nodeTag, dof});
  fixedDofs_.emplace(nodeTag, dof);
  touch();
}

int Domain::removeFix(int nodeTag, int dof) {
  const auto before = fixes_.size();
  fixes_.erase(std::remove_if(fixes_.begin(), fixes_.end(),
                              [&](const SPConstraint& sp) {
                                const bool match = sp.node == nodeTag && (dof < 0 || sp.dof == dof);
                                if (match) fixedDofs_.erase({sp.node, sp.dof});
                                return match;
                              }),
               fixes_.end());
  int removed = static_cast<int>(before - fixes_.size());
  // A fix that a support motion (imposedMotion) took over while its pattern exists: removing it
  // (OpenSees scripts do, `remove sp` after `imposedMotion`) means the pattern gives it back no
  // more; the motion goes on driving the dof.
  for (auto& [ptag, p] : patterns_)
    if (MultipleSupportPattern* ms = p->asMultipleSupport())
      for (auto& m : ms->imposed)
        if (m.replacedFix && m.node == nodeTag && (dof < 0 || m.dof == dof)) {
          m.replacedFix = false;
          ++removed;
        }
  if (removed > 0) touch();
  return removed;
}

void Domain::addMP(MPConstraint mp) {
  const Node& r = node(mp.retainedNode);
  const Node& c = node(mp.constrainedNode);
  if (mp.retainedNode == mp.constrainedNode)
    throw InputError("cNode", "must differ from the retained node");
  if (mp.Ccr.rows() != static_cast<Eigen::Index>(mp.constrainedDofs.size()) ||
      mp.Ccr.cols() != static_cast<Eigen::Index>(mp.retainedDofs.size()))
    throw InputError("constraint", "matrix does not match the dof lists");
  for (int d : mp.constrainedDofs) {
    if (d < 0 || d >= c.ndf())
      throw InputError("dof", std::to_string(d + 1) + " is outside 1.." + std::to_string(c.ndf()) +
                                  " of node " + std::to_string(c.tag()));
    if (fixedDofs_.count({c.tag(), d}) != 0)
      throw InputError("dof", std::to_string(d + 1) + " of node " + std::to_string(c.tag()) +
                                  " is fixed and cannot also be constrained");
    if (constrainedDofs_.count({c.tag(), d}) != 0)
      throw InputError("dof", std::to_string(d + 1) + " of node " + std::to_string(c.tag()) +
                                  " is already constrained");
  }
  for (int d : mp.retainedDofs) {
    if (d < 0 || d >= r.ndf())
      throw InputError("dof", std::to_string(d + 1) + " is outside 1.." + std::to_string(r.ndf()) +
                                  " of node " + std::to_string(r.tag()));
  }
  for (int d : mp.constrainedDofs) constrainedDofs_.emplace(mp.constrainedNode, d);
  mps_.push_back(std::move(mp));
  touch();
}

LoadPattern& Domain::addPattern(std::unique_ptr<LoadPattern> pattern) {
  const int tag = pattern->tag();
  if (patterns_.count(tag) != 0)
    throw InputError("", "pattern " + std::to_string(tag) + " already exists");
  auto& stored = *(patterns_[tag] = std::move(pattern));
  touch();
  return stored;
}

LoadPattern* Domain::findPattern(int tag) {
  auto it = patterns_.find(tag);
  return it == patterns_.end() ? nullptr : it->second.get();
}

void Domain::removePattern(int tag) {
  auto it = patterns_.find(tag);
  if (it == patterns_.end()) throw InputError("pattern", std::to_string(tag) + " does not exist");
  for (const SPConstraint& m : it->second->replacedFixes()) {  // supports give a fix back
    const bool fixed = fixedDofs_.count({m.node, m.dof}) != 0;
    if (!fixed && nodes_.count(m.node) != 0) {
      fixes_.push_back(m);
      fixedDofs_.emplace(m.node, m.dof);
    }
  }
  patterns_.erase(it);
  touch();
}

void Domain::setLoadConst() {
  for (auto& [tag, p] : patterns_) p->setConstant(time_);
}

void Domain::setRayleigh(const RayleighFactors& f) {
  for (const auto& [tag, e] : elements_) elementRayleigh_[tag] = f;
  for (const auto& [tag, n] : nodes_) nodeAlphaM_[tag] = f.alphaM;
  touch();
}

void Domain::setRayleigh(const RayleighFactors& f, const std::vector<int>& elementTags,
                         const std::vector<int>& nodeTags) {
  for (int t : elementTags) elementRayleigh_[t] = f;
  for (int t : nodeTags) nodeAlphaM_[t] = f.alphaM;
  touch();
}

RayleighFactors Domain::elementRayleigh(int elementTag) const {
  auto it = elementRayleigh_.find(elementTag);
  if (it == elementRayleigh_.end()) return RayleighFactors{};
  const elements::Element* e = findElement(elementTag);
  return e != nullptr && e->rayleighByDefault() ? it->second : RayleighFactors{};
}

double Domain::nodeAlphaM(int nodeTag) const {
  auto it = nodeAlphaM_.find(nodeTag);
  return it == nodeAlphaM_.end() ? 0.0 : it->second;
}

void Domain::refreshLists() {
  if (listVersion_ == modelVersion_) return;
  nodeList_.clear();
  for (auto& [tag, n] : nodes_) nodeList_.push_back(&n);
  elementList_.clear();
  for (auto& [tag, e] : elements_) elementList_.push_back(e.get());
  stateKept_.assign(elementList_.size(), 0);
  deferredList_.clear();
  for (const elements::Element* e : elementList_)
    deferredList_.push_back(deferred_.count(e->tag()) != 0 ? 1 : 0);
  listVersion_ = modelVersion_;
}

void Domain::commit() {
  refreshLists();
  for (Node* n : nodeList_) n->commitState();
  for (std::size_t i = 0; i < elementList_.size(); ++i)
    if (!stateKept_[i] && !deferredList_[i]) elementList_[i]->commitState();
  committedTime_ = time_;
  record();
}

void Domain::setStateKept(std::size_t index, bool kept) {
  refreshLists();
  if (index < stateKept_.size()) stateKept_[index] = kept ? 1 : 0;
}

void Domain::clearStateKept() { std::fill(stateKept_.begin(), stateKept_.end(), 0); }

void Domain::setStateDeferred(int elementTag, bool deferred) {
  const auto it = elements_.find(elementTag);
  if (it == elements_.end())
    throw InputError("element", std::to_string(elementTag) + " does not exist");
  elements::Element& e = *it->second;
  if (deferred == stateDeferred(elementTag)) return;
  if (deferred) {
    if (!e.forceIsInitialStiffnessTimesDisplacements())
      throw InputError("element", std::to_string(elementTag) +
                                      " has a state of its own; it cannot be formed when read");
    deferred_.insert(elementTag);
  } else {
    deferred_.erase(elementTag);
    // Commit skipped it: its committed state is formed at the nodes' committed response, then
    // its trial state at their trial one.
    updateAt(e, true);
    e.commitState();
    updateAt(e, false);
  }
  if (listVersion_ == modelVersion_) {  // the lists are in tag order
    const auto pos =
        std::lower_bound(elementList_.begin(), elementList_.end(), elementTag,
                         [](const elements::Element* a, int tag) { return a->tag() < tag; });
    deferredList_[static_cast<std::size_t>(pos - elementList_.begin())] = deferred ? 1 : 0;
  }
}

void Domain::updateAt(elements::Element& e, bool committed) const {
  const Eigen::VectorXd u = gatherElement(e, committed ? &Node::committedDisp : &Node::disp);
  const Eigen::VectorXd v = gatherElement(e, committed ? &Node::committedVel : &Node::vel);
  const Eigen::VectorXd a = gatherElement(e, committed ? &Node::committedAccel : &Node::accel);
  const double t = committed ? committedTime_ : time_;
  // A non-finite response gives a non-finite state, which is what the reader should see.
  static_cast<void>(e.update(elements::Kinematics{u, v, a, t, t - committedTime_}));
}

void Domain::formDeferredState(int elementTag) const {
  if (deferred_.count(elementTag) == 0) return;
  updateAt(*elements_.at(elementTag), false);
}

Eigen::VectorXd Domain::elementForce(int elementTag) const {
  const elements::Element* e = findElement(elementTag);
  if (e == nullptr)
    throw InputError("eleTag", "element " + std::to_string(elementTag) + " does not exist");
  formDeferredState(elementTag);
  return e->resistingForce();
}

std::vector<int> Domain::recordedElements() const {
  std::vector<int> tags = recorders_.elementsRead();
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

void Domain::setTime(double t) {
  applyElementLoads(t);  // first: a refused load leaves the time as it was
  time_ = t;
}

void Domain::setCommittedTime(double t) {
  applyElementLoads(t);
  time_ = committedTime_ = t;
}

void Domain::applyElementLoads(double t) {
  bool any = false;
  for (const auto& [ptag, p] : patterns_) any = any || !p->elementLoads().empty();
  if (!any && !elementLoadsApplied_) return;
  const auto apply = [&](double at, bool skipRefused) {
    for (auto& [tag, e] : elements_) e->zeroLoad();
    for (const auto& [ptag, p] : patterns_) {
      if (p->elementLoads().empty()) continue;
      const double f = p->factor(at);
      for (const ElementLoad& l : p->elementLoads()) {
        // The eleLoad command checked the element and the load; removeElement keeps them.
        elements::Element* e = findElement(l.element);
        if (e == nullptr) continue;
        try {
          e->addLoad(l.load, f);
        } catch (const InputError&) {
          // in the restore below a refused load was not held before either
          if (!skipRefused) throw;
        }
      }
    }
  };
  try {
    apply(t, false);
  } catch (...) {
    // An element refused its load (only C++ code that fills a pattern itself can build this):
    // the loads go back to what they were, applied at the time they last were, and the caller
    // keeps its time.
    apply(elementLoadsTime_, true);
    throw;
  }
  elementLoadsTime_ = t;
  elementLoadsApplied_ = any;
}

void Domain::revertToLastCommit() {
  applyElementLoads(committedTime_);
  refreshLists();
  for (Node* n : nodeList_) n->revertToLastCommit();
  for (std::size_t i = 0; i < elementList_.size(); ++i)
    if (!stateKept_[i] && !deferredList_[i]) elementList_[i]->revertToLastCommit();
  time_ = committedTime_;
}

void Domain::revertToStart() {
  applyElementLoads(0.0);
  for (auto& [tag, n] : nodes_) n.revertToStart();
  for (auto& [tag, e] : elements_) e->revertToStart();
  time_ = committedTime_ = 0.0;
}

int Domain::addRecorder(std::unique_ptr<Recorder> recorder) {
  recorder->initialize(*this);
  return recorders_.add(std::move(recorder));
}

long Domain::materialUpdates() const {
  long n = 0;
  for (const auto& [tag, e] : elements_) n += e->materialUpdates();
  return n;
}

void Domain::record() {
  recorders_.record(*this, [this] { calculateNodalReactions(false); });
}

Eigen::VectorXd Domain::nodalLoad(int nodeTag) const {
  const Node& n = node(nodeTag);
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n.ndf());
  for (const auto& [tag, pat] : patterns_) {
    if (pat->nodalLoads().empty()) continue;
    const double f = pat->factor(time_);
    for (const NodalLoad& load : pat->nodalLoads())
      if (load.node == nodeTag) p += f * load.values;
  }
  return p;
}

Eigen::VectorXd Domain::gatherElement(const elements::Element& e,
                                      Eigen::VectorXd Node::*field) const {
  Eigen::VectorXd out(e.numDof());
  Eigen::Index offset = 0;
  for (int nt : e.nodeTags()) {
    const Node& n = nodes_.at(nt);
    out.segment(offset, n.ndf()) = n.*field;
    offset += n.ndf();
  }
  return out;
}

Eigen::VectorXd Domain::elementRayleighForce(int elementTag) const {
  const elements::Element* e = findElement(elementTag);
  if (e == nullptr)
    throw InputError("eleTag", "element " + std::to_string(elementTag) + " does not exist");
  const RayleighFactors r = elementRayleigh(elementTag);
  if (!r.any()) return Eigen::VectorXd::Zero(e->numDof());
  const Eigen::VectorXd v = gatherElement(*e, &Node::vel);
  return (r.alphaM * e->mass() + r.betaK * e->tangentStiff() + r.betaK0 * e->initialStiff() +
          r.betaKc * e->committedStiff()) *
         v;
}

std::optional<Eigen::VectorXd> Domain::elementResponse(int elementTag,
                                                       std::span<const std::string> args) const {
  const elements::Element* e = findElement(elementTag);
  if (e == nullptr || args.empty()) return std::nullopt;
  if (args.size() == 1 && (args[0] == "dampingForces" || args[0] == "dampingForce" ||
                           args[0] == "rayleighForces" || args[0] == "RayleighForces"))
    return elementRayleighForce(elementTag);
  formDeferredState(elementTag);
  return e->response(args);
}

void Domain::calculateNodalReactions(bool includeInertia) {
  for (auto& [tag, n] : nodes_) n.reaction = -nodalLoad(tag);
  for (const auto& [etag, e] : elements_) {
    formDeferredState(etag);
    Eigen::VectorXd f = e->resistingForce();
    if (includeInertia)
      f += e->mass() * gatherElement(*e, &Node::accel) + elementRayleighForce(etag);
    Eigen::Index offset = 0;
    for (int nt : e->nodeTags()) {
      Node& n = nodes_.at(nt);
      n.reaction += f.segment(offset, n.ndf());
      offset += n.ndf();
    }
  }
  if (includeInertia) {
    for (auto& [tag, n] : nodes_) {
      n.reaction += n.mass() * n.accel + nodeAlphaM(tag) * n.mass() * n.vel;
    }
  }
}

void Domain::clear() {
  recorders_.removeAll(true);
  elements_.clear();
  nodes_.clear();
  fixes_.clear();
  mps_.clear();
  fixedDofs_.clear();
  constrainedDofs_.clear();
  patterns_.clear();
  elementRayleigh_.clear();
  nodeAlphaM_.clear();
  modalDamping.clear();
  eigenvalues.clear();
  time_ = committedTime_ = 0.0;
  elementLoadsApplied_ = false;
  deferred_.clear();
  touch();
}

}  // namespace dabs::domain
