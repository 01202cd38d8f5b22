// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <map>
#include <set>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "elements/Element.h"
#include "tcl/domain/Constraints.h"
#include "tcl/domain/LoadPattern.h"
#include "tcl/domain/Node.h"
#include "tcl/domain/Recorder.h"
#include "tcl/domain/RecorderSet.h"

namespace dabs::domain {

/// Rayleigh damping factors, C = alphaM M + betaK K_current + betaK0 K_initial + betaKc
/// K_committed.
struct RayleighFactors {
  double alphaM = 0.0;
  double betaK = 0.0;
  double betaK0 = 0.0;
  double betaKc = 0.0;
  bool any() const noexcept {
    return alphaM != 0.0 || betaK != 0.0 || betaK0 != 0.0 || betaKc != 0.0;
  }
};

/// The model: nodes, elements, constraints, load patterns, recorders and the (pseudo) time. It owns
/// everything through std::map<int, ...> (style.md section 4). Every mutator checks its input first
/// and throws InputError before changing anything, so a rejected command leaves the model as it
/// was. The analysis (tcl/analysis) reads the model through this interface and writes trial
/// responses into the nodes.
class Domain {
 public:
  Domain();
  ~Domain();
  Domain(const Domain&) = delete;
  Domain& operator=(const Domain&) = delete;

  // --- nodes and elements -----------------------------------------------------------------
  /// Adds a node; throws InputError on a duplicate tag.
  Node& addNode(int tag, int ndm, int ndf, const Eigen::Vector3d& coords);
  /// Adds an element after checking that its nodes exist, have the element's dofs per node and
  /// that its geometry is valid (Element::initialize); throws InputError otherwise.
  elements::Element& addElement(std::unique_ptr<elements::Element> element);
  /// Node by tag, or nullptr.
  const Node* findNode(int tag) const;
  Node* findNode(int tag);
  /// Node by tag; throws InputError("node", ...) when absent.
  const Node& node(int tag) const;
  Node& node(int tag);
  /// Element by tag, or nullptr.
  const elements::Element* findElement(int tag) const;
  elements::Element* findElement(int tag);
  const std::map<int, Node>& nodes() const noexcept { return nodes_; }
  std::map<int, Node>& nodes() noexcept { return nodes_; }
  const std::map<int, std::unique_ptr<elements::Element>>& elements() const noexcept {
    return elements_;
  }
  /// Removes an element / a node (the node must not be used by an element); throws when absent.
  void removeElement(int tag);
  void removeNode(int tag);

  // --- constraints ----------------------------------------------------------------------
  /// Homogeneous single-point constraint (fix); dof is 0-based. Throws on a duplicate or bad dof.
  void addFix(int nodeTag, int dof);
  /// Equal-dof or rigid-link multi-point constraint; throws InputError when inconsistent.
  void addMP(MPConstraint mp);
  const std::vector<SPConstraint>& fixes() const noexcept { return fixes_; }
  const std::vector<MPConstraint>& mps() const noexcept { return mps_; }
  /// Removes every SP constraint (fix) on a node dof (every dof when dof < 0), including a fix a
  /// pattern's imposed motion took over (the pattern then no longer gives it back when it is
  /// removed); returns how many were removed.
  int removeFix(int nodeTag, int dof);

  // --- loads ----------------------------------------------------------------------------
  /// Adds a pattern; throws InputError on a duplicate tag.
  LoadPattern& addPattern(std::unique_ptr<LoadPattern> pattern);
  LoadPattern* findPattern(int tag);
  void removePattern(int tag);
  const std::map<int, std::unique_ptr<LoadPattern>>& patterns() const noexcept { return patterns_; }
  /// Freezes every pattern at its current factor (loadConst).
  void setLoadConst();

  // --- damping --------------------------------------------------------------------------
  /// Sets Rayleigh factors on all elements and nodes (the `rayleigh` command).
  void setRayleigh(const RayleighFactors& f);
  /// Sets Rayleigh factors on listed elements and nodes (`region ... -rayleigh`).
  void setRayleigh(const RayleighFactors& f, const std::vector<int>& elementTags,
                   const std::vector<int>& nodeTags);
  /// Rayleigh factors of an element (zero when none were set or the element declines them).
  RayleighFactors elementRayleigh(int elementTag) const;
  /// Rayleigh mass factor of a node.
  double nodeAlphaM(int nodeTag) const;
  /// Rayleigh damping force of an element at the current state, (alphaM M + betaK K + betaK0 K0 +
  /// betaKc Kc) v in the element's global dofs; zero when the element has no Rayleigh damping.
  /// Throws InputError("eleTag") when the element does not exist.
  Eigen::VectorXd elementRayleighForce(int elementTag) const;
  /// A named element response: the element's own responses, plus `dampingForces` (also
  /// `dampingForce`, `rayleighForces`, `RayleighForces`, as in OpenSees), the Rayleigh force,
  /// which the domain forms. nullopt when the element or the name is unknown.
  std::optional<Eigen::VectorXd> elementResponse(int elementTag,
                                                 std::span<const std::string> args) const;
  /// Modal damping ratio per mode (empty when none).
  std::vector<double> modalDamping;

