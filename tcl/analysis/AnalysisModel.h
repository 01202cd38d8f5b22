// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "elements/FarPair.h"
#include "materials/Status.h"
#include "tcl/analysis/ConstraintHandler.h"
#include "tcl/analysis/DofNumberer.h"
#include "tcl/analysis/MotionWatch.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// Which stiffness the tangent uses.
enum class StiffnessKind { Current, Initial };

/// Coefficients of one assembly: A = cK K + cC C + cM M and whether inertia and damping forces
/// enter the residual (transient) or not (static).
struct AssemblyCoefficients {
  double cK = 1.0;
  double cC = 0.0;
  double cM = 0.0;
  StiffnessKind stiffness = StiffnessKind::Current;
  bool dynamic = false;
  /// True when `o` forms the same matrix (the residual flag aside).
  bool sameMatrix(const AssemblyCoefficients& o) const noexcept {
    return cK == o.cK && cC == o.cC && cM == o.cM && stiffness == o.stiffness;
  }
};

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
  /// Element updates since construction (a work count for benchmarks).
  long elementUpdates() const noexcept { return elementUpdates_; }
  /// Threads that update elements (1: the calling thread alone). Results do not depend on it.
  void setThreads(int threads) noexcept { threads_ = threads < 1 ? 1 : threads; }

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
  void setModalDamping(const Eigen::MatrixXd& Mphi, const Eigen::VectorXd& coefficients);
  bool hasModalDamping() const noexcept { return modalCoefficients_.size() > 0; }
  const Eigen::MatrixXd& modalBasis() const noexcept { return modalMphi_; }
  const Eigen::VectorXd& modalCoefficients() const noexcept { return modalCoefficients_; }

  domain::Domain& domain() noexcept { return domain_; }

  // --- sleeping contact pairs -------------------------------------------------------------
  // An element that offers Element::farPair() (a contact pair with a search distance; the names
  // are elements::FarPair's glossary) and is far apart "sleeps": it is left out of the
  // matrix pattern (no fill in the factorisation) and out of the iterations' element updates, and
  // is checked once per converged step by its distance bound alone (a few flops on its nodes'
  // displacements). A sleeper found near is woken: the pattern is rebuilt before the next step,
  // and when it would already carry force the step is redone with it awake. An awake pair falls
  // asleep when it is beyond twice its search distance (hysteresis, so that a pair hovering at
  // the distance does not rebuild the pattern step after step).
  /// Outcome of checkSleepingPairs.
  enum class SleepCheck { Unchanged, PatternChange, RedoStep };
  /// After a step converged (trial state): brings sleepers' trial states up to date, notes pairs
  /// to wake or to put to sleep. RedoStep when a sleeper would carry force in this trial state.
  SleepCheck checkSleepingPairs();
  /// Rebuilds the pattern and scatter with the noted pairs woken or asleep (equations unchanged);
  /// the linear system must then analyse the new pattern.
  void applySleepChanges();
  long sleepingPairs() const noexcept { return sleeping_; }
  /// Far tests of sleeping pairs made since construction (one per pair per check; a resting
  /// face's pairs are not tested until its horizon is reached, and twice at the check where a
  /// pair of it wakes).
  long farTests() const noexcept { return farTests_; }
  /// Start of a run of steps (analyze): which pairs are observed at every step (read by a
  /// recorder, or all of them with `observeAll`: contact stepping, a script after each step, and
  /// wherever no face may rest: a single step, an integrator that checks the pairs at weighted
  /// displacements). The others may rest: see checkSleepingPairs.
  void beginSteps(bool observeAll);
  /// End of a run of steps: every resting pair's gap formed at its nodes' committed positions,
  /// as the step-by-step check would have left it, and no pair rests any longer.
  void endSteps();
  /// Target faces whose pairs rest (left alone: no check, no commit) at this moment.
  std::size_t restingFaces() const;

 private:
  using Term = DofTerm;
  using Slot = SupportSlot;
  struct VecEntry {
    int local;
    int eq;
    double coef;
  };
  struct MatEntry {
    int local;  // offset j*n+i of (row i, column j) in the column-major element matrix
    int value;  // index into A_.valuePtr()
    double coef;
  };
  struct ElementLink {
    elements::Element* element;
    std::vector<domain::Node*> nodes;
    std::vector<VecEntry> vec;
    std::vector<MatEntry> mat;  // empty when matSlots scatters
    // With `direct` (every dof one equation or none, coefficient 1): `mat` without its
    // coefficients, half the bytes that the assembly of every iteration reads for every
    // nonlinear element.
    std::vector<std::pair<int, int>> matSlots;  // (local, value)
    std::vector<std::pair<int, int>> rowCol;    // (row, column) of each mat entry while building
    domain::RayleighFactors rayleigh;
    bool rayleighOn = false;
    Eigen::VectorXd u, v, a;  // gather buffers
    // Per local dof its equation (coefficient 1) or -1 when prescribed; empty when some dof is a
    // combination (constraints), and then `vec` scatters.
    std::vector<int> direct;
    // Whether updates gather velocities and accelerations: a linear element without a damping
    // tangent has a force that depends on its displacements alone, and the residual needs its
    // rates only when the elements form their own inertia and damping forces.
    bool rates = true;
    mutable Eigen::VectorXd force;  // residual work buffer
    Eigen::MatrixXd work;           // tangent work buffer
    // A nonlinear element's constant matrix terms (mass, initial-stiffness Rayleigh damping) are
    // in the tangent's constant part: was it active when that part was formed?
    bool constantActive = false;
    // An element that may turn inactive (Element::mayTurnInactive) with mass or Rayleigh damping:
    // left out of massGlobal_ and dampingGlobal_; the residual adds its inertia and damping
    // forces itself while it is active.
    bool ownDynamics = false;
    elements::FarPair* far = nullptr;  // a contact pair that may sleep (Element::farPair)
    bool asleep = false;               // left out of the pattern and the iterations
    bool switching = false;  // the element's force switches between laws (Element::HeldStatus)
  };
  // The pairs that may sleep, in the domain's order, with what a sleeper's once-a-step test reads
  // (kept here, compact, so that the test does not touch the element or its link): its contactor
  // here, its target face in the FarFace of its run.
  struct PairLink {
    std::size_t link = 0;  // index in elements_
    const domain::Node* contactor = nullptr;
    Eigen::Vector3d X = Eigen::Vector3d::Zero();  // the contactor's reference coordinates
    double distance = 0.0;                        // search distance
    elements::FarPair* far = nullptr;
    std::uint32_t domainIndex = 0;  // the element's position in the domain's tag order
    bool asleep = false;
    bool observed = false;  // read at every step (beginSteps)
  };
  // A run of consecutive pairs (in the domain's order) against one target face: the same four
  // nodes in the same order, reference coordinates and outward normal (`pounding` defines a girder
  // end's contactors against the other end's face one after the other). The far test forms the
  // face's slab top once per run (a broad phase per face) and each contactor's height above it.
  struct FarFace {
    std::array<const domain::Node*, 4> nodes{};
    std::array<Eigen::Vector3d, 4> X{};
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    std::uint32_t first = 0, end = 0;  // its pairs: pairLinks_[first, end)
  };
  struct NodeLink {
    domain::Node* node;
    int firstDof;                             // index of the node's dof 0 in dofTerms
    std::vector<MatEntry> mass;               // nodal mass scatter (local = j*ndf+i)
    std::vector<std::pair<int, int>> rowCol;  // (row, column) of each mass entry while building
    std::vector<VecEntry> vec;
    double alphaM = 0.0;
  };

  void numberEquations();
  /// Whether the pair of link l sleeps in the next pattern (sleepWanted_, else its committed
  /// state).
  bool wantsSleep(const ElementLink& l) const;
  /// Gather and work buffers of a link for n dofs (once).
  static void allocateBuffers(ElementLink& l, int n);
  /// The face's slab top (FarPair::slabTop) on its nodes' trial (or committed)
  /// translations.
  static double slabTopAt(const FarFace& f, bool committed);
  /// The far test's verdict and bound on the nodes' trial (or committed) translations, without
  /// writing the pair: the height above the face's slab top `top`, and the pair's whole test
  /// (slab and bounding sphere, FarPair::isFarAt) when that does not show it far. The arithmetic of
  /// the pair's own test, so the bound is the gap the pair reports, to the bit.
  static bool sleeperBound(const PairLink& p, const FarFace& f, double top, bool committed,
                           double& bound);
  /// A resting face's bound on how far its nodes moved since its last exact test (infinity
  /// without the displacements).
  double faceMoved(std::size_t r) const;
  /// A face starts (or goes on) resting with horizon `reach` (how far its nodes may move): the
  /// values of its equations and slots now, and the domain leaves its pairs alone.
  void startRest(std::size_t r, double reach);
  /// A resting face whose horizon is reached: its pairs' exact test; true (and a new horizon)
  /// when every one is still far.
  bool rerestFace(std::size_t r);
  /// A face stops resting: its pairs' gaps formed at the committed positions (as the check of
  /// every step would have committed them) and the domain commits them again.
  void wakeFace(std::size_t r);
  /// Per face the equations and slots its nodes' translations (contactors and face) are formed
  /// from (faceMotion_); no face rests.
  void buildWatch();
  /// Each pair's `observed` (observeAll_, observedTags_) and mayRest_.
  void markObserved();
  void buildScatter();
  void buildConstantDynamics();
  [[nodiscard]] Status updateElement(ElementLink& l, double dt) const;
  /// Adds an element matrix (numDof x numDof) to the matrix values through the scatter indices.
  void addElementMatrix(double* values, const ElementLink& l, const Eigen::MatrixXd& m) const;
  /// Adds cK K + cC C + cM M of one element to the matrix values.
  /// Which of an element's matrix terms addElementTangent adds: all, those that never change
  /// (mass and initial-stiffness damping), or the others.
  enum class TangentTerms { All, Constant, Varying };
  void addElementTangent(double* values, ElementLink& l, const AssemblyCoefficients& c,
                         TangentTerms terms = TangentTerms::All) const;
  /// B -= the element force f (local dofs) through the element's equations.
  static void subtractForce(const ElementLink& l, const Eigen::Ref<const Eigen::VectorXd>& f,
                            Eigen::VectorXd& B);
  double termValue(const std::vector<Term>& terms, const Eigen::VectorXd& x, int which) const;

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
  std::vector<NodeLink> nodes_;
  std::vector<ElementLink> elements_;
  std::vector<PenaltyRow> penalties_;
  std::map<int, int> nodeIndex_;                      // node tag -> index in nodes_
  std::vector<std::pair<domain::Node*, int>> eqDof_;  // node and dof of each equation
  Eigen::SparseMatrix<double> A_;
  Eigen::VectorXd P_;
  // Constant parts of the dynamic residual, M a + C v, assembled once per build: masses, alphaM and
  // betaK0 terms, and the betaK/betaKc terms of linear elements. Only used when no support moves
  // with an imposed velocity (otherwise every element forms its own inertia and damping forces).
  Eigen::SparseMatrix<double> massGlobal_, dampingGlobal_;
  std::vector<char> rayleighLeft_;  // per element: Rayleigh stiffness terms left to the element
  bool imposedMotion_ = false;
  // Tangent values of what never changes (linear elements, nodal masses, penalty rows) for the
  // coefficients constantFor_; reset when the pattern is built.
  std::vector<double> constantValues_;
  std::optional<AssemblyCoefficients> constantFor_;
  long elementUpdates_ = 0;
  long farTests_ = 0;
  std::map<const elements::Element*, bool> sleepWanted_;  // pairs to wake (false) or put to sleep
  long sleeping_ = 0;
  std::vector<PairLink> pairLinks_;
  std::vector<FarFace> farFaces_;  // runs of pairLinks_ by target face, in order
  // Resting faces (see checkSleepingPairs): per face of farFaces_ the bound on how far its
  // nodes may move from their positions at its last exact test before a pair of it could be
  // within its search distance (-infinity when it does not rest), and the motion of its nodes
  // (a MotionWatch group per face: its four nodes and its contactors).
  std::vector<double> faceHorizon_;
  MotionWatch faceMotion_;
  bool mayRest_ = false;  // some pair is not observed
  bool observeAll_ = true;
  std::vector<int> observedTags_;               // elements read by recorders (sorted)
  const Eigen::VectorXd* responseU_ = nullptr;  // the displacements of the last setResponse
  // elements_ holds the awake links first (in the domain's order) and the sleepers after them, so
  // the loops of the iterations stop at awake_ and never touch a sleeper.
  std::size_t awake_ = 0;
  std::span<ElementLink> awakeLinks() noexcept { return {elements_.data(), awake_}; }
  std::span<const ElementLink> awakeLinks() const noexcept { return {elements_.data(), awake_}; }
  int threads_ = 1;
  std::vector<Status> elementStatus_;  // per element, of the last updateElements
  mutable Eigen::VectorXd eqVel_, eqAcc_;
  std::map<int, Eigen::VectorXd> influence_;  // M r per excitation dof, formed once per build
  const Eigen::VectorXd& influence(int dof);
  Eigen::MatrixXd modalMphi_;
  Eigen::VectorXd modalCoefficients_;
};

}  // namespace dabs::analysis
