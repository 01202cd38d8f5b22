// SPDX-License-Identifier: MIT
// The fit of the Yoshida material to a bearing's curves: the cyclic test, the targets and their
// parameter ranges, the scaled variables, the objective and the NLopt search (the method is
// described at the top of calibrate_yoshida.cpp).
#include "verification/bearing/YoshidaFit.h"

#include <nlopt.hpp>

#include <chrono>
#include <cmath>
#include <numbers>

namespace dabs::calibration {

constexpr double kLocalXtol = 1e-4;  // BOBYQA: step in the scaled variables [0, 1]
constexpr double kLocalFtol = 1e-7;  // BOBYQA: relative change of the objective
constexpr int kLocalRestarts = 6;
constexpr double kLocalInitialStep = 0.02;    // BOBYQA's first trust region (scaled variables)
constexpr double kPolishSubIncrement = 0.05;  // sub-step (fraction of U0) of the restarts
constexpr int kFinalEvaluations = 150;        // last BOBYQA round, on the shipped sub-step
constexpr double kFinalInitialStep = 0.002;

/// Six triangular cycles of amplitude `x` along one axis; the last cycle gives Keq and Heq.
/// `loop`, when given, receives the (U, F) points of the last cycle.
LoopResult cyclicTest(const Params& p, double x, std::vector<std::array<double, 2>>* loop) {
  materials::YoshidaBearingMaterial m(1, p);
  const int perQuarter = 40;
  const double du = x / perQuarter;
  double u = 0.0, work = 0.0, fPos = 0.0, fNeg = 0.0;
  double fPrev = 0.0;
  const Eigen::Vector2d zero = Eigen::Vector2d::Zero();
  // path: 0 -> +X, then 12 half cycles -X, +X, ...; the last loop from the second-last +X
  const int quarters = 1 + 2 * 6;
  for (int qtr = 0; qtr < quarters; ++qtr) {
    const double sign = (qtr == 0) ? 1.0 : ((qtr % 2 == 1) ? -1.0 : 1.0);
    const int n = (qtr == 0) ? perQuarter : 2 * perQuarter;
    if (loop && qtr == quarters - 2) loop->push_back({u, fPrev});
    for (int i = 0; i < n; ++i) {
      u += sign * du;
      if (!dabs::ok(m.setTrialStrain(Eigen::Vector2d(u, 0.0), zero, 0.0))) return {NAN, NAN};
      m.commitState();
      const double f = m.getStress().x();
      if (qtr >= quarters - 2) work += 0.5 * (f + fPrev) * sign * du;
      if (loop && qtr >= quarters - 2) loop->push_back({u, f});
      fPrev = f;
    }
    if (qtr == quarters - 2) fNeg = fPrev;
    if (qtr == quarters - 1) fPos = fPrev;
  }
  LoopResult r;
  r.keq = (fPos - fNeg) / (2 * x);
  r.heq = work / (2 * std::numbers::pi * r.keq * x * x);
  return r;
}

constexpr std::array<bool, kNumParams> kLogScale = {true, true, true, false, false, true, false};

/// Material parameters from the scaled optimiser variables s in [0, 1]^7.
Params fromScaled(const Target& t, const std::vector<double>& s) {
  std::array<double, kNumParams> v{};
  for (int i = 0; i < kNumParams; ++i) {
    const double w = std::clamp(s[i], 0.0, 1.0);
    v[i] =
        kLogScale[i] ? t.lo[i] * std::pow(t.hi[i] / t.lo[i], w) : t.lo[i] + w * (t.hi[i] - t.lo[i]);
  }
  Params p;
  p.Y0 = v[0];
  p.U0 = v[1];
  p.n = v[2];
  p.q = v[5];
  const double uf = kFailureStrain * t.strainUnit / p.U0;
  p.beta = v[3] * (1.0 - v[4]) / (std::pow(uf, p.q) - 1.0);
  p.alpha0 = v[3] + p.beta;
  p.gamma = v[6] / (uf * uf);
  return p;
}

/// The inverse of fromScaled (for starting points and for reporting where bounds are active).
std::vector<double> toScaled(const Target& t, const Params& p) {
  const double uf = kFailureStrain * t.strainUnit / p.U0;
  const double a0 = p.alpha0 - p.beta;
  const double r = a0 > 0.0 ? (p.alpha0 - p.beta * std::pow(uf, p.q)) / a0 : 1.0;
  const std::array<double, kNumParams> v = {p.Y0, p.U0, p.n, a0, r, p.q, p.gamma * uf * uf};
  std::vector<double> s(kNumParams);
  for (int i = 0; i < kNumParams; ++i)
    s[i] = kLogScale[i] ? std::log(v[i] / t.lo[i]) / std::log(t.hi[i] / t.lo[i])
                        : (v[i] - t.lo[i]) / (t.hi[i] - t.lo[i]);
  return s;
}

/// Six significant digits: what is printed and shipped.
double round6(double v) {
  if (v == 0.0) return 0.0;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return std::strtod(buf, nullptr);
}

Params rounded(Params p) {
  p.Y0 = round6(p.Y0);
  p.U0 = round6(p.U0);
  p.n = round6(p.n);
  p.alpha0 = round6(p.alpha0);
  p.beta = round6(p.beta);
  p.q = round6(p.q);
  p.gamma = round6(p.gamma);
  return p;
}

FitError evaluate(const Target& t, const Params& p, const std::vector<double>& amplitudes) {
  FitError e;
  for (double x : amplitudes) {
    const LoopResult m = cyclicTest(p, x), g = t.curve(x);
    const double ek = (m.keq - g.keq) / g.keq, eh = (m.heq - g.heq) / g.heq;
    if (!std::isfinite(ek) || !std::isfinite(eh)) return {1e9, 1e9, 1e9, 1e9, 1e18, x, x};
    e.rmsK += ek * ek;
    e.rmsH += eh * eh;
    if (std::abs(ek) > e.maxK) e.maxK = std::abs(ek), e.atMaxK = x;
    if (std::abs(eh) > e.maxH) e.maxH = std::abs(eh), e.atMaxH = x;
  }
  e.objective = e.rmsK + e.rmsH;
  const double n = static_cast<double>(amplitudes.size());
  e.rmsK = std::sqrt(e.rmsK / n);
  e.rmsH = std::sqrt(e.rmsH / n);
  return e;
}

// (a) Bridgestone HDR X0.6, in shear stress (MPa) against shear strain: Keq is Geq.
LoopResult bridgestoneX06(double g) {
  LoopResult r;
  r.keq = (g < 1.15) ? 0.68358 * std::pow(g, -0.39964)
                     : 1.10103 - 0.61946 * g + 0.22047 * g * g - 0.022191 * g * g * g;
  r.heq = 0.23834 - 0.028108 * g + 0.000087664 * g * g;
  return r;
}

LoopResult leadRubber(double x) {
  LoopResult r;
  r.keq = kKd + kQd / x;                         // secant through (X, Qd + Kd X)
  const double loop = 4.0 * kQd * (x - kUyLrb);  // area of the bilinear loop
  r.heq = loop / (2 * std::numbers::pi * r.keq * x * x);
  return r;
}

std::vector<Target> targets() {
  std::vector<double> lrbAmplitudes;
  for (double g : {0.1, 0.15, 0.2, 0.3, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0})
    lrbAmplitudes.push_back(g * kTrLrb);
  // Physical ranges (the reasons are in fitted-parameters.md):
  //   Y0: characteristic strength, 0.05-2 MPa of rubber area (HDR) / 0.2-5 Qd (LRB);
  //   U0: yield deformation, 0.5 %-100 % shear strain (HDR) / 1-50 mm (LRB, lead core yield);
  //   n: 1 (the integrator's lower limit; Bouc-Wen's gradual transition) to 20 (indistinguishable
  //      from a bilinear corner at the sampled amplitudes);
  //   alpha0, beta: back-force factor 0-20 (post-yield slope ratio a/(1+a) up to 0.95);
  //   q: 0.01-2;  H: Y at 300 % shear strain from 1 to 6 times Y0.
  return {
      {"hdr",
       "Bridgestone HDR X0.6 (stress MPa, strain)",
       {0.1, 0.2, 0.3, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0, 2.25, 2.5, 2.75, 3.0},
       bridgestoneX06,
       1.0,
       {0.05, 0.005, 0.1, 0.0, -0.5, 0.01, 0.0},
       {2.0, 1.0, 20.0, 20.0, 1.0, 2.0, 5.0}},
      {"lrb",
       "Lead-rubber Qd=150 kN Kd=1500 kN/m K1=6.5Kd Tr=0.2 m (kN, m)",
       lrbAmplitudes,
       leadRubber,
       kTrLrb,
       {0.2 * kQd, 0.001, 0.1, 0.0, -0.5, 0.01, 0.0},
       {5.0 * kQd, 0.05, 20.0, 20.0, 1.0, 2.0, 5.0}},
  };
}

/// Global CRS2-LM on a coarse integration, then BOBYQA on the shipped integration.
FitResult fit(const Target& t, const std::vector<double>* start, int globalBudget, int localBudget,
              unsigned long seed) {
  FitResult r;
  struct Context {
    const Target* t;
    const std::vector<double>* amplitudes;
    double subIncrement;
    int evaluations;
    double bestF;  // best of the local stage so far, and where
    std::vector<double> bestX;
  } ctx{&t, &t.amplitudes, kGlobalSubIncrement, 0, HUGE_VAL, {}};
  auto objective = [](const std::vector<double>& s, std::vector<double>&, void* data) {
    auto* c = static_cast<Context*>(data);
    Params p = fromScaled(*c->t, s);
    p.maxSubIncrement = c->subIncrement;
    ++c->evaluations;
    const double f = evaluate(*c->t, p, *c->amplitudes).objective;
    if (f < c->bestF) c->bestF = f, c->bestX = s;
    return f;
  };
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<double> x = start ? *start : std::vector<double>(kNumParams, 0.5);
  double fx = 0.0;
  if (globalBudget > 0) {
    nlopt::srand(seed);
    nlopt::opt global(nlopt::GN_CRS2_LM, kNumParams);
    global.set_lower_bounds(std::vector<double>(kNumParams, 0.0));
    global.set_upper_bounds(std::vector<double>(kNumParams, 1.0));
    global.set_min_objective(objective, &ctx);
    global.set_maxeval(globalBudget);
    try {
      global.optimize(x, fx);
    } catch (const nlopt::roundoff_limited&) {
    }
    r.globalEvaluations = ctx.evaluations;
  }
  ctx.evaluations = 0;
  nlopt::opt local(nlopt::LN_BOBYQA, kNumParams);
  local.set_lower_bounds(std::vector<double>(kNumParams, 0.0));
  local.set_upper_bounds(std::vector<double>(kNumParams, 1.0));
  local.set_min_objective(objective, &ctx);
  local.set_xtol_abs(kLocalXtol);
  local.set_ftol_rel(kLocalFtol);
  // BOBYQA restarted from the best point so far (a fresh trust region, smaller each time) until a
  // restart gains less than kLocalFtol: one run stops early in the long narrow valleys of these
  // objectives. BOBYQA may shift a start that lies within its initial step of a bound, so the
  // best point evaluated, not the last result, is kept. The restarts run on a sub-step of
  // kPolishSubIncrement U0; the last round on the material exactly as shipped.
  auto polish = [&](double subIncrement, double step, int budget, int rounds) {
    ctx.subIncrement = subIncrement;
    ctx.bestF = HUGE_VAL;
    const int end = ctx.evaluations + budget;
    double fPrev = HUGE_VAL;
    for (int round = 0; round < rounds && ctx.evaluations < end; ++round) {
      local.set_maxeval(end - ctx.evaluations);
      local.set_initial_step(step);
      try {
        local.optimize(x, fx);
      } catch (const nlopt::roundoff_limited&) {
      }
      x = ctx.bestX;
      if (ctx.bestF > fPrev * (1.0 - kLocalFtol)) break;
      fPrev = ctx.bestF;
      step *= 0.25;
    }
  };
  polish(kPolishSubIncrement, kLocalInitialStep, localBudget - kFinalEvaluations, kLocalRestarts);
  polish(Params{}.maxSubIncrement, kFinalInitialStep, kFinalEvaluations, 1);
  r.localEvaluations = ctx.evaluations;
  r.p = rounded(fromScaled(t, x));
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace dabs::calibration
