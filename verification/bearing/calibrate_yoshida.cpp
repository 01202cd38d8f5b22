// SPDX-License-Identifier: MIT
// Least-squares calibration of the Yoshida et al. (1999) bearing material to
//  (a) the Bridgestone HDR X0.6 empirical curves of equivalent shear modulus Geq(g) and equivalent
//      damping ratio Heq(g), g the shear strain amplitude (the design formulas of Bridgestone for
//      X0.6 at the standard compressive stress, as used by Kikuchi and Aiken's HDR model);
//  (b) a lead-rubber bearing given by its characteristic strength Qd and post-yield stiffness Kd
//      (bilinear idealisation, initial stiffness K1 = 6.5 Kd: an assumed ratio, commonly used
//      for lead-rubber bearings in Japanese highway-bridge practice).
//
// Both fits use the same cyclic test: 6 quasi-static cycles of a triangular deformation history of
// amplitude X (a first quarter to +X, then 12 half cycles), the last cycle measured, with
//   Keq = (F(+X) - F(-X)) / (2X)            Heq = dW / (2 pi Keq X^2)
// (dW the loop area: the usual equivalent viscous damping ratio). The curves carry no rate
// information, so the Maxwell part (k, eta) is not identifiable from them and is left off.
//
// The optimiser is NLopt (Johnson, "The NLopt nonlinear-optimization package"): every parameter
// is bounded to its physical range (targets() below; reasons in fitted-parameters.md), a global
// stage (controlled random search with local mutation, CRS2-LM, Kaelo and Ali 2006, fixed seed)
// on a coarser integration of the material, then a restarted gradient-free polish (BOBYQA,
// Powell 2009), its last round on the material exactly as shipped. The objective is the sum of
// squared relative errors of Keq and Heq.
//
// Usage: yoshida_calibration fit ?hdr|lrb? ?-plots dir? ?-seed s?   fit and print the sets
//        yoshida_calibration check ?-plots dir?         evaluate the shipped sets; fail above bounds
//        yoshida_calibration refit ?hdr|lrb?            rerun the fit; fail unless it prints the
//                                                       shipped sets digit for digit
//        yoshida_calibration stiffen                    HDR set with gamma raised to the target
//                                                       Geq at 300 % (bridge sensitivity case)
//        yoshida_calibration eval hdr|lrb Y0 U0 n alpha0 beta q gamma   errors of any set
#include <nlopt.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "materials/bearing/YoshidaBearingMaterial.h"

