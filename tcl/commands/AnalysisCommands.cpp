// SPDX-License-Identifier: MIT
// Analysis commands: constraints, numberer, system, test, algorithm, integrator, analysis,
// analyze, eigen, wipe, wipeAnalysis, reset.
#include <string>

#include "materials/InputError.h"
#include "tcl/analysis/AnalysisBuilder.h"
#include "tcl/analysis/ArcLength.h"
#include "tcl/analysis/CentralDifference.h"
#include "tcl/analysis/DisplacementControl.h"
#include "tcl/analysis/GeneralizedAlpha.h"
#include "tcl/analysis/KrylovNewton.h"
#include "tcl/analysis/LinearAlgorithm.h"
#include "tcl/analysis/LoadControl.h"
#include "tcl/analysis/NewtonLineSearch.h"
#include "tcl/analysis/StopRequest.h"
#include "tcl/analysis/TRBDF2.h"
#include "tcl/commands/SignalExit.h"
#include "tcl/analysis/NewtonRaphson.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

using analysis::AnalysisBuilder;

void constraintsCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  if (type == "Plain") {
    a.finish();
    rt.analysis->setConstraints(analysis::ConstraintKind::Plain);
  } else if (type == "Transformation") {
    a.finish();
    rt.analysis->setConstraints(analysis::ConstraintKind::Transformation);
  } else if (type == "Penalty") {
    const double alphaSP = a.real("alphaSP");
    const double alphaMP = a.real("alphaMP");
    a.finish();
    if (!(alphaSP > 0.0) || !(alphaMP > 0.0)) a.fail("penalty factors must be positive");
    rt.analysis->setConstraints(analysis::ConstraintKind::Penalty, alphaSP, alphaMP);
  } else {
    a.fail(1, "type", "expected Plain, Transformation or Penalty, got \"" + type + "\"");
  }
}

void numbererCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  a.finish();
  if (type == "Plain") rt.analysis->setNumberer(analysis::NumbererKind::Plain);
  else if (type == "RCM" || type == "AMD") rt.analysis->setNumberer(analysis::NumbererKind::RCM);
  else a.fail(1, "type", "expected Plain or RCM, got \"" + type + "\"");
}

void systemCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  // Solver-specific options of OpenSees (e.g. -piv, -lValueFact) do not apply to Eigen's solvers.
  while (a.hasMore()) (void)a.word("option");
  rt.analysis->setSystem(analysis::solverKindFromName(type));
}

// Unconditional stability of the generalized-alpha method, Chung & Hulbert (1993) eq. 25:
// alpha_m <= alpha_f <= 1/2 and beta >= 1/4 + (alpha_f - alpha_m)/2, with gamma at least the
// second-order value 1/2 - alpha_m + alpha_f. In OpenSees' convention alphaM = 1 - alpha_m and
// alphaF = 1 - alpha_f (1 and 1 is Newmark), so: 1/2 <= alphaF <= alphaM.
void checkAlphaStability(ArgReader& a, double alphaM, double alphaF, double gamma, double beta) {
  if (!(alphaF >= 0.5 && alphaF <= 1.0 && alphaM >= alphaF && alphaM <= 2.0))
    a.fail("alphaM and alphaF must satisfy 1/2 <= alphaF <= alphaM <= 2 and alphaF <= 1 for unconditional "
           "stability (Chung & Hulbert 1993), got alphaM " + std::to_string(alphaM) + ", alphaF " +
           std::to_string(alphaF));
  const double d = alphaM - alphaF;
  constexpr double kRoundOff = 1e-12;
  if (gamma < 0.5 + d - kRoundOff || beta < 0.25 + 0.5 * d - kRoundOff)
    a.fail("gamma must be at least 1/2 + alphaM - alphaF = " + std::to_string(0.5 + d) +
           " and beta at least 1/4 + (alphaM - alphaF)/2 = " + std::to_string(0.25 + 0.5 * d) +
           " for unconditional stability (Chung & Hulbert 1993), got gamma " + std::to_string(gamma) +
           ", beta " + std::to_string(beta));
}

void testCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  analysis::ConvergenceTest::Kind kind{};
  if (type == "NormDispIncr") kind = analysis::ConvergenceTest::Kind::NormDispIncr;
  else if (type == "NormUnbalance") kind = analysis::ConvergenceTest::Kind::NormUnbalance;
  else if (type == "EnergyIncr") kind = analysis::ConvergenceTest::Kind::EnergyIncr;
  else a.fail(1, "type", "expected NormDispIncr, NormUnbalance or EnergyIncr, got \"" + type + "\"");
  const double tol = a.real("tol");
  const int maxIter = a.integer("maxIter");
  const int pFlag = a.optionalInteger("pFlag").value_or(0);
  const int nType = a.optionalInteger("nType").value_or(2);
  a.finish();
  if (!(tol > 0.0)) a.fail(2, "tol", "must be positive");
  if (maxIter < 1) a.fail(3, "maxIter", "must be at least 1");
  if (nType < 0) a.fail(5, "nType", "must be 0 (max norm) or a positive p");
  auto test = std::make_unique<analysis::ConvergenceTest>(kind, tol, maxIter, pFlag, nType);
  test->log = rt.analysis->log;
  rt.analysis->setTest(std::move(test));
}

void algorithmCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  std::unique_ptr<analysis::SolutionAlgorithm> algorithm;
  if (type == "Linear") {
    const bool initial = a.flag("-initial");
    const bool factorOnce = a.flag("-factorOnce");
    (void)a.flag("-secant");
    algorithm = std::make_unique<analysis::LinearAlgorithm>(initial, factorOnce);
  } else if (type == "Newton") {
    auto tangent = analysis::NewtonRaphson::Tangent::Current;
    if (a.flag("-initial")) tangent = analysis::NewtonRaphson::Tangent::Initial;
    if (a.flag("-initialThenCurrent") || a.flag("-initialCurrent"))
      tangent = analysis::NewtonRaphson::Tangent::InitialThenCurrent;
    algorithm = std::make_unique<analysis::NewtonRaphson>(tangent, false);
  } else if (type == "ModifiedNewton") {
    const auto tangent = a.flag("-initial") ? analysis::NewtonRaphson::Tangent::Initial
                                            : analysis::NewtonRaphson::Tangent::Current;
    algorithm = std::make_unique<analysis::NewtonRaphson>(tangent, true);
  } else if (type == "NewtonLineSearch") {
    auto search = analysis::NewtonLineSearch::Search::InitialInterpolated;
    if (auto t = a.optionalWordOption("-type")) {
      if (*t == "InitialInterpolated") search = analysis::NewtonLineSearch::Search::InitialInterpolated;
      else if (*t == "Bisection") search = analysis::NewtonLineSearch::Search::Bisection;
      else if (*t == "Secant") search = analysis::NewtonLineSearch::Search::Secant;
      else if (*t == "RegulaFalsi" || *t == "LinearInterpolated")
        search = analysis::NewtonLineSearch::Search::RegulaFalsi;
      else a.fail("-type must be InitialInterpolated, Bisection, Secant or RegulaFalsi");
    }
    double tol = a.option("-tol", 0.8);
    if (auto ratio = a.optionalReal("ratio")) tol = *ratio;  // older form: NewtonLineSearch 0.8
    const int maxIter = a.option("-maxIter", 10);
    const double minEta = a.option("-minEta", 0.1);
    const double maxEta = a.option("-maxEta", 10.0);
    (void)a.option("-pFlag", 1);
    if (!(tol > 0.0)) a.fail("-tol must be positive");
    if (maxIter < 1) a.fail("-maxIter must be at least 1, got " + std::to_string(maxIter));
    if (!(minEta > 0.0 && minEta <= 1.0 && maxEta >= 1.0))
      a.fail("-minEta must be in (0, 1] and -maxEta at least 1");
    algorithm = std::make_unique<analysis::NewtonLineSearch>(search, tol, maxIter, minEta, maxEta);
  } else if (type == "KrylovNewton") {
    const bool initial = a.flag("-initial");
    const int maxDim = a.option("-maxDim", 3);
    if (maxDim < 1) a.fail("-maxDim must be at least 1");
    algorithm = std::make_unique<analysis::KrylovNewton>(initial, maxDim);
  } else {
    a.fail(1, "type", "expected Linear, Newton, ModifiedNewton, NewtonLineSearch or KrylovNewton, got \"" + type + "\"");
  }
  a.finish();
  rt.analysis->setAlgorithm(std::move(algorithm));
}

void integratorCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  std::unique_ptr<analysis::Integrator> integrator;
  if (type == "LoadControl") {
    const double dLambda = a.real("dLambda");
    int Jd = 1;
    double minL = dLambda, maxL = dLambda;
    if (auto j = a.optionalInteger("Jd")) {
      Jd = *j;
      minL = a.real("minLambda");
      maxL = a.real("maxLambda");
    }
    a.finish();
    if (Jd < 1) a.fail(3, "Jd", "must be at least 1");
    integrator = std::make_unique<analysis::LoadControl>(dLambda, Jd, minL, maxL);
  } else if (type == "DisplacementControl") {
    const int node = a.integer("node");
    const int dof = a.integer("dof");
    const double incr = a.real("incr");
    int Jd = 1;
    double dUmin = incr, dUmax = incr;
    if (auto j = a.optionalInteger("Jd")) {
      Jd = *j;
      dUmin = a.real("dUmin");
      dUmax = a.real("dUmax");
    }
    const bool initial = a.flag("-initial");
    a.finish();
    const domain::Node& n = rt.domain.node(node);
    if (dof < 1 || dof > n.ndf()) a.fail(3, "dof", "must be 1.." + std::to_string(n.ndf()));
    if (Jd < 1) a.fail(5, "Jd", "must be at least 1");
    integrator = std::make_unique<analysis::DisplacementControl>(node, dof - 1, incr, Jd, dUmin, dUmax, initial);
  } else if (type == "Newmark") {
    const double gamma = a.real("gamma");
    const double beta = a.real("beta");
    if (auto form = a.optionalWordOption("-form"))
      if (form->empty() || (std::toupper((*form)[0]) != 'D' && std::toupper((*form)[0]) != 'A'))
        a.fail("-form must be D or A");
    a.finish();
    if (!(gamma > 0.0) || !(beta > 0.0)) a.fail("gamma and beta must be positive");
    integrator = std::make_unique<analysis::GeneralizedAlpha>(1.0, 1.0, gamma, beta);
  } else if (type == "HHT") {
    const double alpha = a.real("alpha");
    double gamma = 1.5 - alpha, beta = (2.0 - alpha) * (2.0 - alpha) / 4.0;
    if (auto g = a.optionalReal("gamma")) {
      gamma = *g;
      beta = a.real("beta");
    }
    a.finish();
    // Hilber, Hughes & Taylor (1977): unconditionally stable for alpha_HHT in [-1/3, 0], i.e.
    // OpenSees' alpha = 1 + alpha_HHT in [2/3, 1].
    if (!(alpha >= 2.0 / 3.0 && alpha <= 1.0))
      a.fail(1, "alpha", "must be in [2/3, 1] for unconditional stability (OpenSees convention: 1 is Newmark, 2/3 the most dissipative)");
    checkAlphaStability(a, 1.0, alpha, gamma, beta);
    integrator = std::make_unique<analysis::GeneralizedAlpha>(1.0, alpha, gamma, beta);
  } else if (type == "GeneralizedAlpha") {
    const double alphaM = a.real("alphaM");
    const double alphaF = a.real("alphaF");
    double gamma = 0.5 + alphaM - alphaF;
    double beta = 0.25 * (1.0 + alphaM - alphaF) * (1.0 + alphaM - alphaF);
    if (auto g = a.optionalReal("gamma")) {
      gamma = *g;
      beta = a.real("beta");
    }
    a.finish();
    checkAlphaStability(a, alphaM, alphaF, gamma, beta);
    integrator = std::make_unique<analysis::GeneralizedAlpha>(alphaM, alphaF, gamma, beta);
  } else if (type == "CentralDifference") {
    a.finish();
    integrator = std::make_unique<analysis::CentralDifference>();
  } else if (type == "TRBDF2" || type == "Bathe") {
    a.finish();
    integrator = std::make_unique<analysis::TRBDF2>();
  } else if (type == "ArcLength") {
    const double s = a.real("arcLength");
    const double alpha = a.real("alpha");
    a.finish();
    if (!(s > 0.0)) a.fail(2, "arcLength", "must be positive");
    integrator = std::make_unique<analysis::ArcLength>(s, 1.0, alpha * alpha, false);
  } else if (type == "HSConstraint") {
    const double s = a.real("arcLength");
    const double psiU = a.optionalReal("psiU").value_or(1.0);
    const double psiF = a.optionalReal("psiF").value_or(1.0);
    const double uRef = a.optionalReal("uRef").value_or(1.0);
    a.finish();
    if (!(s > 0.0)) a.fail(2, "arcLength", "must be positive");
    if (uRef == 0.0) a.fail(5, "uRef", "must not be zero");
    if (psiU == 0.0 && psiF == 0.0) a.fail("psiU and psiF must not both be zero");
    integrator = std::make_unique<analysis::ArcLength>(s, psiU * psiU / (uRef * uRef), psiF * psiF, true);
  } else {
    a.fail(1, "type", "expected LoadControl, DisplacementControl, ArcLength, HSConstraint, Newmark, HHT, GeneralizedAlpha, TRBDF2 or CentralDifference, got \"" + type + "\"");
  }
  rt.analysis->setIntegrator(std::move(integrator));
}

void analysisCmd(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const int levels = a.option("-numSubLevels", 0);
  const int steps = a.option("-numSubSteps", 10);
  a.finish();
  if (levels < 0) a.fail("-numSubLevels must not be negative");
  if (steps < 2) a.fail("-numSubSteps must be at least 2");
  if (type == "Static") rt.analysis->setAnalysis(AnalysisBuilder::Kind::Static, levels, steps);
  else if (type == "Transient" || type == "VariableTransient")
    rt.analysis->setAnalysis(AnalysisBuilder::Kind::Transient, levels, steps);
  else a.fail(1, "type", "expected Static or Transient, got \"" + type + "\"");
}

