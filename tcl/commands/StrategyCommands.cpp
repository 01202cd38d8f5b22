// SPDX-License-Identifier: MIT
// The analysis strategy commands: constraints, numberer, system, test, algorithm, integrator.
// Each type word selects a row of a table (name -> parser or kind), with its own usage line.
#include "tcl/commands/StrategyCommands.h"

#include <cctype>
#include <memory>
#include <string>

#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/integrators/ArcLength.h"
#include "tcl/analysis/integrators/CentralDifference.h"
#include "tcl/analysis/integrators/DisplacementControl.h"
#include "tcl/analysis/integrators/GeneralizedAlpha.h"
#include "tcl/analysis/algorithms/KrylovNewton.h"
#include "tcl/analysis/algorithms/LinearAlgorithm.h"
#include "tcl/analysis/integrators/LoadControl.h"
#include "tcl/analysis/algorithms/NewtonLineSearch.h"
#include "tcl/analysis/algorithms/NewtonRaphson.h"
#include "tcl/analysis/integrators/TRBDF2.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl::strategy {

void warn(const std::string& text) {
  if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr)
    Tcl_WriteChars(err, text.c_str(), static_cast<int>(text.size()));
}

namespace {

constexpr KindEntry<analysis::ConstraintKind> kConstraints[] = {
    {"Plain", analysis::ConstraintKind::Plain},
    {"Transformation", analysis::ConstraintKind::Transformation},
    {"Penalty", analysis::ConstraintKind::Penalty},
};

// AMD orders for a sparse factorisation as RCM does; both give the same results.
constexpr KindEntry<analysis::NumbererKind> kNumberers[] = {
    {"Plain", analysis::NumbererKind::Plain},
    {"RCM", analysis::NumbererKind::RCM},
    {"AMD", analysis::NumbererKind::RCM},
};

// Unconditional stability of the generalized-alpha method, Chung & Hulbert (1993) eq. 25:
// alpha_m <= alpha_f <= 1/2 and beta >= 1/4 + (alpha_f - alpha_m)/2, with gamma at least the
// second-order value 1/2 - alpha_m + alpha_f. In OpenSees' convention alphaM = 1 - alpha_m and
// alphaF = 1 - alpha_f (1 and 1 is Newmark), so: 1/2 <= alphaF <= alphaM.
void checkAlphaStability(ArgReader& a, double alphaM, double alphaF, double gamma, double beta) {
  if (!(alphaF >= 0.5 && alphaF <= 1.0 && alphaM >= alphaF && alphaM <= 2.0))
    a.fail(
        "alphaM and alphaF must satisfy 1/2 <= alphaF <= alphaM <= 2 and alphaF <= 1 for "
        "unconditional "
        "stability (Chung & Hulbert 1993), got alphaM " +
        std::to_string(alphaM) + ", alphaF " + std::to_string(alphaF));
  const double d = alphaM - alphaF;
  constexpr double kRoundOff = 1e-12;
  if (gamma < 0.5 + d - kRoundOff || beta < 0.25 + 0.5 * d - kRoundOff)
    a.fail("gamma must be at least 1/2 + alphaM - alphaF = " + std::to_string(0.5 + d) +
           " and beta at least 1/4 + (alphaM - alphaF)/2 = " + std::to_string(0.25 + 0.5 * d) +
           " for unconditional stability (Chung & Hulbert 1993), got gamma " +
           std::to_string(gamma) + ", beta " + std::to_string(beta));
}

constexpr KindEntry<analysis::ConvergenceTest::Kind> kTests[] = {
    {"NormDispIncr", analysis::ConvergenceTest::Kind::NormDispIncr},
    {"NormUnbalance", analysis::ConvergenceTest::Kind::NormUnbalance},
    {"EnergyIncr", analysis::ConvergenceTest::Kind::EnergyIncr},
};

// The parsers check their arguments first, with messages that name them as the user typed them,
// then call the parameters' validate(), which holds the same rules for C++ callers (an
// InputError from it is reported at the argument its field names).

// --- algorithm TYPE ?options? ---------------------------------------------------------------

using AlgorithmPtr = std::unique_ptr<analysis::SolutionAlgorithm>;
using AlgorithmParser = AlgorithmPtr (*)(ArgReader& a);

// OpenSees' -secant asks the elements for a secant stiffness; dabs' elements give none, so the
// option is refused rather than silently replaced by the tangent.
void rejectSecant(ArgReader& a) {
  if (a.flag("-secant") || a.flag("-Secant"))
    a.fail(
        "-secant is not supported: the elements give no secant stiffness (use -initial or the "
        "current tangent)");
}

AlgorithmPtr parseLinear(ArgReader& a) {
  rejectSecant(a);
  const bool initial = a.flag("-initial");
  const bool factorOnce = a.flag("-factorOnce");
  return std::make_unique<analysis::LinearAlgorithm>(initial, factorOnce);
}

AlgorithmPtr parseNewton(ArgReader& a) {
  rejectSecant(a);
  auto tangent = analysis::NewtonRaphson::Tangent::Current;
  if (a.flag("-initial")) tangent = analysis::NewtonRaphson::Tangent::Initial;
  if (a.flag("-initialThenCurrent") || a.flag("-initialCurrent"))
    tangent = analysis::NewtonRaphson::Tangent::InitialThenCurrent;
  return std::make_unique<analysis::NewtonRaphson>(tangent, false);
}

AlgorithmPtr parseModifiedNewton(ArgReader& a) {
  rejectSecant(a);
  const auto tangent = a.flag("-initial") ? analysis::NewtonRaphson::Tangent::Initial
                                          : analysis::NewtonRaphson::Tangent::Current;
  return std::make_unique<analysis::NewtonRaphson>(tangent, true);
}

constexpr KindEntry<analysis::NewtonLineSearch::Search> kSearches[] = {
    {"InitialInterpolated", analysis::NewtonLineSearch::Search::InitialInterpolated},
    {"Bisection", analysis::NewtonLineSearch::Search::Bisection},
    {"Secant", analysis::NewtonLineSearch::Search::Secant},
    {"RegulaFalsi", analysis::NewtonLineSearch::Search::RegulaFalsi},
    {"LinearInterpolated", analysis::NewtonLineSearch::Search::RegulaFalsi},
};

AlgorithmPtr parseNewtonLineSearch(ArgReader& a) {
  auto search = analysis::NewtonLineSearch::Search::InitialInterpolated;
  if (auto t = a.optionalWordOption("-type")) {
    const auto* entry = findType<KindEntry<analysis::NewtonLineSearch::Search>>({kSearches}, *t);
    if (entry == nullptr)
      a.failArgument("-type",
                     "expected one of " +
                         typeNames<KindEntry<analysis::NewtonLineSearch::Search>>({kSearches}));
    search = entry->kind;
  }
  double tol = a.option("-tol", 0.8);
  const char* tolName = "-tol";
  if (auto ratio = a.optionalReal("ratio")) {  // older form: NewtonLineSearch 0.8
    tol = *ratio;
    tolName = "ratio";
  }
  const int maxIter = a.option("-maxIter", 10);
  const double minEta = a.option("-minEta", 0.1);
  const double maxEta = a.option("-maxEta", 10.0);
  // OpenSees prints each line-search iteration when pFlag is 0 and is quiet otherwise (its
  // default is 1); dabs has no such output, so only the quiet setting is accepted.
  if (a.option("-pFlag", 1) == 0)
    a.failArgument("-pFlag",
                   "0 (print each line-search iteration) is not supported; use 1 (quiet)");
  if (!(tol > 0.0)) a.failArgument(tolName, "must be positive");
  if (maxIter < 1) a.failArgument("-maxIter", "must be at least 1");
  if (!(minEta > 0.0 && minEta <= 1.0)) a.failArgument("-minEta", "must be in (0, 1]");
  if (!(maxEta >= 1.0)) a.failArgument("-maxEta", "must be at least 1");
  const analysis::NewtonLineSearch::Params p{search, tol, maxIter, minEta, maxEta};
  p.validate();
  return std::make_unique<analysis::NewtonLineSearch>(p);
}

AlgorithmPtr parseKrylovNewton(ArgReader& a) {
  rejectSecant(a);
  const bool initial = a.flag("-initial");
  const int maxDim = a.option("-maxDim", 3);
  if (maxDim < 1) a.failArgument("-maxDim", "must be at least 1");
  const analysis::KrylovNewton::Params p{initial, maxDim};
  p.validate();
  return std::make_unique<analysis::KrylovNewton>(p);
}

constexpr TypeEntry<AlgorithmParser> kAlgorithms[] = {
    {"Linear", "algorithm Linear ?-initial? ?-factorOnce?", parseLinear},
    {"Newton", "algorithm Newton ?-initial? ?-initialThenCurrent?", parseNewton},
    {"ModifiedNewton", "algorithm ModifiedNewton ?-initial?", parseModifiedNewton},
    {"NewtonLineSearch",
     "algorithm NewtonLineSearch ?ratio? ?-type InitialInterpolated|Bisection|Secant|RegulaFalsi? "
     "?-tol tol? ?-maxIter n? ?-minEta e? ?-maxEta e? ?-pFlag 1?",
     parseNewtonLineSearch},
    {"KrylovNewton", "algorithm KrylovNewton ?-initial? ?-maxDim n?", parseKrylovNewton},
};

// --- integrator TYPE args ---------------------------------------------------------------------

using IntegratorPtr = std::unique_ptr<analysis::Integrator>;
using IntegratorParser = IntegratorPtr (*)(Runtime& rt, ArgReader& a);

IntegratorPtr parseLoadControl(Runtime& /*rt*/, ArgReader& a) {
  const double dLambda = a.real("dLambda");
  int Jd = 1;
  double minL = dLambda, maxL = dLambda;
  if (auto j = a.optionalInteger("Jd")) {
    Jd = *j;
    minL = a.real("minLambda");
    maxL = a.real("maxLambda");
  }
  a.finish();
  if (Jd < 1) a.failArgument("Jd", "must be at least 1");
  const analysis::LoadControl::Params p{dLambda, Jd, minL, maxL};
  p.validate();
  return std::make_unique<analysis::LoadControl>(p);
}

IntegratorPtr parseDisplacementControl(Runtime& rt, ArgReader& a) {
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
  if (dof < 1 || dof > n.ndf()) a.failArgument("dof", "must be 1.." + std::to_string(n.ndf()));
  if (Jd < 1) a.failArgument("Jd", "must be at least 1");
  const analysis::DisplacementControl::Params p{node, dof - 1, incr, Jd, dUmin, dUmax, initial};
  p.validate();
  return std::make_unique<analysis::DisplacementControl>(p);
}

IntegratorPtr parseNewmark(Runtime& /*rt*/, ArgReader& a) {
  const double gamma = a.real("gamma");
  const double beta = a.real("beta");
  if (auto form = a.optionalWordOption("-form"))
    if (form->empty() || (std::toupper((*form)[0]) != 'D' && std::toupper((*form)[0]) != 'A'))
      a.failArgument("-form", "must be D or A");
  a.finish();
  if (!(gamma > 0.0)) a.failArgument("gamma", "must be positive");
  if (!(beta > 0.0)) a.failArgument("beta", "must be positive");
  const analysis::GeneralizedAlpha::Params p{1.0, 1.0, gamma, beta};
  p.validate();
  return std::make_unique<analysis::GeneralizedAlpha>(p);
}

IntegratorPtr parseHHT(Runtime& /*rt*/, ArgReader& a) {
  const double alpha = a.real("alpha");
  double gamma = 1.5 - alpha, beta = (2.0 - alpha) * (2.0 - alpha) / 4.0;
  if (auto g = a.optionalReal("gamma")) {
    gamma = *g;
    beta = a.real("beta");
  }
  a.finish();
  // Hilber, Hughes & Taylor (1977) give alpha_HHT in [-1/3, 0], i.e. OpenSees' alpha = 1 +
  // alpha_HHT in [2/3, 1]. OpenSees runs smaller values (its workshop scripts use 0.6); as a
  // generalized-alpha method with alpha_m = 1 the scheme stays unconditionally stable down to
  // alpha = 1/2 (Chung & Hulbert 1993, checked below), so [1/2, 2/3) runs with a warning that
  // it is outside HHT's published range, and below 1/2 or above 1 is an error.
  if (!(alpha >= 0.5 && alpha <= 1.0))
    a.failArgument("alpha",
                   "must be in [2/3, 1] (HHT's range; OpenSees convention: 1 is Newmark, 2/3 the "
                   "most dissipative), or in [1/2, 2/3) with a warning");
  if (alpha < 2.0 / 3.0)
    warn("WARNING integrator HHT " + std::to_string(alpha) +
         ": alpha below 2/3 is outside Hilber, Hughes and Taylor's range [2/3, 1]; the step is "
         "unconditionally stable (generalized alpha with alpha_m = 1) but its high-frequency "
         "dissipation is no longer the one HHT designed\n");
  checkAlphaStability(a, 1.0, alpha, gamma, beta);
  const analysis::GeneralizedAlpha::Params p{1.0, alpha, gamma, beta};
  p.validate();
  return std::make_unique<analysis::GeneralizedAlpha>(p);
}

IntegratorPtr parseGeneralizedAlpha(Runtime& /*rt*/, ArgReader& a) {
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
  const analysis::GeneralizedAlpha::Params p{alphaM, alphaF, gamma, beta};
  p.validate();
  return std::make_unique<analysis::GeneralizedAlpha>(p);
}

IntegratorPtr parseCentralDifference(Runtime& /*rt*/, ArgReader& a) {
  a.finish();
  return std::make_unique<analysis::CentralDifference>();
}

IntegratorPtr parseTRBDF2(Runtime& /*rt*/, ArgReader& a) {
  a.finish();
  return std::make_unique<analysis::TRBDF2>();
}

IntegratorPtr parseArcLength(Runtime& /*rt*/, ArgReader& a) {
  const double s = a.real("arcLength");
  const double alpha = a.real("alpha");
  a.finish();
  if (!(s > 0.0)) a.failArgument("arcLength", "must be positive");
  const analysis::ArcLength::Params p{s, 1.0, alpha * alpha, false};
  p.validate();
  return std::make_unique<analysis::ArcLength>(p);
}

IntegratorPtr parseHSConstraint(Runtime& /*rt*/, ArgReader& a) {
  const double s = a.real("arcLength");
  const double psiU = a.optionalReal("psiU").value_or(1.0);
  const double psiF = a.optionalReal("psiF").value_or(1.0);
  const double uRef = a.optionalReal("uRef").value_or(1.0);
  a.finish();
  if (!(s > 0.0)) a.failArgument("arcLength", "must be positive");
  if (uRef == 0.0) a.failArgument("uRef", "must not be zero");
  if (psiU == 0.0 && psiF == 0.0) a.fail("psiU and psiF must not both be zero");
  const analysis::ArcLength::Params p{s, psiU * psiU / (uRef * uRef), psiF * psiF, true};
  p.validate();
  return std::make_unique<analysis::ArcLength>(p);
}

constexpr TypeEntry<IntegratorParser> kIntegrators[] = {
    {"LoadControl", "integrator LoadControl dLambda ?Jd minLambda maxLambda?", parseLoadControl},
    {"DisplacementControl",
     "integrator DisplacementControl node dof incr ?Jd dUmin dUmax? ?-initial?",
     parseDisplacementControl},
    {"ArcLength", "integrator ArcLength arcLength alpha", parseArcLength},
    {"HSConstraint", "integrator HSConstraint arcLength ?psiU? ?psiF? ?uRef?", parseHSConstraint},
    {"Newmark", "integrator Newmark gamma beta ?-form D|A?", parseNewmark},
    {"HHT", "integrator HHT alpha ?gamma beta?", parseHHT},
    {"GeneralizedAlpha", "integrator GeneralizedAlpha alphaM alphaF ?gamma beta?",
     parseGeneralizedAlpha},
    {"TRBDF2", "integrator TRBDF2", parseTRBDF2},
    {"Bathe", "integrator Bathe", parseTRBDF2},
    {"CentralDifference", "integrator CentralDifference", parseCentralDifference},
};

}  // namespace

void constraintsCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto kind = lookUp<KindEntry<analysis::ConstraintKind>>(a, kConstraints, type).kind;
  if (kind != analysis::ConstraintKind::Penalty) {
    a.finish();
    rt.analysis->setConstraints(kind);
    return;
  }
  const double alphaSP = a.real("alphaSP");
  const double alphaMP = a.real("alphaMP");
  a.finish();
  if (!(alphaSP > 0.0)) a.failArgument("alphaSP", "must be positive");
  if (!(alphaMP > 0.0)) a.failArgument("alphaMP", "must be positive");
  rt.analysis->setConstraints(kind, alphaSP, alphaMP);
}

void numbererCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto kind = lookUp<KindEntry<analysis::NumbererKind>>(a, kNumberers, type).kind;
  a.finish();
  rt.analysis->setNumberer(kind);
}

// `system TYPE ?options?`. The words after the type tune OpenSees' own solvers (e.g. UmfPack
// -lvalueFact, Mumps -ICNTL14, SparseGeneral -piv); OpenSees 3.8 itself skips words it does not
// know and ignores UmfPack's options. They have no counterpart in Eigen's solvers and cannot change
// the results, so they are reported on stderr as not supported and ignored.
void systemCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto kind = analysis::solverKindFromName(type);
  std::string ignored;
  while (a.hasMore()) {
    ignored += ' ';
    ignored += a.word("option");
  }
  if (!ignored.empty())
    warn("system " + type +
         ": solver options are not supported (dabs' solvers have no such settings); "
         "ignored:" +
         ignored + "\n");
  rt.analysis->setSystem(kind);
}

void testCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto kind = lookUp<KindEntry<analysis::ConvergenceTest::Kind>>(a, kTests, type).kind;
  const double tol = a.real("tol");
  const int maxIter = a.integer("maxIter");
  const int pFlag = a.optionalInteger("pFlag").value_or(0);
  const int nType = a.optionalInteger("nType").value_or(2);
  a.finish();
  if (!(tol > 0.0)) a.failArgument("tol", "must be positive");
  if (maxIter < 1) a.failArgument("maxIter", "must be at least 1");
  if (nType < 0) a.failArgument("nType", "must be 0 (max norm) or a positive p");
  const analysis::ConvergenceTest::Params p{kind, tol, maxIter, pFlag, nType};
  p.validate();
  auto test = std::make_unique<analysis::ConvergenceTest>(p);
  test->log = rt.analysis->log;
  rt.analysis->setTest(std::move(test));
}

void algorithmCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto& entry = lookUp<TypeEntry<AlgorithmParser>>(a, kAlgorithms, type);
  a.setContext("algorithm " + type);
  a.setUsage(std::string(entry.usage));
  AlgorithmPtr algorithm = entry.parse(a);
  a.finish();
  rt.analysis->setAlgorithm(std::move(algorithm));
}

void integratorCommand(Runtime& rt, ArgReader& a) {
  const std::string type = a.word("type");
  const auto& entry = lookUp<TypeEntry<IntegratorParser>>(a, kIntegrators, type);
  a.setContext("integrator " + type);
  a.setUsage(std::string(entry.usage));
  IntegratorPtr integrator = entry.parse(rt, a);
  rt.analysis->setIntegrator(std::move(integrator));
}

}  // namespace dabs::tcl::strategy
