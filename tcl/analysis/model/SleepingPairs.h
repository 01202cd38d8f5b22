// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <vector>

#include "elements/FarPair.h"
#include "tcl/analysis/model/ConstraintHandler.h"
#include "tcl/analysis/model/MotionBound.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// The sleeping contact pairs of an analysis (the names are elements::FarPair's glossary). An
/// element that offers Element::farPair() (a contact pair with a search distance) and is far
/// apart "sleeps": the model leaves it out of the matrix pattern (no fill in the factorisation)
/// and out of the iterations' element updates, and this class checks it once per converged step
/// by its distance bound alone (a few flops on its nodes' displacements). A sleeper found near is
/// woken: the pattern is rebuilt before the next step, and when it would already carry force the
/// step is redone with it awake. An awake pair goes to sleep when it is beyond twice its search
/// distance (hysteresis, so that a pair hovering at the distance does not rebuild the pattern
/// step after step). Deferred tests of a face: see check().
///
/// The model (AnalysisModel) decides from wantsSleep() which pairs sleep in a new pattern, gives
/// them to build() in the domain's order, and wakes the elements check() asks it to.
class SleepingPairs {
 public:
  explicit SleepingPairs(domain::Domain& domain) : domain_(domain) {}

  /// One pair as the model built it.
  struct Pair {
    std::size_t link = 0;  ///< the model's index of the pair's element (passed to the waker)
    int tag = 0;           ///< element tag
    elements::FarPair* far = nullptr;
    const domain::Node* contactor = nullptr;
    std::array<const domain::Node*, 4> face{};  ///< target face nodes, in the element's order
    bool sleeping = false;                      ///< left out of the pattern and the iterations
    std::uint32_t domainIndex = 0;  ///< the element's position in the domain's tag order
  };
  /// Where the nodes' translations come from (their motion bound): per node dof its equation
  /// (coefficient 1) or -1, and its value as terms; the index of a node's dof 0 by node tag.
  struct DofSource {
    std::function<int(int nodeTag)> firstDof;
    std::span<const int> directEq;
    std::span<const std::vector<DofTerm>> dofTerms;
  };

  /// Whether the pair sleeps in the next pattern: as check() noted, else by its committed state.
  bool wantsSleep(const elements::FarPair& far) const;
  /// Takes the pairs of a new pattern (in the domain's order); no face's test deferred, no change
  /// noted.
  void build(std::vector<Pair> pairs, const DofSource& dofs);

  /// Outcome of check.
  enum class Check { Unchanged, PatternChange, RedoStep };
  /// Wakes the element of a pair (its model index): updates it for the trial state; returns true
  /// when it failed or carries force (the step missed it).
  using Waker = std::function<bool(std::size_t link)>;
  /// After a step converged (trial state, step dt, support values `slots`): brings sleepers'
  /// trial states up to date, notes pairs to wake or to put to sleep. RedoStep when a sleeper
  /// would carry force in this trial state.
  Check check(double dt, std::span<const SupportSlot> slots, const Waker& wake);
  /// The displacements (equation space) the trial state was formed from, what the motion of a face
  /// whose test is deferred is measured on; copied when some pair is unobserved (else unused).
  void setDisplacements(const Eigen::VectorXd& U);

  /// Start of a run of steps (analyze): which pairs are observed at every step (read by a
  /// recorder, or all of them with `observeAll`: contact stepping, a script after each step, and
  /// wherever no face's test may be deferred: a single step, an integrator that checks the pairs
  /// at weighted displacements). The others' may: see check().
  void beginSteps(bool observeAll);
  /// End of a run of steps: every deferred pair's gap formed at its nodes' committed positions,
  /// as the step-by-step check would have left it, and no test is deferred any longer.
  void endSteps();

  /// What a rebuild of the pattern carries over: the deferred faces' motion bounds and horizons.
  struct Carried {
    struct Face {
      MotionBound::Saved motion;
      double horizon = 0.0;
      std::uint32_t pairs = 0;
    };
    std::map<const elements::FarPair*, Face> faces;  // by the face's first pair
  };
  /// Before the model rebuilds its pattern with the noted changes: pairs without a change keep
  /// their state; every deferred face's pairs get their gaps (a new pattern moves no node).
  Carried beforeRebuild();
  /// After build(): a face with the same pairs, all still sleeping, bounding the motion of the
  /// same equations, has its test deferred again with its motion bound and horizon.
  void afterRebuild(const Carried& carried);