void analyzeCmd(Runtime& rt, ArgReader& a) {
  const int n = a.integer("numIncr");
  const double dt = a.optionalReal("dt").value_or(0.0);
  a.finish();
  if (n < 0) a.fail(1, "numIncr", "must not be negative");
  if (rt.analysis->kind() == AnalysisBuilder::Kind::Transient && !(dt > 0.0))
    a.fail(2, "dt", "a positive time step is required for a transient analysis");
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
  if (options.empty()) a.fail(1, "numModes", "is missing");
  bool dense = false, largest = false, standard = false;
  for (std::size_t i = 0; i + 1 < options.size(); ++i) {
    std::string o = options[i];
    if (o.size() > 1 && o[0] == '-') o.erase(0, 1);
    if (o.size() > 5 && o.ends_with("Eigen")) o.resize(o.size() - 5);
    if (o == "fullGenLapack") dense = true;
    else if (o == "findLargest") largest = true;
    else if (o == "standard") standard = true;
    else if (o == "frequency" || o == "generalized" || o == "genBandArpack" || o == "symmBandLapack") continue;
    else if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr) {
      const std::string text = "eigen - unknown option specified " + options[i] + "\n";
      Tcl_WriteChars(err, text.c_str(), static_cast<int>(text.size()));
    }
  }
  int n = 0;
  if (Tcl_GetInt(nullptr, options.back().c_str(), &n) != TCL_OK)
    a.fail(options.size(), "numModes", "expected an integer, got \"" + options.back() + "\"");
  if (n < 1) a.fail(options.size(), "numModes", "must be at least 1");
  if (standard) {
    // OpenSees' eigen solvers other than the banded one (which dabs does not have) solve only the
    // generalized problem: the step fails with a warning and the result is empty.
    if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr) {
      const std::string text = "eigen - the standard problem is not solved; no eigenvalues\n";
      Tcl_WriteChars(err, text.c_str(), static_cast<int>(text.size()));
    }
    return;
  }
  if (rt.analysis->kind() == AnalysisBuilder::Kind::None) {
    if (!rt.analysis->constraintsGiven()) rt.analysis->setConstraints(analysis::ConstraintKind::Transformation);
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

// DABS extension: `threads ?n?` sets how many threads update the elements (1 to 256; results are
// bit-identical at any count) and returns the count in force.
void threadsCmd(Runtime& rt, ArgReader& a) {
  if (const auto n = a.optionalInteger("n")) {
    if (*n < 1 || *n > 256) a.fail("n must be 1 to 256, got " + std::to_string(*n));
    a.finish();
    rt.analysis->setThreads(*n);
  } else {
    a.finish();
  }
  setResult(rt, std::to_string(rt.analysis->threads()));
}

// DABS extension: what the analyses since the last wipe did, as a Tcl dict.
void analysisStatisticsCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  const auto& s = rt.analysis->statistics();
  const std::string text = "steps " + std::to_string(s.steps) + " failedSteps " + std::to_string(s.failedSteps) +
                           " subSteppedSteps " + std::to_string(s.subSteppedSteps) + " iterations " +
                           std::to_string(s.iterations) + " factorizations " + std::to_string(s.factorizations) +
                           " equations " + std::to_string(s.equations) + " elementUpdates " +
                           std::to_string(s.elementUpdates) + " materialUpdates " +
                           std::to_string(s.materialUpdates) + " failedBearings " +
                           std::to_string(s.failedBearings);
  setResult(rt, text);
}

constexpr CommandEntry kCommands[] = {
    {"analysisStatistics", "analysisStatistics", analysisStatisticsCmd},
    {"threads", "threads ?n?", threadsCmd},
    {"constraints", "constraints Plain|Transformation|Penalty ?alphaSP alphaMP?", constraintsCmd},
    {"numberer", "numberer Plain|RCM", numbererCmd},
    {"system", "system BandGeneral|BandSPD|ProfileSPD|SparseGeneral|UmfPack|FullGeneral|SparseSYM|Mumps", systemCmd},
    {"test", "test NormDispIncr|NormUnbalance|EnergyIncr tol maxIter ?pFlag? ?nType?", testCmd},
    {"algorithm", "algorithm Linear|Newton|ModifiedNewton|NewtonLineSearch|KrylovNewton ?options?", algorithmCmd},
    {"integrator", "integrator LoadControl|DisplacementControl|ArcLength|HSConstraint|Newmark|HHT|GeneralizedAlpha|TRBDF2|CentralDifference args...", integratorCmd},
    {"analysis", "analysis Static|Transient ?-numSubLevels n? ?-numSubSteps m?", analysisCmd},
    {"analyze", "analyze numIncr ?dt?", analyzeCmd},
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
