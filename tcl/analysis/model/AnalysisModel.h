// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "elements/FarPair.h"
#include "materials/Status.h"
#include "tcl/analysis/model/ConstraintHandler.h"
#include "tcl/analysis/model/DofNumberer.h"
#include "tcl/analysis/model/ResidualAssembler.h"
#include "tcl/analysis/model/Scatter.h"
#include "tcl/analysis/model/SleepingPairs.h"
#include "tcl/analysis/model/TangentAssembler.h"
#include "tcl/analysis/model/WorkUnits.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// The equations of a domain: numbers the free dofs (DofNumberer for the node order,
/// ConstraintHandler for what is an equation), keeps each element's scatter indices into the
/// sparse matrix's value array (AssemblyPattern; assembly is an indexed add), writes trial
/// responses to nodes, and assembles the residual and tangent. Plays the role of OpenSees'
/// AnalysisModel (OpenSees/OpenSees:SRC/analysis/model/AnalysisModel.cpp).
///
/// A node dof is either an equation or prescribed. A prescribed dof's value is a combination of
/// equations and prescribed "slots" (support values from fix, sp and imposedMotion), which covers
/// equalDOF and rigidLink under the Transformation handler. Under the Penalty handler every dof is
/// an equation and constraints add alpha C^T C to the stiffness.
///
/// The per-element and per-node scatter records are value types (Scatter.h); the residual
/// (ResidualAssembler), the tangent (TangentAssembler) and the sleeping contact pairs
/// (SleepingPairs) are formed by classes the model owns and passes them to.
class AnalysisModel {
 public:
  AnalysisModel(domain::Domain& domain, ConstraintKind constraints, NumbererKind numberer,
                double alphaSP = 0.0, double alphaMP = 0.0);

  /// Numbers the equations and builds the sparse pattern for the domain as it is now. Throws
  /// InputError for constraints this handler cannot enforce.
  void build();
  /// True when the domain changed since build().
  bool stale() const noexcept { return builtVersion_ != domain_.modelVersion(); }

  int numEquations() const noexcept { return neq_; }
  /// Elements the iterations update (the sleeping contact pairs left out).
  std::size_t awakeElements() const noexcept { return awake_; }
  /// Sparse matrix with the pattern of every possible coupling (values zero after build).
  const Eigen::SparseMatrix<double>& pattern() const noexcept { return A_; }
  /// True when some element declares a non-symmetric tangent.
  bool nonSymmetric() const;
  /// True when some element that currently carries stiffness has a non-symmetric tangent.
  bool nonSymmetricNow() const;
  /// True when every element is linear, so the tangent never changes between assemblies.
  bool allLinear() const;

  /// Sets the time, support values (fix, sp, imposed motion) and external loads at time t.
  void applyLoad(double t);
  /// External load vector (equation space) of the last applyLoad.
  const Eigen::VectorXd& externalLoad() const noexcept { return P_; }
  /// External load vector at time t without changing the state (for reference loads).
  Eigen::VectorXd externalLoadAt(double t);
  /// The same into P (resized only when its size differs: no allocation in the step loop).
  void externalLoadAt(double t, Eigen::VectorXd& P);

  /// Writes U, V, A (equation space) to the nodes' trial response; prescribed dofs take their
  /// support values.
  void setResponse(const Eigen::VectorXd& U, const Eigen::VectorXd& V, const Eigen::VectorXd& A);
  /// Reads the nodes' committed (or trial) response into equation space.
  void getResponse(Eigen::VectorXd& U, Eigen::VectorXd& V, Eigen::VectorXd& A,
                   bool committed) const;
  /// Updates every element from its nodes' trial response.
  [[nodiscard]] Status updateElements();
  /// Holds the statuses of the awake elements that switch them (Element::holdStatus); false when
  /// there is none.
  bool holdStatuses();
  /// Checks the held statuses after an update (Element::checkHeldStatus): Switched when some
  /// element switched (none conflicting), Conflict when one found no status that agrees.
  elements::Element::HeldStatus checkHeldStatuses();
  /// After an update: the multiple of Newton's last step that the awake elements ask for
  /// (Element::newtonStepScale), the smallest of those above 1, or 1 when none asks.
  double newtonStepScale() const;
  /// Element updates since construction (a work count for benchmarks).
  long elementUpdates() const noexcept { return elementUpdates_; }
  /// Threads that update elements (1: the calling thread alone). Results do not depend on it.
  void setThreads(int threads) noexcept {
    const int count = threads < 1 ? 1 : threads;
    if (count != threads_) unitsFormedAt_ = -1;  // one list per thread
    threads_ = count;
  }
  /// Threads in force (the linear system's factorisation may share its work among them).
  int threads() const noexcept { return threads_; }
  /// Threads the process may use for the element updates (1 without OpenMP).
  static int availableThreads() noexcept;

  /// Residual B = P - F_int (- inertia - damping when dynamic).
  void formResidual(const AssemblyCoefficients& c, Eigen::VectorXd& B) const;
  /// Tangent A = cK K + cC C + cM M; returns the matrix (pattern fixed at build).
  const Eigen::SparseMatrix<double>& formTangent(const AssemblyCoefficients& c);
  /// Mass matrix (elements and nodes) in equation space.
  Eigen::SparseMatrix<double> formMass();
  /// Equation of (node, dof), or -1 when the dof is prescribed.
  int equationOf(int nodeTag, int dof) const;
  /// Mass-orthonormal eigenvectors in equation space to node eigenvectors.
  void setEigenvectors(const Eigen::MatrixXd& phi);

