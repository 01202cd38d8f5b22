// SPDX-License-Identifier: MIT
// Analysis commands: analysis, analyze, eigen, wipe, wipeAnalysis, reset, initialize, testIter,
// threads, analysisStatistics; the strategy commands (constraints, numberer, system, test,
// algorithm, integrator) are in StrategyCommands.cpp and listed here.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/driver/StopRequest.h"
#include "tcl/analysis/driver/ThreadChoice.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/SignalExit.h"
#include "tcl/commands/StrategyCommands.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

using analysis::AnalysisBuilder;

using strategy::KindEntry;
using strategy::lookUp;
using strategy::warn;

constexpr KindEntry<AnalysisBuilder::Kind> kAnalyses[] = {
    {"Static", AnalysisBuilder::Kind::Static},
    {"Transient", AnalysisBuilder::Kind::Transient},
    {"VariableTransient", AnalysisBuilder::Kind::Transient},
};

void analysisCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto kind = lookUp<KindEntry<AnalysisBuilder::Kind>>(a, kAnalyses, type).kind;
  const int levels = a.option("-numSubLevels", 0);
  const int steps = a.option("-numSubSteps", 10);
  a.finish();
  if (levels < 0) a.failArgument("-numSubLevels", "must not be negative");
  if (steps < 2) a.failArgument("-numSubSteps", "must be at least 2");
  rt.analysis->setAnalysis(kind, levels, steps);
}

/// `analyze ... -progress`: one line on stderr that the steps rewrite (in a terminal; elsewhere a
/// line at most every second), with the steps done, the analysis time, the time elapsed and an
/// estimate of the time left; the last line stays. Nothing goes to recorders or results.
class AnalyzeProgress {
 public:
  AnalyzeProgress(AnalysisBuilder& analysis, const domain::Domain& domain)
      : analysis_(analysis), domain_(domain), terminal_(isatty(STDERR_FILENO) != 0) {
    analysis_.progress = [this](int done, int total) { report(done, total); };
  }
  ~AnalyzeProgress() { analysis_.progress = nullptr; }
  AnalyzeProgress(const AnalyzeProgress&) = delete;
  AnalyzeProgress& operator=(const AnalyzeProgress&) = delete;

 private:
  void report(int done, int total) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point now = Clock::now();
    const bool last = done == total || done < 0;
    if (!last && now - lastShown_ <
                     (terminal_ ? std::chrono::milliseconds(250) : std::chrono::milliseconds(1000)))
      return;
    lastShown_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    char line[200];
    if (done < 0)
      std::snprintf(line, sizeof line, "analyze: stopped at t = %.6g after %.1f s",
                    domain_.committedTime(), elapsed);
    else
      std::snprintf(line, sizeof line,
                    "analyze: %d/%d steps (%d %%), t = %.6g, %.1f s elapsed, about %.1f s left",
                    done, total, total > 0 ? 100 * done / total : 100, domain_.committedTime(),
                    elapsed, done > 0 ? elapsed / done * (total - done) : 0.0);
    std::string text = terminal_ ? std::string("\r") + line + "\x1b[K" : std::string(line) + "\n";
    if (terminal_ && last) text += "\n";
    warn(text);
    if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr) Tcl_Flush(err);
  }

  AnalysisBuilder& analysis_;
  const domain::Domain& domain_;
  bool terminal_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastShown_{};
};

void analyzeCmd(Runtime& rt, ArgReader& a) {
  const int n = a.integer("numIncr");
  const double dt = a.optionalReal("dt").value_or(0.0);
  const bool showProgress = a.flag("-progress");
  a.finish();
  if (n < 0) a.failArgument("numIncr", "must not be negative");
  if (rt.analysis->kind() == AnalysisBuilder::Kind::Transient && !(dt > 0.0))
    a.failArgument("dt", "must be positive: a transient analysis needs a time step");
  std::optional<AnalyzeProgress> progress;
  if (showProgress) progress.emplace(*rt.analysis, rt.domain);
  const int result = rt.analysis->analyze(n, dt);
  if (const int signal = analysis::StopRequest::signal) exitOnSignal(rt, signal);
  setResult(rt, result);
}

// `eigen ?options? numModes` (OpenSees SRC/tcl/commands.cpp eigenAnalysis): solver options are
// accepted, as Eigen's solvers replace them; unknown options are reported on stderr and ignored,
// as OpenSees does. With no analysis yet, OpenSees creates a transient one (Newmark 1/2 1/4, the
// Transformation handler unless `constraints` was given) and keeps it for later `analyze` calls.
void eigenCmd(Runtime& rt, ArgReader& a) {
  std::vector<std::string> options;
  while (a.hasMore()) options.push_back(a.word("option"));
  if (options.empty()) (void)a.integer("numModes");  // reports the missing argument
  bool dense = false, largest = false, standard = false;
  for (std::size_t i = 0; i + 1 < options.size(); ++i) {
    std::string o = options[i];
    if (o.size() > 1 && o[0] == '-') o.erase(0, 1);
    if (o.size() > 5 && o.ends_with("Eigen")) o.resize(o.size() - 5);
    if (o == "fullGenLapack")
      dense = true;
    else if (o == "findLargest")
      largest = true;
    else if (o == "standard")
      standard = true;
    else if (o == "frequency" || o == "generalized" || o == "genBandArpack" ||
             o == "symmBandLapack")
      continue;
    else
      warn("eigen - unknown option specified " + options[i] + "\n");
  }
  int n = 0;
  if (Tcl_GetInt(nullptr, options.back().c_str(), &n) != TCL_OK)
    a.fail(a.lastPosition(), "numModes", "expected an integer, got \"" + options.back() + "\"");
  if (n < 1)
    a.fail(a.lastPosition(), "numModes", "must be at least 1, got \"" + options.back() + "\"");
  if (standard) {
    // OpenSees' eigen solvers other than the banded one (which dabs does not have) solve only the
    // generalized problem: the step fails with a warning and the result is empty.
    warn("eigen - the standard problem is not solved; no eigenvalues\n");
    return;
  }
  if (rt.analysis->kind() == AnalysisBuilder::Kind::None) {
    if (!rt.analysis->constraintsGiven())
      rt.analysis->setConstraints(analysis::ConstraintKind::Transformation);
    rt.analysis->setAnalysis(AnalysisBuilder::Kind::Transient);
  }
  const auto result = rt.analysis->eigen(n, dense, largest);
  if (!ok(result.status)) {
    setResult(rt, code(result.status));
    return;
  }
  setResult(rt, result.values);
  rt.domain.flushRecorders();
}

void wipeCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  rt.analysis->wipe();
  rt.domain.clear();
  rt.builder.clear();
  rt.testMaterial.reset();
  rt.currentPattern = -1;
}

// `initialize`: OpenSees sets up its analysis and domain here; dabs initialises elements when they
// are added and builds the equations at the first `analyze` or `eigen`, so nothing is left to do.
void initializeCmd(Runtime& /*rt*/, ArgReader& a) { a.finish(); }

void wipeAnalysisCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  rt.analysis->wipe();
}

void resetCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  rt.domain.revertToStart();
  rt.analysis->invalidate();
}

// `testIter`: iterations the convergence test counted in the last step (0 before any analysis).
void testIterCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  const analysis::ConvergenceTest* test = rt.analysis->test();
  setResult(rt, test != nullptr ? test->iterations() : 0);
}

// DABS extension: `threads ?n|auto?` sets how many threads update the elements (1 to 256, or
// auto: measured on the model's first steps and again during the run, ThreadChoice; results are
// bit-identical at any count) and returns the count in force (auto's last decision; before its
// first, the next step's).
void threadsCmd(Runtime& rt, ArgReader& a) {
  if (a.hasMore()) {
    const auto n = analysis::ThreadChoice::parseCount(a.word("n"));
    if (!n)
      a.failArgument(
          "n", "must be 1 to " + std::to_string(analysis::ThreadChoice::kMaxThreads) + " or auto");
    a.finish();
    rt.analysis->setThreads(*n);  // 0: auto
  }
  setResult(rt, std::to_string(rt.analysis->threads()));
}

// DABS extension: what the analyses since the last wipe did, as a Tcl dict.
void analysisStatisticsCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  const auto& s = rt.analysis->statistics();
  const std::string text =
      "steps " + std::to_string(s.steps) + " failedSteps " + std::to_string(s.failedSteps) +
      " subSteppedSteps " + std::to_string(s.subSteppedSteps) + " iterations " +
      std::to_string(s.iterations) + " factorizations " + std::to_string(s.factorizations) +
      " keptPivots " + std::to_string(s.keptPivots) + " equations " + std::to_string(s.equations) +
      " elementUpdates " + std::to_string(s.elementUpdates) + " materialUpdates " +
      std::to_string(s.materialUpdates) + " failedBearings " + std::to_string(s.failedBearings) +
      " buckledBearings " + std::to_string(s.buckledBearings) + " threads " +
      std::to_string(rt.analysis->threads());
  // The automatic choice's measurement (ThreadChoice): the threads' time per iteration over one
  // thread's, the median of its pairs of steps; present once it has measured.
  const auto& choice = rt.analysis->threadChoice();
  char ratio[32] = "";
  if (rt.analysis->threadsAsked() == 0 && choice.measured())
    std::snprintf(ratio, sizeof ratio, " threadRatio %.3f", choice.ratio());
  setResult(rt, text + ratio);
}

constexpr CommandEntry kCommands[] = {
    {"analysisStatistics", "analysisStatistics", analysisStatisticsCmd},
    {"threads", "threads ?n|auto?", threadsCmd},
    {"constraints", "constraints Plain|Transformation|Penalty ?alphaSP alphaMP?",
     strategy::constraintsCommand},
    {"numberer", "numberer Plain|RCM", strategy::numbererCommand},
    {"system",
     "system BandGeneral|BandSPD|ProfileSPD|SparseGeneral|UmfPack|FullGeneral|SparseSYM|Mumps",
     strategy::systemCommand},
    {"test", "test NormDispIncr|NormUnbalance|EnergyIncr tol maxIter ?pFlag? ?nType?",
     strategy::testCommand},
    {"algorithm", "algorithm Linear|Newton|ModifiedNewton|NewtonLineSearch|KrylovNewton ?options?",
     strategy::algorithmCommand},
    {"integrator",
     "integrator "
     "LoadControl|DisplacementControl|ArcLength|HSConstraint|Newmark|HHT|GeneralizedAlpha|TRBDF2|"
     "CentralDifference args...",
     strategy::integratorCommand},
    {"analysis", "analysis Static|Transient ?-numSubLevels n? ?-numSubSteps m?", analysisCmd},
    {"analyze", "analyze numIncr ?dt? ?-progress?", analyzeCmd},
    {"eigen", "eigen ?-fullGenLapack? ?-findLargest? numModes", eigenCmd},
    {"wipe", "wipe", wipeCmd},
    {"wipeAnalysis", "wipeAnalysis", wipeAnalysisCmd},
    {"initialize", "initialize", initializeCmd},
    {"testIter", "testIter", testIterCmd},
    {"reset", "reset", resetCmd},
};

}  // namespace

std::span<const CommandEntry> analysisCommands() { return kCommands; }

}  // namespace dabs::tcl
