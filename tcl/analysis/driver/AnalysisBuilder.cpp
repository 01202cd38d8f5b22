// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/AnalysisBuilder.h"

#include "tcl/analysis/driver/StopRequest.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "materials/InputError.h"
#include "tcl/analysis/integrators/GeneralizedAlpha.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"

namespace dabs::analysis {

namespace {
// Defaults OpenSees uses when a component is missing at `analysis` time.
constexpr double kDefaultTestTolerance = 1e-6;
constexpr int kDefaultTestIterations = 25;
// Up to this many equations an eigen problem is solved densely.
constexpr int kDenseEigenLimit = 600;
}  // namespace

AnalysisBuilder::AnalysisBuilder(domain::Domain& domain) : domain_(domain) {}
AnalysisBuilder::~AnalysisBuilder() = default;

void AnalysisBuilder::setConstraints(ConstraintKind kind, double alphaSP, double alphaMP) {
  constraints_ = kind;
  constraintsGiven_ = true;
  alphaSP_ = alphaSP;
  alphaMP_ = alphaMP;
  model_.reset();
}
void AnalysisBuilder::setNumberer(NumbererKind kind) {
  numberer_ = kind;
  model_.reset();
}
void AnalysisBuilder::setSystem(SolverKind kind) {
  solver_ = kind;
  model_.reset();
}
void AnalysisBuilder::setTest(std::unique_ptr<ConvergenceTest> test) { test_ = std::move(test); }
void AnalysisBuilder::setAlgorithm(std::unique_ptr<SolutionAlgorithm> algorithm) {
  algorithm_ = std::move(algorithm);
}
void AnalysisBuilder::setIntegrator(std::unique_ptr<Integrator> integrator) {
  const bool transient = integrator->transient();
  (transient ? transientIntegrator_ : staticIntegrator_) = std::move(integrator);
  if (kind_ != Kind::None && transient == (kind_ == Kind::Transient)) {
    integrator_ = transient ? transientIntegrator_.get() : staticIntegrator_.get();
    integratorSeeded_ = false;
  }
}

void AnalysisBuilder::setAnalysis(Kind kind, int numSubLevels, int numSubSteps) {
  kind_ = kind;
  numSubLevels_ = numSubLevels;
  numSubSteps_ = numSubSteps;
  if (kind == Kind::Transient && !transientIntegrator_)
    transientIntegrator_ = std::make_unique<GeneralizedAlpha>(1.0, 1.0, 0.5, 0.25);
  if (kind == Kind::Static && !staticIntegrator_)
    staticIntegrator_ = std::make_unique<LoadControl>(1.0, 1, 1.0, 1.0);
  integrator_ = kind == Kind::Transient ? transientIntegrator_.get() : staticIntegrator_.get();
  integratorSeeded_ = false;
  if (!algorithm_)
    algorithm_ = std::make_unique<NewtonRaphson>(NewtonRaphson::Tangent::Current, false);
  if (!test_)
    test_ = std::make_unique<ConvergenceTest>(ConvergenceTest::Kind::NormUnbalance,
                                              kDefaultTestTolerance, kDefaultTestIterations);
}

void AnalysisBuilder::wipe() {
  test_.reset();
  algorithm_.reset();
  staticIntegrator_.reset();
  transientIntegrator_.reset();
  integrator_ = nullptr;
  system_.reset();
  model_.reset();
  kind_ = Kind::None;
  constraints_ = ConstraintKind::Plain;
  constraintsGiven_ = false;
  numberer_ = NumbererKind::RCM;
  solver_ = SolverKind::SparseLU;
  numSubLevels_ = 0;
  numSubSteps_ = 10;
  integratorSeeded_ = false;
  stats_ = {};
  contactStepping_.reset();
  afterStep = nullptr;
}

void AnalysisBuilder::setContactStepping(const std::optional<ContactSteppingParams>& params) {
  if (!params) {
    contactStepping_.reset();
    return;
  }
  params->validate();
  contactStepping_ = std::make_unique<ContactStepping>(*params);
  contactStepping_->attach(domain_);
}

void AnalysisBuilder::ensureModel() {
  if (domain_.nodes().empty())
    throw InputError("model", "has no nodes; define the model before analysing it");
  if (!model_ || model_->stale()) {
    auto model =
        std::make_unique<AnalysisModel>(domain_, constraints_, numberer_, alphaSP_, alphaMP_);
    model->build();  // throws InputError for constraints it cannot enforce; nothing changed yet
    threadChoice_.reset(model->awakeElements());  // a new model: measured anew
    model->setThreads(threadsForNextStep());
    model_ = std::move(model);
    system_ = std::make_unique<LinearSystem>(*model_, solver_);
    system_->patternChanged();
    integratorSeeded_ = false;
    refreshModalDamping();
    if (contactStepping_) contactStepping_->attach(domain_);  // the pairs of the new model
  }
  if (integrator_ && !integratorSeeded_) {
    model_->applyLoad(domain_.committedTime());
    integrator_->domainChanged(*system_);
    integratorSeeded_ = true;
  }
}

void AnalysisBuilder::refreshModalDamping() {
  const auto& zeta = domain_.modalDamping;
  if (zeta.empty() || domain_.eigenvalues.empty()) return;
  const int modes = static_cast<int>(domain_.eigenvalues.size());
  const int neq = model_->numEquations();
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(neq, modes);
  for (const auto& [tag, node] : domain_.nodes()) {
    if (node.eigenvectors.cols() != modes) continue;
    for (int d = 0; d < node.ndf(); ++d) {
      const int eq = model_->equationOf(tag, d);
      if (eq >= 0) phi.row(eq) = node.eigenvectors.row(d);
    }
  }
  const Eigen::SparseMatrix<double> M = model_->formMass();
  Eigen::VectorXd coef(modes);
  for (int i = 0; i < modes; ++i) {
    const double lambda = domain_.eigenvalues[static_cast<std::size_t>(i)];
    const double z = zeta.size() == 1 ? zeta[0]
                                      : zeta[static_cast<std::size_t>(std::min<std::size_t>(
                                            static_cast<std::size_t>(i), zeta.size() - 1))];
    coef(i) = lambda > 0.0 ? 2.0 * z * std::sqrt(lambda) : 0.0;
  }
  model_->setModalDamping(M * phi, coef);
}

Status AnalysisBuilder::analyzeStep(double dt) {
  // Every step of the automatic choice is recorded: a choice is measured again after a while.
  const bool choosing = threads_ == 0 && !threadChoice_.fixed();
  const auto start =
      choosing ? std::chrono::steady_clock::now() : std::chrono::steady_clock::time_point{};
  if (choosing) model_->setThreads(threadChoice_.next());
  Status s = integrator_->newStep(*system_, dt);
  if (ok(s)) s = algorithm_->solveCurrentStep(*system_, *integrator_, test_.get());
  stats_.iterations += algorithm_->iterations();
  if (choosing && ok(s)) {
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    threadChoice_.record(took.count(), algorithm_->iterations());
    model_->setThreads(threadsForNextStep());
  }
  // Sleeping contact pairs are checked once the step converged: one that would carry force in
  // the converged state is woken and the step is redone with it.
  auto sleep = AnalysisModel::SleepCheck::Unchanged;
  if (ok(s)) sleep = model_->checkSleepingPairs();
  if (sleep == AnalysisModel::SleepCheck::RedoStep) {
    domain_.revertToLastCommit();
    integrator_->revertToLastStep();
    model_->applyLoad(domain_.committedTime());
    rebuildPattern();
    ++stats_.redoneSteps;
    return analyzeStep(dt);
  }
  if (ok(s)) s = integrator_->commit(*system_);
  if (ok(s) && sleep == AnalysisModel::SleepCheck::PatternChange) rebuildPattern();
  if (!ok(s)) {
    domain_.revertToLastCommit();
    integrator_->revertToLastStep();
    model_->applyLoad(domain_.committedTime());
    return s;
  }
  ++stats_.steps;
  stats_.equations = model_->numEquations();
  return Status::Ok;
}

Status AnalysisBuilder::analyzeSubLevel(int level, double dt) {
  // OpenSees DirectIntegrationAnalysis::analyzeSubLevel: the failed step is retried as
  // numSubSteps smaller steps, each of which may itself be split, down to numSubLevels levels.
  const double subDt = dt / numSubSteps_;
  for (int i = 0; i < numSubSteps_; ++i) {
    Status s = analyzeStep(subDt);
    if (!ok(s)) {
      if (level >= numSubLevels_) return s;
      s = analyzeSubLevel(level + 1, subDt);
      if (!ok(s)) return s;
    }
  }
  return Status::Ok;
}

int AnalysisBuilder::analyze(int numSteps, double dt) {
  if (inAfterStep_)
    throw InputError("analyze", "cannot be called from the script run after each step");
  if (kind_ == Kind::None)
    throw InputError("analysis",
                     "is not defined; give `analysis Static` or `analysis Transient` first");
  if (kind_ == Kind::Transient && !(dt > 0.0))
    throw InputError("dt", "must be positive for a transient analysis");
  if (algorithm_->needsTest() && !test_) throw InputError("test", "is not defined");
  ensureModel();
  if (modelBuilt) modelBuilt();
  const FactorCounts factorizationsBefore = factorizationsSoFar();
  const long elementUpdatesBefore = model_->elementUpdates();
  const long farTestsBefore = model_->farTests();
  const long materialUpdatesBefore = domain_.materialUpdates();
  int result = 0;
  struct StepLoopGuard {
    StepLoopGuard() { StopRequest::stepLoopRunning = 1; }
    ~StepLoopGuard() { StopRequest::stepLoopRunning = 0; }
  } guard;
  const bool stepping = kind_ == Kind::Transient && contactStepping_ != nullptr;
  // Sleeping pairs' tests may be deferred through the steps unless something reads them at every
  // step: contact stepping reads every gap, and the script after each step may read anything
  // (recorders name theirs). At the end every pair's state is as the check of every step leaves
  // it, so one step (`analyze 1` in a loop) gains nothing from deferring and checks every pair.
  // With HHT the check of every step forms the gaps at the weighted displacements, which are not
  // those a deferred pair's gap is formed at (the committed ones): no deferral.
  model_->beginSteps(stepping || (afterStep && kind_ == Kind::Transient) || numSteps < 2 ||
                     !integrator_->checksCommittedDisplacements());
  struct EndSteps {
    AnalysisModel& model;
    ~EndSteps() { model.endSteps(); }
  } endSteps{*model_};
  const double t0 = domain_.committedTime();
  const long contactStepsBefore = stepping ? contactStepping_->contactSteps() : 0;
  for (int step = 0; step < numSteps && StopRequest::signal == 0 && result == 0; ++step) {
    if (progress && step > 0) progress(step, numSteps);
    if (!stepping) {
      result = advance(dt, factorizationsBefore);
      continue;
    }
    // Steps of the lengths contact stepping chooses up to the end of this output step (times
    // from the start of analyze, so round-off does not accumulate from step to step).
    const double tEnd = t0 + (step + 1) * dt;
    while (result == 0 && StopRequest::signal == 0) {
      const double remaining = tEnd - domain_.committedTime();
      if (remaining <= 1e-9 * dt) break;
      const double committedBefore = domain_.committedTime();
      result = advance(contactStepping_->nextStep(remaining, dt), factorizationsBefore);
      if (domain_.committedTime() == committedBefore) contactStepping_->stepNotTaken();
    }
  }
  if (progress) progress(result == 0 ? numSteps : -1, numSteps);  // -1: stopped early
  if (stepping) stats_.contactSteps += contactStepping_->contactSteps() - contactStepsBefore;
  addFactorizations(factorizationsBefore);
  stats_.elementUpdates += model_->elementUpdates() - elementUpdatesBefore;
  stats_.farTests += model_->farTests() - farTestsBefore;
  stats_.materialUpdates += domain_.materialUpdates() - materialUpdatesBefore;
  domain_.flushRecorders();
  return result;
}

int AnalysisBuilder::advance(double dt, const FactorCounts& factorizationsBefore) {
  Status s = analyzeStep(dt);
  if (!ok(s) && kind_ == Kind::Transient && numSubLevels_ > 0) {
    ++stats_.failedSteps;
    s = analyzeSubLevel(1, dt);
    if (ok(s)) ++stats_.subSteppedSteps;
  } else if (!ok(s)) {
    ++stats_.failedSteps;
  }
  if (!ok(s)) return code(s);
  if (const int stop = notifyObservers(); stop != 0) return stop;
  if (auto error = domain_.takeRecorderError()) {
    addFactorizations(factorizationsBefore);
    char when[64];
    std::snprintf(when, sizeof when, "%.10g", domain_.committedTime());
    throw InputError("", *error + "; the analysis stopped at time " + when +
                             " (the other recorders hold every step up to it)");
  }
  if (afterStep && kind_ == Kind::Transient) {
    struct Flag {
      bool& f;
      explicit Flag(bool& flag) : f(flag) { f = true; }
      ~Flag() { f = false; }
    } flag(inAfterStep_);
    return afterStep();
  }
  return 0;
}

void AnalysisBuilder::rebuildPattern() {
  model_->applySleepChanges();
  // the new solvers count from zero
  factorizationsCarried_.all += system_->factorizations();
  factorizationsCarried_.kept += system_->keptPivots();
  system_->patternChanged();
  ++stats_.patternChanges;
}

AnalysisBuilder::FactorCounts AnalysisBuilder::factorizationsSoFar() const {
  FactorCounts counts = factorizationsCarried_;
  if (system_) {
    counts.all += system_->factorizations();
    counts.kept += system_->keptPivots();
  }
  return counts;
}

void AnalysisBuilder::addFactorizations(const FactorCounts& before) {
  const FactorCounts now = factorizationsSoFar();
  stats_.factorizations += now.all - before.all;
  stats_.keptPivots += now.kept - before.kept;
}

StepObserver& AnalysisBuilder::addStepObserver(std::unique_ptr<StepObserver> observer) {
  observers_.push_back(std::move(observer));
  return *observers_.back();
}

int AnalysisBuilder::notifyObservers() {
  int stop = 0;
  StepContext context{stats_, log};
  for (const auto& o : observers_) {
    const int code = o->afterCommit(domain_, context);
    if (stop == 0) stop = code;
  }
  return stop;
}

EigenResult AnalysisBuilder::eigen(int numModes, bool dense, bool largest) {
  ensureModel();
  // Bring elements to the committed state so their tangents are current.
  Eigen::VectorXd U, V, A;
  model_->applyLoad(domain_.committedTime());
  model_->getResponse(U, V, A, true);
  model_->setResponse(U, V, A);
  EigenResult result;
  if (!ok(model_->updateElements())) {
    result.status = Status::Failed;
    return result;
  }
  AssemblyCoefficients c;
  const Eigen::SparseMatrix<double> K = model_->formTangent(c);
  const Eigen::SparseMatrix<double> M = model_->formMass();
  if (numModes > model_->numEquations()) {
    result.status = Status::Failed;
    return result;
  }
  result = (dense || largest || model_->numEquations() <= kDenseEigenLimit)
               ? solveEigenDense(K, M, numModes, largest)
               : solveEigenSubspace(K, M, numModes);
  if (ok(result.status)) {
    domain_.eigenvalues.assign(result.values.data(), result.values.data() + result.values.size());
    model_->setEigenvectors(result.vectors);
    refreshModalDamping();
    system_->invalidate();
  }
  return result;
}

}  // namespace dabs::analysis
