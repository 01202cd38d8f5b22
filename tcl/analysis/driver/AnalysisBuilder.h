// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "tcl/analysis/model/AnalysisModel.h"
#include "tcl/analysis/driver/ContactStepping.h"
#include "tcl/analysis/driver/ThreadChoice.h"
#include "tcl/analysis/algorithms/ConvergenceTest.h"
#include "tcl/analysis/system/EigenSolver.h"
#include "tcl/analysis/integrators/Integrator.h"
#include "tcl/analysis/system/LinearSystem.h"
#include "tcl/analysis/algorithms/SolutionAlgorithm.h"
#include "tcl/analysis/driver/StepObserver.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {

/// Counters of what an analysis did, for benchmarks and reports.
struct AnalysisStatistics {
  long steps = 0;            ///< committed steps (sub-steps counted individually)
  long failedSteps = 0;      ///< steps that failed at full size
  long subSteppedSteps = 0;  ///< steps that were recovered by sub-stepping
  long iterations = 0;       ///< algorithm iterations
  long factorizations = 0;   ///< numeric factorisations
  long keptPivots = 0;       ///< of them, sparse LU ones that kept the previous pivots
  long equations = 0;        ///< equations of the last committed step (free dofs after constraints)
  long elementUpdates = 0;   ///< element state determinations
  long materialUpdates = 0;  ///< section material (fiber) state determinations
  long failedBearings = 0;   ///< bearings that reached their failure shear strain (their
                             ///< StepObserver counts them)
  long buckledBearings = 0;  ///< bearings whose axial compression reached their critical load
                             ///< (yoshidaBearing -vertical kumar; the same StepObserver)
  long contactSteps = 0;     ///< steps shortened by contact stepping (shorter than analyze's dt)
  long patternChanges = 0;   ///< matrix patterns rebuilt as contact pairs woke or went to sleep
  long redoneSteps = 0;      ///< steps redone because a sleeping contact pair would carry force
  long farTests = 0;         ///< far tests of sleeping contact pairs (one per pair and check)
};

/// Code `analyze` returns when a bearing with `-afterFailure stop` reached its failure strain: the
/// step in which it did is committed and recorded, and the analysis stops there (the bearing's
/// StepObserver returns it).
inline constexpr int kBearingFailureStop = -5;

/// The analysis strategy of one interpreter (style.md section 4: one per Runtime, no globals):
/// constraint handler, numberer, system, test, algorithm, integrator and the analysis type, and the
/// step loop that uses them (OpenSees/OpenSees:SRC/analysis/analysis/DirectIntegrationAnalysis.cpp
/// and StaticAnalysis.cpp). Components may be replaced between `analyze` calls; the equations are
/// renumbered whenever the domain changed.
class AnalysisBuilder {
 public:
  enum class Kind { None, Static, Transient };

  explicit AnalysisBuilder(domain::Domain& domain);
  ~AnalysisBuilder();

  void setConstraints(ConstraintKind kind, double alphaSP = 0.0, double alphaMP = 0.0);
  void setNumberer(NumbererKind kind);
  void setSystem(SolverKind kind);
  void setTest(std::unique_ptr<ConvergenceTest> test);
  void setAlgorithm(std::unique_ptr<SolutionAlgorithm> algorithm);
  void setIntegrator(std::unique_ptr<Integrator> integrator);
  /// Selects the analysis type and the integrator of that type (a default when none was given).
  void setAnalysis(Kind kind, int numSubLevels = 0, int numSubSteps = 10);
  Kind kind() const noexcept { return kind_; }

  /// Runs n steps of size dt (ignored by static integrators). Returns 0 or a negative status code
  /// of the first step that failed (even after sub-stepping); the model stays at the last
  /// converged step. Throws InputError when the analysis cannot start (no analysis, no model).
  int analyze(int numSteps, double dt);
  /// Lowest eigenpairs (with `largest`, the highest finite ones, by the dense solver); stores
  /// eigenvalues in the domain and eigenvectors in the nodes.
  EigenResult eigen(int numModes, bool dense, bool largest = false);
  /// The convergence test in use (null before any analysis), for `testIter`.
  const ConvergenceTest* test() const noexcept { return test_.get(); }
  /// True once `constraints` was given (OpenSees' eigen picks Transformation when it was not).
  bool constraintsGiven() const noexcept { return constraintsGiven_; }

  /// Forgets every component (wipeAnalysis); the domain is untouched.
  void wipe();
  /// Forces renumbering at the next analyze (after wipe, reset, domain changes).
  void invalidate() noexcept { model_.reset(); }