  // --- time and state -------------------------------------------------------------------
  double time() const noexcept { return time_; }
  double committedTime() const noexcept { return committedTime_; }
  /// Sets the trial time and applies the patterns' member loads at it (each element's loads are
  /// replaced by the sum over the patterns of factor(t) times its loads, as OpenSees'
  /// Domain::applyLoad does), in effect from the elements' next update.
  void setTime(double t);
  /// setTime command: sets trial and committed time.
  void setCommittedTime(double t);
  /// Commits nodes, elements and time, then lets recorders record.
  void commit();
  /// Reverts nodes, elements and time to the last commit.
  void revertToLastCommit();
  /// Back to the virgin state at time 0 (the `reset` command).
  void revertToStart();
  /// Marks whether the analysis keeps the state of the element at `index` (its position in tag
  /// order, the order of elements()) until it takes the element up again, so commit and revert
  /// skip it: a sleeping contact pair whose face's test is deferred (its gap is formed anew when
  /// the test is due) then costs nothing per step. The marks are cleared whenever the model
  /// changes, and the analysis clears them at the end of `analyze`.
  void setStateKept(std::size_t index, bool kept);
  /// Clears every mark of setStateKept.
  void clearStateKept();
  /// Marks whether the analysis forms the element's force itself, from its nodes' displacements
  /// (Element::forceIsInitialStiffnessTimesDisplacements), and leaves the element un-updated.
  /// While marked, commit and revert skip the element and every read here (elementResponse,
  /// elementForce, reactions) first updates it at its nodes' trial response; unmarking brings
  /// its committed state and then its trial state up to date. Throws InputError("element") when
  /// the element does not exist or its state is not a function of its displacements.
  void setStateDeferred(int elementTag, bool deferred);
  bool stateDeferred(int elementTag) const { return deferred_.count(elementTag) != 0; }
  /// The element's force (Element::resistingForce) at the current trial state; throws
  /// InputError("eleTag") when the element does not exist.
  Eigen::VectorXd elementForce(int elementTag) const;
  /// Increases whenever nodes, elements, constraints or patterns change; the analysis re-numbers
  /// its equations when this differs from what it saw.
  long modelVersion() const noexcept { return modelVersion_; }
  /// Sum of the elements' material update counts (Element::materialUpdates).
  long materialUpdates() const;
  void touch() noexcept { ++modelVersion_; }

  /// Eigenvalues of the last eigen analysis.
  std::vector<double> eigenvalues;

  // --- recorders ------------------------------------------------------------------------
  /// Adds a recorder and returns its tag (0, 1, 2, ... as OpenSees does).
  int addRecorder(std::unique_ptr<Recorder> recorder);
  void removeRecorder(int tag) { recorders_.remove(tag); }
  void removeAllRecorders() { recorders_.removeAll(false); }
  void flushRecorders() { recorders_.flush(); }
  /// Tags of the elements whose responses some recorder reads (sorted, unique).
  std::vector<int> recordedElements() const;
  /// Records the current state with every recorder. A recorder that cannot write (a full disk)
  /// does not stop the others; its error is kept for takeRecorderError().
  void record();
  /// The first recorder write error since the last call, if any (the step loop stops on it).
  std::optional<std::string> takeRecorderError() { return recorders_.takeError(); }

  /// Computes nodal reactions from element forces and applied loads; with `includeInertia`,
  /// inertia and damping forces too (`reactions -dynamic`).
  void calculateNodalReactions(bool includeInertia);

  /// External nodal load vector of a node at the current time (sum over patterns).
  Eigen::VectorXd nodalLoad(int nodeTag) const;

  /// Empties the model (wipe): recorders are flushed and closed first.
  void clear();

 private:
  std::map<int, Node> nodes_;
  std::map<int, std::unique_ptr<elements::Element>> elements_;
  std::vector<SPConstraint> fixes_;
  std::vector<MPConstraint> mps_;
  // (node, dof) of fixes_ and of the dofs mps_ constrain, kept with them so that adding a fix or
  // a constraint checks them in log time: a model of n constraints is built in n log n.
  std::set<std::pair<int, int>> fixedDofs_;
  std::set<std::pair<int, int>> constrainedDofs_;
  std::map<int, std::unique_ptr<LoadPattern>> patterns_;
  std::map<int, RayleighFactors> elementRayleigh_;
  std::map<int, double> nodeAlphaM_;
  /// An element's slice of a nodal vector (disp, vel, accel), node by node.
  Eigen::VectorXd gatherElement(const elements::Element& e, Eigen::VectorXd Node::*field) const;
  RecorderSet recorders_;
  double time_ = 0.0;
  double committedTime_ = 0.0;
  long modelVersion_ = 0;
  /// Nodes and elements in tag order as flat lists for the loops of every step (commit, revert),
  /// which would otherwise take a tree step per map entry; rebuilt when the model version changes.
  void refreshLists();
  std::vector<Node*> nodeList_;
  std::vector<elements::Element*> elementList_;
  std::vector<char> stateKept_;     ///< per element of elementList_ (setStateKept)
  std::set<int> deferred_;          ///< tags of the elements setStateDeferred marks
  std::vector<char> deferredList_;  ///< per element of elementList_: in deferred_
  /// An element whose state is deferred: updated at its nodes' trial response (a cache filled
  /// on reading, so the const readers may call it).
  void formDeferredState(int elementTag) const;
  /// Updates `e` at its nodes' (committed or trial) response.
  void updateAt(elements::Element& e, bool committed) const;
  long listVersion_ = -1;
  /// Member loads at time t on the elements (see setTime).
  void applyElementLoads(double t);
  bool elementLoadsApplied_ = false;  ///< some element holds member loads
  double elementLoadsTime_ = 0.0;     ///< the time the member loads were last applied at
};

}  // namespace dabs::domain