  /// Pairs sleeping in this pattern.
  long sleeping() const noexcept { return sleeping_; }
  /// Far tests of sleeping pairs made since construction (one per pair per check; a deferred
  /// face's pairs are not tested until its horizon is reached, and twice at the check where a
  /// pair of it wakes).
  long farTests() const noexcept { return farTests_; }
  /// Target faces whose test is deferred (no check, no commit of their pairs) at this moment.
  std::size_t deferredFaces() const;

 private:
  // A pair as the once-a-step test reads it (compact, so that the test does not touch the
  // element): its contactor here, its target face in the FarFace of its run.
  struct PairLink {
    std::size_t link = 0;
    const domain::Node* contactor = nullptr;
    Eigen::Vector3d X = Eigen::Vector3d::Zero();  // the contactor's reference coordinates
    double distance = 0.0;                        // search distance
    elements::FarPair* far = nullptr;
    std::uint32_t domainIndex = 0;
    bool sleeping = false;
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
    std::uint32_t first = 0, end = 0;  // its pairs: pairs_[first, end)
  };

  /// The face's slab top (FarPair::slabTop) on its nodes' trial (or committed) translations.
  static double slabTopAt(const FarFace& f, bool committed);
  /// The far test's verdict and bound on the nodes' trial (or committed) translations, without
  /// writing the pair: the height above the face's slab top `top`, and the pair's whole test
  /// (slab and bounding sphere, FarPair::isFarAt) when that does not show it far. The arithmetic
  /// of the pair's own test, so the bound is the gap the pair reports, to the bit.
  static bool sleeperBound(const PairLink& p, const FarFace& f, double top, bool committed,
                           double& bound);
  /// A deferred face's bound on how far its nodes moved since its last exact test (infinity
  /// without the displacements).
  double faceMoved(std::size_t r, std::span<const SupportSlot> slots) const;
  /// A face's test is deferred (again) with horizon `reach` (how far its nodes may move): the
  /// values of its equations and slots now, and the domain leaves its pairs alone.
  void deferFace(std::size_t r, double reach, std::span<const SupportSlot> slots);
  /// A deferred face whose horizon is reached: its pairs' exact test; true (and a new horizon)
  /// when every one is still far.
  bool retestFace(std::size_t r, std::span<const SupportSlot> slots);
  /// A face's test is no longer deferred: its pairs' gaps formed at the committed positions (as the
  /// check of every step would have committed them) and the domain commits them again.
  void endDeferral(std::size_t r);
  /// Per face the equations and slots its nodes' translations (contactors and face) are formed
  /// from (faceMotion_); no face's test deferred.
  void buildMotionBounds(const DofSource& dofs);
  /// Each pair's `observed` (observeAll_, observedTags_) and mayDefer_.
  void markObserved();

  domain::Domain& domain_;
  std::vector<PairLink> pairs_;
  std::vector<int> tags_;          // element tag of each pair
  std::vector<FarFace> farFaces_;  // runs of pairs_ by target face, in order
  long sleeping_ = 0;
  long farTests_ = 0;
  std::map<const elements::FarPair*, bool> sleepWanted_;  // pairs to wake (false) or put to sleep
  // Deferred tests (see check): per face of farFaces_ the bound on how far its nodes may move from
  // their positions at its last exact test before a pair of it could be within its search
  // distance (-infinity when its test is not deferred), and the motion of its nodes (a MotionBound
  // group per face: its four nodes and its contactors).
  std::vector<double> faceHorizon_;
  MotionBound faceMotion_;
  bool mayDefer_ = false;  // some pair is not observed
  bool observeAll_ = true;
  std::vector<int> observedTags_;  // elements read by recorders (sorted)
  // The displacements of the last trial state (setDisplacements), valid while haveU_: a copy,
  // since the vector the model was given may be gone by the check (eigen's, a replaced
  // integrator's).
  Eigen::VectorXd U_;
  bool haveU_ = false;
};

}  // namespace dabs::analysis