  /// Modal damping (modalDamping): C_modal = sum_i 2 zeta_i omega_i (M phi_i)(M phi_i)^T.
  void setModalDamping(const Eigen::MatrixXd& Mphi, const Eigen::VectorXd& coefficients) {
    residual_.setModalDamping(Mphi, coefficients);
  }
  bool hasModalDamping() const noexcept { return residual_.hasModalDamping(); }
  const Eigen::MatrixXd& modalBasis() const noexcept { return residual_.modalBasis(); }
  const Eigen::VectorXd& modalCoefficients() const noexcept {
    return residual_.modalCoefficients();
  }

  domain::Domain& domain() noexcept { return domain_; }

  // --- sleeping contact pairs (SleepingPairs) ---------------------------------------------
  using SleepCheck = SleepingPairs::Check;
  /// After a step converged (trial state): SleepingPairs::check, waking the sleepers it finds
  /// near with their full update.
  SleepCheck checkSleepingPairs();
  /// Rebuilds the pattern and scatter with the noted pairs woken or sleeping (equations unchanged);
  /// the linear system must then analyse the new pattern.
  void applySleepChanges();
  long sleepingPairs() const noexcept { return sleepers_.sleeping(); }
  /// SleepingPairs::farTests.
  long farTests() const noexcept { return sleepers_.farTests(); }
  /// SleepingPairs::beginSteps.
  void beginSteps(bool observeAll) { sleepers_.beginSteps(observeAll); }
  /// SleepingPairs::endSteps.
  void endSteps() { sleepers_.endSteps(); }
  /// SleepingPairs::deferredFaces.
  std::size_t deferredFaces() const { return sleepers_.deferredFaces(); }

 private:
  using Term = DofTerm;
  using Slot = SupportSlot;

  void numberEquations();
  void buildScatter();
  /// The pairs that may sleep, with the scatter just built, to sleepers_.
  void buildSleepers();
  /// The residual's constant matrices for the new scatter.
  void buildConstantDynamics() { residual_.build(elements_, nodes_, A_); }
  /// A dof's displacement, velocity and acceleration from its terms (one pass over them; each
  /// sum in the terms' order).
  std::array<double, 3> termValues(const std::vector<Term>& terms, const Eigen::VectorXd& U,
                                   const Eigen::VectorXd& V, const Eigen::VectorXd& A) const;

  domain::Domain& domain_;
  ConstraintKind constraints_;
  NumbererKind numberer_;
  double alphaSP_, alphaMP_;
  long builtVersion_ = -1;
  int neq_ = 0;
  double time_ = 0.0;

  std::vector<std::vector<Term>> dofTerms_;  // per node dof: combination of equations and slots
  std::vector<int> directEq_;  // per node dof: its equation when it is one (coefficient 1), or -1
  std::vector<Slot> slots_;
  std::vector<int> patternSlots_;  // slot of each pattern sp / imposed motion, in pattern order
  std::vector<domain::SupportMotion> supportMotion_;  // the patterns' support motion, same order
  std::vector<NodeScatter> nodes_;
  std::vector<ElementScatter> elements_;
  std::vector<PenaltyRow> penalties_;
  std::map<int, int> nodeIndex_;                      // node tag -> index in nodes_
  std::vector<std::pair<domain::Node*, int>> eqDof_;  // node and dof of each equation
  Eigen::SparseMatrix<double> A_;
  Eigen::VectorXd P_;
  bool imposedMotion_ = false;
  ResidualAssembler residual_;
  TangentAssembler tangent_;
  SleepingPairs sleepers_;
  long elementUpdates_ = 0;
  std::ptrdiff_t deferredCount_ = 0;  ///< awake links whose elements the passes leave (deferred)
  // elements_ holds the awake links first (in the domain's order) and the sleepers after them, so
  // the loops of the iterations stop at awake_ and never touch a sleeper.
  std::size_t awake_ = 0;
  std::span<ElementScatter> awakeLinks() noexcept { return {elements_.data(), awake_}; }
  std::span<const ElementScatter> awakeLinks() const noexcept { return {elements_.data(), awake_}; }
  int threads_ = 1;
  // The awake elements' lists, one per thread (WorkUnits), from the elements' material updates.
  WorkUnits units_;
  long unitsFormedAt_ = -1;  ///< updateCalls_ when units_ was formed; -1: to form
  /// The next item of each list in a pass, each on a cache line of its own: a thread done with
  /// its own list takes the rest of the others' (formUnits sizes them).
  struct alignas(64) ListCursor {
    std::atomic<int> next{0};
  };
  std::unique_ptr<ListCursor[]> cursors_;
  int cursorCount_ = 0;                 ///< cursors_'s length (kept when the lists shrink)
  long updateCalls_ = 0;                ///< updateElements calls since the last build
  std::vector<long> materialsAtBuild_;  ///< each element's material update count at the build
  std::vector<double> costs_;           ///< work buffer of formUnits
  /// Forms units_ from the elements' material updates per update since the build.
  void formUnits();
  /// Whether every node's trial displacement is the one of the last updateElements, bit for bit
  /// (no after a build); keeps the present ones for the next call.
  bool nodesUnmovedSinceLastUpdate();
  std::vector<double> updatedDisp_;    ///< every node dof's displacement at the last updateElements
  bool updatedDispKnown_ = false;      ///< updatedDisp_ holds them (an update since the build)
  bool anyScalesSteps_ = false;        // some element may ask Newton for a longer step
  std::vector<Status> elementStatus_;  // per element, of the last updateElements
  std::map<int, Eigen::VectorXd> influence_;  // M r per excitation dof, formed once per build
  const Eigen::VectorXd& influence(int dof);
};

}  // namespace dabs::analysis
