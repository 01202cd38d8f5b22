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
//        yoshida_calibration check ?-plots dir?         evaluate the shipped sets; fail above
//        bounds yoshida_calibration refit ?hdr|lrb?            rerun the fit; fail unless it prints
//        the
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

#include "verification/bearing/YoshidaFit.h"

namespace {

using namespace dabs::calibration;

void print(const Target& t, const Params& p, const FitError& e, const FitError& dense) {
  std::printf("%s: Y0 %.6g U0 %.6g n %.6g alpha0 %.6g beta %.6g q %.6g gamma %.6g\n", t.name, p.Y0,
              p.U0, p.n, p.alpha0, p.beta, p.q, p.gamma);
  const double s = t.strainUnit;
  std::printf(
      "  fitted amplitudes: Keq error rms %.2f %%, max %.2f %% (at strain %.3g); Heq error "
      "rms %.2f %%, max %.2f %% (at %.3g)\n",
      100 * e.rmsK, 100 * e.maxK, e.atMaxK / s, 100 * e.rmsH, 100 * e.maxH, e.atMaxH / s);
  std::printf(
      "  every 5 %% from 10 %% to 300 %%: Keq max %.2f %% (at %.3g), Heq max %.2f %% (at "
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
        const double fTop = kKd * x + kQd;                        // force at +X
        const double elastic =
            down * (fTop - kK1 * (x - down * ut));     // unloading line from the tip
        const double yielded = kKd * ut - down * kQd;  // post-yield line
        ft = down > 0 ? std::max(elastic, yielded) : std::min(elastic, yielded);
      } else {
        // equivalent linear loop: F = Keq u + Keq 2 Heq sqrt(X^2 - u^2) (sign with the motion)
        ft = g.keq * (ut + 2 * g.heq * x * std::sin(th));
      }
      std::fprintf(f, "%g %g %g %g\n", loop[i][0] / t.strainUnit, loop[i][1], ut / t.strainUnit,
                   ft);
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
  std::fprintf(f,
               "plot '%s-curves.dat' u 1:3 w l lw 2 t '%s', '' u 1:2 w lp pt 7 ps 0.4 t 'model'\n",
               base.c_str(), targetName);
  std::fprintf(f, "set ylabel 'Heq'\nset yrange [0:*]\n");
  std::fprintf(f,
               "plot '%s-curves.dat' u 1:5 w l lw 2 t '%s', '' u 1:4 w lp pt 7 ps 0.4 t 'model'\n",
               base.c_str(), targetName);
  std::fprintf(f, "unset multiplot\nset yrange [*:*]\n");
  std::fprintf(f,
               "set output '%s-loops.png'\nset terminal pngcairo size 760,300 font ',9'\n"
               "set multiplot layout 1,3\nset key bottom right font ',8'\n",
               base.c_str());
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
        f0 = loop[i - 1][1] +
             (loop[i][1] - loop[i - 1][1]) * loop[i - 1][0] / (loop[i - 1][0] - loop[i][0]);
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
  while (cyclicTest(
             p =
                 [&] {
                   Params q = p;
                   q.gamma = hi;
                   return q;
                 }(),
             x)
             .keq < goal)
    hi *= 2.0;
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
    // `-seed s` changes the global stage's random generator (to see the spread of the search).
    const std::string sd = option(argc, argv, "-seed");
    const unsigned long seed = sd.empty() ? kSeed : std::strtoul(sd.c_str(), nullptr, 10);
    for (const Target& t : ts) {
      if (!which.empty() && which != t.key) continue;
      const FitResult r = fit(t, nullptr, kGlobalEvaluations, kLocalEvaluations, seed);
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
    print(ts[0], p, evaluate(ts[0], p, ts[0].amplitudes),
          evaluate(ts[0], p, denseAmplitudes(ts[0])));
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
      const FitResult r = fit(ts[i], nullptr, kGlobalEvaluations, kLocalEvaluations, kSeed);
      const Params& w = sets[i].p;
      const bool same = r.p.Y0 == w.Y0 && r.p.U0 == w.U0 && r.p.n == w.n &&
                        r.p.alpha0 == w.alpha0 && r.p.beta == w.beta && r.p.q == w.q &&
                        r.p.gamma == w.gamma;
      const bool withinBounds = same || withinDocumented(ts[i], r.p, sets[i]);
      std::printf(
          "%s  %s: the fit (%d + %d evaluations, %.1f s) %s\n", withinBounds ? "PASSED" : "FAILED",
          ts[i].name, r.globalEvaluations, r.localEvaluations, r.seconds,
          same ? "reproduces the shipped set"
               : (withinBounds ? "gives another set (below), within the documented bounds"
                               : "gives another set (below), outside the documented bounds"));
      if (!same)
        print(ts[i], r.p, evaluate(ts[i], r.p, ts[i].amplitudes),
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
      std::printf(
          "%s  %s: errors within the documented rms %.1f %% / max %.1f %% (Keq) and rms "
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
