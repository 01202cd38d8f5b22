// SPDX-License-Identifier: MIT
// Benchmarks of the fiber-section piers: section state determination throughput for a
// 200-fiber RC section (fibers per second), element state determination of force- and
// displacement-based 3D beam-columns with 5 Lobatto points, and an elastic 3D beam with a Linear
// transformation. A counting global operator new checks that the timed loops allocate nothing:
// the counter "allocs_per_iter" must be 0, otherwise the benchmark reports an error.
#include <benchmark/benchmark.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <new>
#include <vector>

#include "elements/beam/DispBeamColumn.h"
#include "elements/beam/ElasticBeam3d.h"
#include "elements/beam/ForceBeamColumn.h"
#include "elements/beam/QuadratureIntegration.h"
#include "elements/transform/LinearTransf.h"
#include "materials/Concrete02.h"
#include "materials/Steel02.h"
#include "materials/section/FiberSection.h"
#include "materials/section/geometry/CircPatch.h"
#include "materials/section/geometry/StraightLayer.h"

#include "verification/bench/CountingAllocator.h"

namespace {

using namespace dabs;
using materials::section::FiberSection3d;

/// Circular RC section D = 1.5 m, 200 fibers: core 16 x 8 (128) and cover 16 x 2 (32)
/// annular-sector Concrete02 fibers and 40 Steel02 bars.
struct RcSection {
  materials::Concrete02 core{
      1, materials::Concrete02::Params{-35000.0, -0.0025, -7000.0, -0.02, 0.1, 2800.0, 1.4e6}};
  materials::Concrete02 cover{
      2, materials::Concrete02::Params{-30000.0, -0.002, -6000.0, -0.005, 0.1, 2500.0, 1.2e6}};
  materials::Steel02 steel{3, [] {
                             materials::Steel02::Params p;
                             p.Fy = 420000.0;
                             p.E = 2.0e8;
                             p.b = 0.01;
                             p.R0 = 18.0;
                             return p;
                           }()};
  std::unique_ptr<FiberSection3d> build() const {
    materials::section::FiberList pts;
    materials::section::CircPatch c1;
    c1.materialTag = 1;
    c1.divCirc = 16;
    c1.divRad = 8;
    c1.rExt = 0.7;
    c1.discretize(pts);  // 128
    materials::section::CircPatch c2 = c1;
    c2.materialTag = 2;
    c2.divRad = 2;
    c2.rInt = 0.7;
    c2.rExt = 0.75;
    c2.discretize(pts);  // 32
    materials::section::CircLayer l;
    l.materialTag = 3;
    l.numBars = 40;
    l.barArea = 0.000804;
    l.radius = 0.68;
    l.endAngle = 351.0;
    l.discretize(pts);  // 40
    std::vector<FiberSection3d::Fiber> fibers;
    for (const auto& p : pts) {
      const materials::UniaxialMaterial* m =
          p.materialTag == 1   ? static_cast<const materials::UniaxialMaterial*>(&core)
          : p.materialTag == 2 ? static_cast<const materials::UniaxialMaterial*>(&cover)
                               : &steel;
      fibers.push_back({p.y, p.z, p.area, m});
    }
    return std::make_unique<FiberSection3d>(1, fibers, 1.0e7);
  }
};

/// Cyclic section deformation at step k: curvature amplitude about 5 times yield, with axial
/// compression, so the materials run through loading and unloading branches.
Eigen::Vector4d sectionPath(long k) {
  const double t = 0.01 * static_cast<double>(k % 2000);
  const double amp = 0.015 * std::min(1.0, t / 5.0);
  return {-2.0e-4, amp * std::sin(t), 0.3 * amp * std::cos(1.3 * t), 1e-4 * std::sin(t)};
}

void BM_FiberSection200(benchmark::State& state) {
  RcSection rc;
  auto s = rc.build();
  const int n = s->numFibers();
  long k = 0;
  for (int w = 0; w < 100; ++w) (void)s->setTrialDeformation(sectionPath(k++));
  const long before = gAllocations.load();
  for (auto _ : state) {
    const Status st = s->setTrialDeformation(sectionPath(k));
    benchmark::DoNotOptimize(st);
    if (k % 4 == 0) s->commitState();
    ++k;
    benchmark::DoNotOptimize(s->getStressResultant().data());
  }
  const long allocs = gAllocations.load() - before;
  state.counters["fibers"] = n;
  state.counters["fibers_per_second"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
  state.counters["allocs_per_iter"] =
      static_cast<double>(allocs) / static_cast<double>(state.iterations());
  if (allocs != 0) state.SkipWithError("setTrialDeformation/commitState allocated memory");
}
BENCHMARK(BM_FiberSection200);

template <class Element, bool Force>
std::unique_ptr<Element> makeBeamColumn(const RcSection& rc) {
  elements::QuadratureIntegration rule(1, elements::QuadratureIntegration::Rule::Lobatto, 1, 5);
  std::vector<elements::BeamIntegrationPoint> pts;
  const std::vector<double> xi = rule.locations(8.0), w = rule.weights(8.0);
  for (std::size_t i = 0; i < xi.size(); ++i) pts.push_back({rc.build(), xi[i], w[i]});
  auto t = std::make_unique<elements::LinearTransf3d>(1, Eigen::Vector3d(1.0, 0.0, 0.0));
  std::unique_ptr<Element> e;
  if constexpr (Force)
    e = std::make_unique<Element>(1, 1, 2, std::move(pts), std::move(t), 0.0, 10, 1e-12);
  else
    e = std::make_unique<Element>(1, 1, 2, std::move(pts), std::move(t), 0.0);
  e->initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 8.0)});
  return e;
}