namespace {

using dabs::materials::YoshidaBearingMaterial;
using Params = YoshidaBearingMaterial::Params;
constexpr int kNumParams = 7;
constexpr unsigned long kSeed = 20261123;  // NLopt's random generator (CRS2-LM population)
unsigned long seed = kSeed;                 // `fit -seed s` changes it (spread of the search)
constexpr double kGlobalSubIncrement = 0.25;  // sub-step (fraction of U0) of the global stage
constexpr int kGlobalEvaluations = 3000;
constexpr int kLocalEvaluations = 800;
constexpr double kLocalXtol = 1e-4;   // BOBYQA: step in the scaled variables [0, 1]
constexpr double kLocalFtol = 1e-7;   // BOBYQA: relative change of the objective
constexpr int kLocalRestarts = 6;
constexpr double kLocalInitialStep = 0.02;  // BOBYQA's first trust region (scaled variables)
constexpr double kPolishSubIncrement = 0.05;  // sub-step (fraction of U0) of the restarts
constexpr int kFinalEvaluations = 150;        // last BOBYQA round, on the shipped sub-step
constexpr double kFinalInitialStep = 0.002;
constexpr double kFailureStrain = 3.0;  // shear strain at which the hardening bound is stated

struct LoopResult {
  double keq = 0.0, heq = 0.0;
};

/// Six triangular cycles of amplitude `x` along one axis; the last cycle gives Keq and Heq.
/// `loop`, when given, receives the (U, F) points of the last cycle.
LoopResult cyclicTest(const Params& p, double x, std::vector<std::array<double, 2>>* loop = nullptr) {
  YoshidaBearingMaterial m(1, p);
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

/// One fit: its target curve, amplitudes, units and the physical range of each parameter.
struct Target {
  const char* key;   // "hdr" or "lrb"
  const char* name;
  std::vector<double> amplitudes;
  std::function<LoopResult(double)> curve;
  double strainUnit;  // deformation per unit shear strain (1 for stress-strain, Tr for a bearing)
  // Bounds of the optimiser's variables, in this order: Y0, U0, n (these three searched on a log
  // scale), A0 = alpha0 - beta (back-force factor at first yield, Umax = U0), r = a(Uf)/A0 (the
  // fraction of it left at the failure deformation Uf = 3 Tr; r < 0: a reaches zero before Uf),
  // q (log scale), H = Y(Uf)/Y0 - 1 = gamma (Uf/U0)^2 (hardening at the failure strain).
  // A0 and r instead of alpha0 and beta: with the small q of these fits alpha0 and beta are
  // almost perfectly correlated (a is nearly alpha0 - beta - beta q ln(Umax/U0)).
  std::array<double, kNumParams> lo, hi;
};

constexpr std::array<bool, kNumParams> kLogScale = {true, true, true, false, false, true, false};

/// Material parameters from the scaled optimiser variables s in [0, 1]^7.
Params fromScaled(const Target& t, const std::vector<double>& s) {
  std::array<double, kNumParams> v{};
  for (int i = 0; i < kNumParams; ++i) {
    const double w = std::clamp(s[i], 0.0, 1.0);
    v[i] = kLogScale[i] ? t.lo[i] * std::pow(t.hi[i] / t.lo[i], w) : t.lo[i] + w * (t.hi[i] - t.lo[i]);
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

struct FitError {
  double rmsK = 0, maxK = 0, rmsH = 0, maxH = 0, objective = 0;
  double atMaxK = 0, atMaxH = 0;  // amplitudes of the largest errors
};

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

// (b) Lead-rubber bearing, bilinear: Qd = 150 kN, Kd = 1500 kN/m, K1 = 6.5 Kd, Tr = 0.2 m.
constexpr double kQd = 150.0, kKd = 1500.0, kK1 = 6.5 * kKd, kTrLrb = 0.2;
constexpr double kUyLrb = kQd / (kK1 - kKd);  // yield displacement of the bilinear loop
LoopResult leadRubber(double x) {
  LoopResult r;
  r.keq = kKd + kQd / x;                                  // secant through (X, Qd + Kd X)
  const double loop = 4.0 * kQd * (x - kUyLrb);           // area of the bilinear loop
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

struct FitResult {
  Params p;
  int globalEvaluations = 0, localEvaluations = 0;
  double seconds = 0.0;
};

/// Global CRS2-LM on a coarse integration, then BOBYQA on the shipped integration.
FitResult fit(const Target& t, const std::vector<double>* start, int globalBudget, int localBudget) {
  FitResult r;
  struct Context {
    const Target* t;
    const std::vector<double>* amplitudes;
    double subIncrement;
    int evaluations;
    double bestF;               // best of the local stage so far, and where
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

void print(const Target& t, const Params& p, const FitError& e, const FitError& dense) {
  std::printf("%s: Y0 %.6g U0 %.6g n %.6g alpha0 %.6g beta %.6g q %.6g gamma %.6g\n", t.name, p.Y0,
              p.U0, p.n, p.alpha0, p.beta, p.q, p.gamma);
  const double s = t.strainUnit;
  std::printf("  fitted amplitudes: Keq error rms %.2f %%, max %.2f %% (at strain %.3g); Heq error "
              "rms %.2f %%, max %.2f %% (at %.3g)\n",
              100 * e.rmsK, 100 * e.maxK, e.atMaxK / s, 100 * e.rmsH, 100 * e.maxH, e.atMaxH / s);
  std::printf("  every 5 %% from 10 %% to 300 %%: Keq max %.2f %% (at %.3g), Heq max %.2f %% (at "
              "%.3g)\n",
              100 * dense.maxK, dense.atMaxK / s, 100 * dense.maxH, dense.atMaxH / s);
  const std::vector<double> sc = toScaled(t, p);
  const char* names[kNumParams] = {"Y0", "U0", "n", "A0", "r", "q", "H"};
  std::string active;
  for (int i = 0; i < kNumParams; ++i)
    if (sc[i] < 1e-4 || sc[i] > 1 - 1e-4)
      active += std::string(" ") + names[i] + (sc[i] < 0.5 ? "(lower)" : "(upper)");
  std::printf("  parameters on a bound:%s\n", active.empty() ? " none" : active.c_str());
  std::printf("  Tcl: biaxialMaterial Yoshida tag %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n", p.Y0, p.U0,
              p.n, p.alpha0, p.beta, p.q, p.gamma);
}

void printTable(const Target& t, const Params& p) {
  std::printf("  strain  Keq model  Keq target  error %%   Heq model  Heq target  error %%\n");
  for (double x : t.amplitudes) {
    const LoopResult m = cyclicTest(p, x), g = t.curve(x);
    std::printf("  %6.3f %10.5g %10.5g %8.2f %10.4f %10.4f %8.2f\n", x / t.strainUnit, m.keq, g.keq,
                100 * (m.keq / g.keq - 1), m.heq, g.heq, 100 * (m.heq / g.heq - 1));
  }
}

/// Writes the data and a gnuplot script for: Keq and Heq against shear strain (model and
/// target), and the loops at 100, 200 and 300 % over the target loop (the bilinear loop for (b),
/// the equivalent linear ellipse with the target's Keq and Heq for (a)); runs gnuplot.
void writePlots(const Target& t, const Params& p, const std::string& dir) {
  const std::string base = dir + "/" + t.key;
  {
    FILE* f = std::fopen((base + "-curves.dat").c_str(), "w");
    if (!f) return;
    std::fprintf(f, "# strain Keq_model Keq_target Heq_model Heq_target\n");
    for (double g = 0.1; g <= 3.0 + 1e-9; g += 0.05) {
      const double x = g * t.strainUnit;
      const LoopResult m = cyclicTest(p, x), tg = t.curve(x);
      std::fprintf(f, "%g %g %g %g %g\n", g, m.keq, tg.keq, m.heq, tg.heq);
    }
    std::fclose(f);
  }
  for (int pct : {100, 200, 300}) {
    const double x = pct / 100.0 * t.strainUnit;
    std::vector<std::array<double, 2>> loop;
    cyclicTest(p, x, &loop);
    FILE* f = std::fopen((base + "-loop" + std::to_string(pct) + ".dat").c_str(), "w");
    if (!f) return;
    std::fprintf(f, "# strain force_model strain force_target\n");
    const LoopResult g = t.curve(x);
    const std::size_t n = loop.size();
    for (std::size_t i = 0; i < n; ++i) {
      // target loop sampled at the same number of points, starting at +X going down
      const double th = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n - 1);
      double ut = x * std::cos(th), ft = 0.0;
      if (std::strcmp(t.key, "lrb") == 0) {
        // bilinear loop: upper branch (unloading side) and lower branch as function of u
        const double down = th <= std::numbers::pi ? 1.0 : -1.0;  // 1: from +X to -X
        const double fTop = kKd * x + kQd;                           // force at +X
        const double elastic = down * (fTop - kK1 * (x - down * ut));  // unloading line from the tip
        const double yielded = kKd * ut - down * kQd;               // post-yield line
        ft = down > 0 ? std::max(elastic, yielded) : std::min(elastic, yielded);
      } else {
        // equivalent linear loop: F = Keq u + Keq 2 Heq sqrt(X^2 - u^2) (sign with the motion)
        ft = g.keq * (ut + 2 * g.heq * x * std::sin(th));
      }
      std::fprintf(f, "%g %g %g %g\n", loop[i][0] / t.strainUnit, loop[i][1], ut / t.strainUnit, ft);
    }
    std::fclose(f);
  }
  const std::string script = base + ".gp";
  FILE* f = std::fopen(script.c_str(), "w");
  if (!f) return;
  const bool lrb = std::strcmp(t.key, "lrb") == 0;
  const char* unitK = lrb ? "Keq (kN/m)" : "Geq (MPa)";
  const char* unitF = lrb ? "shear force (kN)" : "shear stress (MPa)";
  const char* targetName = lrb ? "bilinear target" : "target (Bridgestone X0.6)";
  const char* loopTarget = lrb ? "bilinear target" : "target (equiv. linear)";
  std::fprintf(f, "set terminal pngcairo size 760,330 font ',9'\nset grid\nset key top right\n");
  std::fprintf(f, "set output '%s-curves.png'\nset multiplot layout 1,2\n", base.c_str());
  std::fprintf(f, "set xlabel 'shear strain amplitude'\nset ylabel '%s'\n", unitK);
  std::fprintf(f, "plot '%s-curves.dat' u 1:3 w l lw 2 t '%s', '' u 1:2 w lp pt 7 ps 0.4 t 'model'\n",
               base.c_str(), targetName);
  std::fprintf(f, "set ylabel 'Heq'\nset yrange [0:*]\n");
  std::fprintf(f, "plot '%s-curves.dat' u 1:5 w l lw 2 t '%s', '' u 1:4 w lp pt 7 ps 0.4 t 'model'\n",
               base.c_str(), targetName);
  std::fprintf(f, "unset multiplot\nset yrange [*:*]\n");
  std::fprintf(f, "set output '%s-loops.png'\nset terminal pngcairo size 760,300 font ',9'\n"
               "set multiplot layout 1,3\nset key bottom right font ',8'\n", base.c_str());
  for (int pct : {100, 200, 300}) {
    std::fprintf(f, "set title '%d %%'\nset xlabel 'shear strain'\nset ylabel '%s'\n", pct, unitF);
    std::fprintf(f, "plot '%s-loop%d.dat' u 3:4 w l lw 2 t '%s', '' u 1:2 w l t 'model'\n",
                 base.c_str(), pct, pct == 100 ? loopTarget : "");
  }
  std::fprintf(f, "unset multiplot\n");
  std::fclose(f);
  const std::string cmd = "gnuplot '" + script + "'";
  if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "gnuplot failed on %s\n", script.c_str());
}

// Shipped sets (fitted-parameters.md), in the order of targets(), with the error bounds (in %,
// the errors of the set rounded up) documented there.
struct Shipped {
  Params p;
  double rmsK, maxK, rmsH, maxH;
};

std::vector<Shipped> shipped() {
  Params hdr;
  hdr.Y0 = 0.435794;
  hdr.U0 = 0.0683367;
  hdr.n = 0.115167;
  hdr.alpha0 = 0.831926;
  hdr.beta = 0.698464;
  hdr.q = 0.0393774;
  hdr.gamma = 0.000947439;
  Params lrb;
  lrb.Y0 = 178.979;
  lrb.U0 = 0.018842;
  lrb.n = 19.9935;
  lrb.alpha0 = 0.189001;
  lrb.beta = 0.000226503;
  lrb.q = 1.03444;
  lrb.gamma = 3.16031e-05;
  return {{hdr, 2.0, 3.5, 2.4, 4.2}, {lrb, 0.3, 0.6, 0.4, 0.8}};
}

std::string option(int argc, char** argv, const char* name) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  return "";
}

}  // namespace

/// Loop shape, not fitted: the force at zero deformation on the unloading branch over the peak
/// force, model and the X0.6 design formula u(g) = 0.44236 - 0.062943 g - 0.0037571 g^2
/// (Bridgestone's, the one Kikuchi and Aiken's HDR model takes; OpenSees KikuchiAikenHDR).
void printLoopShape(const Target& t, const Params& p) {
  if (std::strcmp(t.key, "hdr") != 0) return;
  std::printf("  force at zero strain / peak force (loop shape, not fitted):");
  for (double g : {1.0, 2.0, 3.0}) {
    std::vector<std::array<double, 2>> loop;
    cyclicTest(p, g, &loop);
    double f0 = 0.0, fmax = 0.0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
      fmax = std::max(fmax, loop[i][1]);
      if (loop[i - 1][0] > 0.0 && loop[i][0] <= 0.0)  // unloading branch crosses U = 0
        f0 = loop[i - 1][1] + (loop[i][1] - loop[i - 1][1]) * loop[i - 1][0] / (loop[i - 1][0] - loop[i][0]);
    }
    std::printf(" %.0f %%: model %.3f, X0.6 %.3f;", 100 * g, -f0 / fmax,
                0.44236 - 0.062943 * g - 0.0037571 * g * g);
  }
  std::printf("\n");
}

/// Amplitudes every 5 % of shear strain from 10 % to 300 %: the errors between the fitted points.
std::vector<double> denseAmplitudes(const Target& t) {
  std::vector<double> a;
  for (int pct = 10; pct <= 300; pct += 5) a.push_back(pct / 100.0 * t.strainUnit);
  return a;
}

/// The documented bounds: rms on the fitted amplitudes, largest error every 5 % of strain.
bool withinDocumented(const Target& t, const Params& p, const Shipped& bound) {
  const FitError e = evaluate(t, p, t.amplitudes), d = evaluate(t, p, denseAmplitudes(t));
  return 100 * e.rmsK <= bound.rmsK && 100 * d.maxK <= bound.maxK && 100 * e.rmsH <= bound.rmsH &&
         100 * d.maxH <= bound.maxH;
}

const Target* findTarget(const std::vector<Target>& ts, const std::string& key) {
  for (const Target& t : ts)
    if (key == t.key) return &t;
  return nullptr;
}

/// The HDR set with its hardening raised until Geq at 300 % equals the target's (bisection on
/// gamma): the sensitivity case "as stiff as the rubber at 300 %".
Params stiffened(const Target& t, Params p) {
  const double x = kFailureStrain * t.strainUnit, goal = t.curve(x).keq;
  double lo = p.gamma, hi = std::max(p.gamma, 1e-6);
  while (cyclicTest(p = [&] { Params q = p; q.gamma = hi; return q; }(), x).keq < goal) hi *= 2.0;
  for (int it = 0; it < 60; ++it) {
    p.gamma = 0.5 * (lo + hi);
    (cyclicTest(p, x).keq < goal ? lo : hi) = p.gamma;
  }
  p.gamma = round6(hi);
  return p;
}

int main(int argc, char** argv) {
  const std::vector<Target> ts = targets();
  const std::string mode = argc > 1 ? argv[1] : "";
  const std::string which = (argc > 2 && argv[2][0] != '-') ? argv[2] : "";
  const std::string plots = option(argc, argv, "-plots");
  const std::vector<Shipped> sets = shipped();
  if (mode == "fit") {
    if (const std::string sd = option(argc, argv, "-seed"); !sd.empty())
      seed = std::strtoul(sd.c_str(), nullptr, 10);
    for (const Target& t : ts) {
      if (!which.empty() && which != t.key) continue;
      const FitResult r = fit(t, nullptr, kGlobalEvaluations, kLocalEvaluations);
      print(t, r.p, evaluate(t, r.p, t.amplitudes), evaluate(t, r.p, denseAmplitudes(t)));
      std::printf("  %d global (sub-step %.2g U0) + %d local evaluations, %.1f s\n",
                  r.globalEvaluations, kGlobalSubIncrement, r.localEvaluations, r.seconds);
      printTable(t, r.p);
      if (!plots.empty()) writePlots(t, r.p, plots);
    }
    return 0;
  }
  if (mode == "eval" && argc >= 10 && findTarget(ts, which)) {
    const Target& t = *findTarget(ts, which);
    Params p;
    double* fields[] = {&p.Y0, &p.U0, &p.n, &p.alpha0, &p.beta, &p.q, &p.gamma};
    for (int i = 0; i < kNumParams; ++i) *fields[i] = std::strtod(argv[3 + i], nullptr);
    const std::string sub = option(argc, argv, "-subIncrement");
    if (!sub.empty()) p.maxSubIncrement = std::strtod(sub.c_str(), nullptr);
    try {
      p.validate();
    } catch (const std::exception& e) {
      std::printf("invalid parameters: %s\n", e.what());
      return 2;
    }
    print(t, p, evaluate(t, p, t.amplitudes), evaluate(t, p, denseAmplitudes(t)));
    printTable(t, p);
    if (!plots.empty()) writePlots(t, p, plots);
    return 0;
  }
  if (mode == "stiffen") {
    const Params p = stiffened(ts[0], sets[0].p);
    std::printf("gamma raised until Geq(300 %%) = target:\n");
    print(ts[0], p, evaluate(ts[0], p, ts[0].amplitudes), evaluate(ts[0], p, denseAmplitudes(ts[0])));
    printTable(ts[0], p);
    return 0;
  }
  if (mode == "refit") {
    // The whole fit (fixed seed) must print the shipped sets digit for digit. A polish started
    // away from a shipped set does not come back to within the optimiser's tolerance: the
    // objectives are flat along some directions (e.g. q of the lead-rubber set, whose beta is
    // almost zero), so the fit is checked for reproducibility, not for a unique minimum. glibc
    // picks its pow() by CPU (FMA variants), which may change the last bits and so the search
    // path: a different set that still meets the documented error bounds passes with a note.
    int failed = 0;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      if (!which.empty() && which != ts[i].key) continue;
      const FitResult r = fit(ts[i], nullptr, kGlobalEvaluations, kLocalEvaluations);
      const Params& w = sets[i].p;
      const bool same = r.p.Y0 == w.Y0 && r.p.U0 == w.U0 && r.p.n == w.n && r.p.alpha0 == w.alpha0 &&
                        r.p.beta == w.beta && r.p.q == w.q && r.p.gamma == w.gamma;
      const bool withinBounds = same || withinDocumented(ts[i], r.p, sets[i]);
      std::printf("%s  %s: the fit (%d + %d evaluations, %.1f s) %s\n",
                  withinBounds ? "PASSED" : "FAILED", ts[i].name, r.globalEvaluations,
                  r.localEvaluations, r.seconds,
                  same ? "reproduces the shipped set"
                       : (withinBounds ? "gives another set (below), within the documented bounds"
                                       : "gives another set (below), outside the documented bounds"));
      if (!same) print(ts[i], r.p, evaluate(ts[i], r.p, ts[i].amplitudes),
                       evaluate(ts[i], r.p, denseAmplitudes(ts[i])));
      failed += withinBounds ? 0 : 1;
    }
    return failed > 0 ? 1 : 0;
  }
  if (mode == "check") {
    int failed = 0;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      sets[i].p.validate();
      print(ts[i], sets[i].p, evaluate(ts[i], sets[i].p, ts[i].amplitudes),
            evaluate(ts[i], sets[i].p, denseAmplitudes(ts[i])));
      printLoopShape(ts[i], sets[i].p);
      const bool pass = withinDocumented(ts[i], sets[i].p, sets[i]);
      std::printf("%s  %s: errors within the documented rms %.1f %% / max %.1f %% (Keq) and rms "
                  "%.1f %% / max %.1f %% (Heq)\n",
                  pass ? "PASSED" : "FAILED", ts[i].name, sets[i].rmsK, sets[i].maxK, sets[i].rmsH,
                  sets[i].maxH);
      failed += pass ? 0 : 1;
      if (!plots.empty()) writePlots(ts[i], sets[i].p, plots);
    }
    return failed > 0 ? 1 : 0;
  }
  std::printf(
      "usage: yoshida_calibration fit ?hdr|lrb? ?-plots dir? ?-seed s?\n"
      "       yoshida_calibration check ?-plots dir?\n"
      "       yoshida_calibration refit ?hdr|lrb?\n"
      "       yoshida_calibration stiffen\n"
      "       yoshida_calibration eval hdr|lrb Y0 U0 n alpha0 beta q gamma ?-subIncrement s? "
      "?-plots dir?\n");
  return 2;
}