  /// Event-located contact stepping of transient analyses (the `contactStepping` command): each
  /// of analyze's steps is then made of steps of the lengths ContactStepping chooses; nullopt
  /// turns it off. Forgotten by wipe().
  void setContactStepping(const std::optional<ContactSteppingParams>& params);
  const ContactStepping* contactStepping() const noexcept { return contactStepping_.get(); }
  /// Called after every step of a transient analysis (contact stepping's steps each; a failed step
  /// recovered by sub-stepping once, after its sub-steps); a non-zero
  /// return stops the analysis with that code. Thrown exceptions leave analyze.
  std::function<int()> afterStep;
  /// Adds an observer called after every committed step (StepObserver::afterCommit), after those
  /// added before it. Observers outlive wipe(): they belong with the model's elements, which
  /// wipeAnalysis keeps.
  StepObserver& addStepObserver(std::unique_ptr<StepObserver> observer);
  /// Called after each output step of `analyze` with the steps done and asked for (progress
  /// reports; nothing it does changes the analysis).
  std::function<void(int done, int total)> progress;

  const AnalysisStatistics& statistics() const noexcept { return stats_; }
  /// Threads for element state determination (`threads n`; 0: chosen by measurement,
  /// ThreadChoice, the default); results do not depend on it.
  void setThreads(int threads) {
    threads_ = threads;
    threadChoice_.reset(model_ ? model_->awakeElements() : 2);
    if (model_) model_->setThreads(threadsForNextStep());
  }
  /// The count asked for: n, or 0 for the automatic choice.
  int threadsAsked() const noexcept { return threads_; }
  /// The count in force: the one asked for, or the automatic choice's (ThreadChoice::inForce).
  int threads() const noexcept { return threads_ > 0 ? threads_ : threadChoice_.inForce(); }
  /// The automatic choice (its decision, for reports).
  const ThreadChoice& threadChoice() const noexcept { return threadChoice_; }
  /// Where convergence-test output goes.
  std::function<void(const std::string&)> log;
  /// Called by `analyze` once its model is built, before the steps (the interpreter asks there
  /// for huge pages on what the model's building added to the heap: HugePageHeap).
  std::function<void()> modelBuilt;

 private:
  /// Factorisations of the solvers so far, and of them those that kept the previous pivots.
  struct FactorCounts {
    long all = 0, kept = 0;
  };
  int threads_ = 0;
  ThreadChoice threadChoice_{AnalysisModel::availableThreads()};
  /// The count the next step runs on (during a trial of the automatic choice, the trial's).
  int threadsForNextStep() const noexcept { return threads_ > 0 ? threads_ : threadChoice_.next(); }
  void ensureModel();
  void refreshModalDamping();
  [[nodiscard]] Status analyzeStep(double dt);
  [[nodiscard]] Status analyzeSubLevel(int level, double dt);
  /// One step of analyze (sub-stepped on failure), with the checks that follow it; 0 or the code
  /// analyze returns.
  int advance(double dt, const FactorCounts& factorizationsBefore);
  /// New matrix pattern after contact pairs woke or went to sleep
  /// (AnalysisModel::applySleepChanges).
  void rebuildPattern();
  /// Factorisations of this model's systems, across pattern changes.
  FactorCounts factorizationsSoFar() const;
  /// Adds the factorisations since `before` to the statistics.
  void addFactorizations(const FactorCounts& before);
  /// Calls every step observer after a committed step; 0 or the first non-zero code one returned
  /// (every observer is called, so each notes the step).
  int notifyObservers();

  domain::Domain& domain_;
  ConstraintKind constraints_ = ConstraintKind::Plain;
  bool constraintsGiven_ = false;
  double alphaSP_ = 0.0, alphaMP_ = 0.0;
  NumbererKind numberer_ = NumbererKind::RCM;
  SolverKind solver_ = SolverKind::SparseLU;
  std::unique_ptr<ConvergenceTest> test_;
  std::unique_ptr<SolutionAlgorithm> algorithm_;
  // OpenSees keeps a static and a transient integrator; `analysis` picks one.
  std::unique_ptr<Integrator> staticIntegrator_;
  std::unique_ptr<Integrator> transientIntegrator_;
  Integrator* integrator_ = nullptr;
  Kind kind_ = Kind::None;
  int numSubLevels_ = 0;
  int numSubSteps_ = 10;

  std::unique_ptr<AnalysisModel> model_;
  std::unique_ptr<LinearSystem> system_;
  bool integratorSeeded_ = false;
  AnalysisStatistics stats_;
  std::unique_ptr<ContactStepping> contactStepping_;
  bool inAfterStep_ = false;
  FactorCounts factorizationsCarried_;
  std::vector<std::unique_ptr<StepObserver>> observers_;
};

}  // namespace dabs::analysis
