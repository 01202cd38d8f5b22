// SPDX-License-Identifier: MIT
// Benchmarks of the Yoshida bi-axial bearing (speed): material updates per second
// (setTrialStrain + commitState on a circular orbit, with and without the Maxwell part, for several
// deformation increments per step) and yoshidaBearing element updates per second. A counting
// global operator new checks that the timed loops allocate nothing: the counter
// "allocs_per_iter" must be 0, otherwise the benchmark reports an error.
//
// The cost of a material update is proportional to the number of backward Euler sub-steps,
// ceil(|dU| / (maxSubIncrement U0)) with maxSubIncrement = 0.02 by default, so every benchmark is
// run for increments |dU| / U0 = 0.01 (one sub-step), 0.1 (5) and 1.0 (50); the benchmark argument
// is the increment in hundredths of U0. In a time history the increment is |v| dt: an HDR bearing
// with Tr = 0.2 m (U0 = 0.146 Tr = 29 mm) moving at 1 m/s with dt = 0.01 s has |dU|/U0 = 0.34.
//
// Parameter sets: the fitted sets of verification/bearing/fitted-parameters.md, (a) HDR X0.6 per
// unit area and rubber thickness (n = 1) and (b) lead-rubber (kN, m; n = 10). The Maxwell part
// (k, eta) has no fitted values; k = 0.5 Y0/U0 and tau = eta/k = 0.2 s are illustrative only.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <numbers>
#include <vector>

#include "elements/link/YoshidaBearing3d.h"
#include "materials/bearing/YoshidaBearingMaterial.h"

#include "verification/bench/CountingAllocator.h"

namespace {

using namespace dabs;
using materials::YoshidaBearingMaterial;

constexpr double kStepTime = 0.01;     // dt passed to the material/element (s)
constexpr double kMaxwellTau = 0.2;    // illustrative relaxation time eta/k (s)
constexpr double kMaxwellRatio = 0.5;  // illustrative k / (Y0/U0)

/// (a) HDR X0.6 per unit area and unit rubber thickness (MPa, strain).
YoshidaBearingMaterial::Params hdrParams(bool maxwell) {
  YoshidaBearingMaterial::Params p;
  p.Y0 = 0.265147;
  p.U0 = 0.145833;
  p.n = 1.0;
  p.alpha0 = 4.33547;
  p.beta = 3.49049;
  p.q = 0.058481;
  p.gamma = 0.00170082;
  if (maxwell) {
    p.k = kMaxwellRatio * p.Y0 / p.U0;
    p.eta = kMaxwellTau * p.k;
  }
  p.validate();
  return p;
}

/// (b) lead-rubber bearing Qd = 150 kN, Kd = 1500 kN/m (kN, m).
YoshidaBearingMaterial::Params lrbParams(bool maxwell) {
  YoshidaBearingMaterial::Params p;
  p.Y0 = 116.221;
  p.U0 = 0.0209912;
  p.n = 10.0;
  p.alpha0 = 11.2634;
  p.beta = 10.474;
  p.q = 0.0106544;
  p.gamma = 0.0;
  if (maxwell) {
    p.k = kMaxwellRatio * p.Y0 / p.U0;
    p.eta = kMaxwellTau * p.k;
  }
  p.validate();
  return p;
}

/// Orbit of radius 3 U0 (300 % of U0, several times yield), walked so that each step moves by
/// `increment` U0 along the circle: the force lags and the material is always yielding in a
/// turning direction, the worst case for the coupled update.
struct Orbit {
  double radius, dTheta;
  Orbit(double U0, double increment) : radius(3.0 * U0), dTheta(increment / 3.0) {}
  Eigen::Vector2d at(long k) const {
    const double t = dTheta * static_cast<double>(k);
    return {radius * std::cos(t), radius * std::sin(t)};
  }
};

int subSteps(double increment) { return static_cast<int>(std::ceil(increment / 0.02 - 1e-9)); }

void materialBench(benchmark::State& state, const YoshidaBearingMaterial::Params& p) {
  const double increment = 0.01 * static_cast<double>(state.range(0));
  YoshidaBearingMaterial m(1, p);
  const Orbit orbit(p.U0, increment);
  const Eigen::Vector2d rate = Eigen::Vector2d::Zero();
  long k = 0, failures = 0;
  for (int w = 0; w < 200; ++w) {
    if (!ok(m.setTrialStrain(orbit.at(++k), rate, kStepTime))) ++failures;
    m.commitState();
  }
  const long before = gAllocations.load();
  for (auto _ : state) {
    if (!ok(m.setTrialStrain(orbit.at(++k), rate, kStepTime))) ++failures;
    m.commitState();
    benchmark::DoNotOptimize(m.getTangent().data());
  }
  const long allocs = gAllocations.load() - before;
  state.counters["sub_steps"] = subSteps(increment);
  state.counters["updates_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["allocs_per_iter"] =
      static_cast<double>(allocs) / static_cast<double>(state.iterations());
  state.counters["failed_updates"] = static_cast<double>(failures);
  if (allocs != 0) state.SkipWithError("setTrialStrain/commitState allocated memory");
  if (failures != 0) state.SkipWithError("a material update failed");
}

void BM_YoshidaMaterial_HDR(benchmark::State& s) { materialBench(s, hdrParams(false)); }
void BM_YoshidaMaterial_HDR_Maxwell(benchmark::State& s) { materialBench(s, hdrParams(true)); }
void BM_YoshidaMaterial_LRB(benchmark::State& s) { materialBench(s, lrbParams(false)); }
void BM_YoshidaMaterial_LRB_Maxwell(benchmark::State& s) { materialBench(s, lrbParams(true)); }
BENCHMARK(BM_YoshidaMaterial_HDR)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_YoshidaMaterial_HDR_Maxwell)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_YoshidaMaterial_LRB)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_YoshidaMaterial_LRB_Maxwell)->Arg(1)->Arg(10)->Arg(100);