/// Pier top displacement history (cantilever along Z, pushed in X and Y, cyclic, up to 2 % drift).
Eigen::VectorXd elementPath(long k) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  const double t = 0.01 * static_cast<double>(k % 2000);
  const double amp = 0.16 * std::min(1.0, t / 5.0);
  u(6) = amp * std::sin(t);
  u(7) = 0.3 * amp * std::cos(1.3 * t);
  u(8) = -1e-3;
  u(10) = 1.5 * u(6) / 8.0;
  u(9) = -1.5 * u(7) / 8.0;
  return u;
}

template <class Element, bool Force>
void BM_BeamColumn5(benchmark::State& state) {
  RcSection rc;
  auto e = makeBeamColumn<Element, Force>(rc);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(12);
  std::vector<Eigen::VectorXd> path;
  for (long k = 0; k < 2000; ++k) path.push_back(elementPath(k));
  long k = 0, failures = 0;
  auto step = [&] {
    const elements::Kinematics kin{path[static_cast<std::size_t>(k % 2000)], zero, zero, 0.0, 0.0};
    if (!ok(e->update(kin)))
      ++failures;
    else if (k % 4 == 0)
      e->commitState();
    ++k;
  };
  for (int w = 0; w < 50; ++w) step();
  const long before = gAllocations.load();
  for (auto _ : state) {
    step();
    benchmark::DoNotOptimize(e->tangentStiff().data());
  }
  const long allocs = gAllocations.load() - before;
  state.counters["sections"] = 5;
  state.counters["updates_per_second"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["allocs_per_iter"] =
      static_cast<double>(allocs) / static_cast<double>(state.iterations());
  state.counters["failed_updates"] = static_cast<double>(failures);
  if (allocs != 0) state.SkipWithError("element update allocated memory");
}
BENCHMARK(BM_BeamColumn5<elements::ForceBeamColumn3d, true>)->Name("BM_ForceBeamColumn3d_5IP");
BENCHMARK(BM_BeamColumn5<elements::DispBeamColumn3d, false>)->Name("BM_DispBeamColumn3d_5IP");

void BM_ElasticBeam3dLinear(benchmark::State& state) {
  elements::ElasticBeam3d::Params p{0.5, 3.0e7, 1.2e7, 0.05, 0.04, 0.04, 0.0, false};
  elements::ElasticBeam3d e(
      1, 1, 2, p, std::make_unique<elements::LinearTransf3d>(1, Eigen::Vector3d(1, 0, 0)));
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 8.0)});
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(12);
  Eigen::VectorXd u = elementPath(77);
  const long before = gAllocations.load();
  for (auto _ : state) {
    u(6) += 1e-9;
    const elements::Kinematics kin{u, zero, zero, 0.0, 0.0};
    benchmark::DoNotOptimize(e.update(kin));
    benchmark::DoNotOptimize(e.resistingForce().data());
  }
  const long allocs = gAllocations.load() - before;
  state.counters["allocs_per_iter"] =
      static_cast<double>(allocs) / static_cast<double>(state.iterations());
  if (allocs != 0) state.SkipWithError("elastic beam update allocated memory");
}
BENCHMARK(BM_ElasticBeam3dLinear);

}  // namespace

BENCHMARK_MAIN();
