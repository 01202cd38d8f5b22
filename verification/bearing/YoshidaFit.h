// SPDX-License-Identifier: MIT
#pragma once

// The fit of the Yoshida bearing material to a bearing's curves (used by calibrate_yoshida.cpp,
// which describes the method).

#include <array>
#include <functional>
#include <vector>

#include "materials/bearing/YoshidaBearingMaterial.h"

namespace dabs::calibration {

using Params = materials::YoshidaBearingMaterial::Params;
inline constexpr int kNumParams = 7;
inline constexpr unsigned long kSeed = 20261123;  // NLopt's random generator (CRS2-LM population)
inline constexpr int kGlobalEvaluations = 3000;
inline constexpr double kGlobalSubIncrement =
    0.25;  // sub-step (fraction of U0) of the global stage
inline constexpr int kLocalEvaluations = 800;
inline constexpr double kFailureStrain =
    3.0;  // shear strain at which the hardening bound is stated
// (b) Lead-rubber bearing, bilinear: Qd = 150 kN, Kd = 1500 kN/m, K1 = 6.5 Kd, Tr = 0.2 m.
inline constexpr double kQd = 150.0, kKd = 1500.0, kK1 = 6.5 * kKd, kTrLrb = 0.2;
inline constexpr double kUyLrb = kQd / (kK1 - kKd);  // yield displacement of the bilinear loop

struct LoopResult {
  double keq = 0.0, heq = 0.0;
};

/// One fit: its target curve, amplitudes, units and the physical range of each parameter.
struct Target {
  const char* key;  // "hdr" or "lrb"
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

struct FitError {
  double rmsK = 0, maxK = 0, rmsH = 0, maxH = 0, objective = 0;
  double atMaxK = 0, atMaxH = 0;  // amplitudes of the largest errors
};

struct FitResult {
  Params p;
  int globalEvaluations = 0, localEvaluations = 0;
  double seconds = 0.0;
};

/// Six triangular cycles of amplitude `x` along one axis; the last cycle gives Keq and Heq.
/// `loop`, when given, receives the (U, F) points of the last cycle.
LoopResult cyclicTest(const Params& p, double x,
                      std::vector<std::array<double, 2>>* loop = nullptr);
/// Material parameters from the scaled optimiser variables s in [0, 1]^7, and back.
Params fromScaled(const Target& t, const std::vector<double>& s);
std::vector<double> toScaled(const Target& t, const Params& p);
/// Six significant digits: what is printed and shipped.
double round6(double v);
Params rounded(Params p);
/// Errors of Keq and Heq of `p` against the target at `amplitudes`.
FitError evaluate(const Target& t, const Params& p, const std::vector<double>& amplitudes);
/// (a) Bridgestone HDR X0.6 Geq and Heq at shear strain g; (b) the bilinear lead-rubber loop.
LoopResult bridgestoneX06(double g);
LoopResult leadRubber(double x);
/// The two fits: HDR and LRB, with their amplitudes and parameter bounds.
std::vector<Target> targets();
/// Global CRS2-LM (random generator seeded with `seed`) on a coarse integration, then BOBYQA on
/// the shipped integration.
FitResult fit(const Target& t, const std::vector<double>* start, int globalBudget, int localBudget,
              unsigned long seed);

}  // namespace dabs::calibration