/// yoshidaBearing element, lead-rubber set, Tr = 0.2 m, height 0.3 m (nodes apart, so the
/// shared shear moment is formed), jNode orbiting in global X-Y with a small rocking rotation.
/// Each benchmark iteration is one update (as in a global Newton iteration); every third update is
/// committed, so the material also works from a committed state several updates old.
void elementBench(benchmark::State& state, bool maxwell) {
  const double increment = 0.01 * static_cast<double>(state.range(0));
  const YoshidaBearingMaterial mat(1, lrbParams(maxwell));
  elements::YoshidaBearing3d::Params ep;
  ep.Tr = 0.2;
  ep.Kv = 2.0e6;
  ep.Kt = 500.0;
  ep.Kry = ep.Krz = 8000.0;
  ep.failureLimit = 1e6;  // stay on the material path, no release
  ep.designLimit = 1e6;
  ep.validate();
  elements::YoshidaBearing3d e(1, 1, 2, mat, ep);
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 0.3)});
  const Orbit orbit(mat.params().U0, increment);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(12);
  long k = 0, failures = 0;
  auto step = [&] {
    const Eigen::Vector2d xy = orbit.at(k / 3 + 1);
    u(6) = xy(0);
    u(7) = xy(1);
    u(8) = -1e-4;
    u(9) = 1e-4 * xy(1) / orbit.radius;
    u(10) = -1e-4 * xy(0) / orbit.radius;
    const elements::Kinematics kin{u, zero, zero, 0.0, kStepTime};
    if (!ok(e.update(kin))) ++failures;
    if (k % 3 == 2) e.commitState();
    ++k;
  };
  for (int w = 0; w < 300; ++w) step();
  const long before = gAllocations.load();
  for (auto _ : state) {
    step();
    benchmark::DoNotOptimize(e.tangentStiff().data());
    benchmark::DoNotOptimize(e.resistingForce().data());
  }
  const long allocs = gAllocations.load() - before;
  state.counters["sub_steps"] = subSteps(increment);
  state.counters["updates_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["allocs_per_iter"] =
      static_cast<double>(allocs) / static_cast<double>(state.iterations());
  state.counters["failed_updates"] = static_cast<double>(failures);
  if (allocs != 0) state.SkipWithError("element update/commitState allocated memory");
  if (failures != 0) state.SkipWithError("an element update failed");
}

void BM_YoshidaBearing3d_LRB(benchmark::State& s) { elementBench(s, false); }
void BM_YoshidaBearing3d_LRB_Maxwell(benchmark::State& s) { elementBench(s, true); }
BENCHMARK(BM_YoshidaBearing3d_LRB)->Arg(1)->Arg(10)->Arg(100);
BENCHMARK(BM_YoshidaBearing3d_LRB_Maxwell)->Arg(1)->Arg(10)->Arg(100);

}  // namespace

BENCHMARK_MAIN();
