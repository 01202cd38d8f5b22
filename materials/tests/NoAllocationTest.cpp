// SPDX-License-Identifier: MIT
// setTrialStrain + commitState allocate nothing in the steady state (style.md section 10):
// global operator new is replaced by a counting one for this test program.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ENT.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/ElasticPPGap.h"
#include "materials/Fatigue.h"
#include "materials/Parallel.h"
#include "materials/Series.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"
#include "materials/Viscous.h"
#include "materials/tests/MaterialContract.h"

namespace {
std::atomic<long> gAllocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++gAllocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace dabs::materials {
namespace {

long allocationsAlong(UniaxialMaterial& m, const std::vector<double>& path) {
  const long before = gAllocations.load();
  for (std::size_t k = 0; k < path.size(); ++k) {
    if (!ok(m.setTrialStrain(path[k], testing::pathRate(path, k)))) return -1;
    m.commitState();
  }
  return gAllocations.load() - before;
}

TEST(NoAllocationTest, SetTrialStrainAndCommitDoNotAllocate) {
  const Steel01 steel(1, Steel01::Params{400.0, 2.0e5, 0.02});
  const Elastic spring(2, Elastic::Params{4.0e5, 10.0, std::nullopt});
  std::vector<std::unique_ptr<UniaxialMaterial>> all;
  all.push_back(spring.clone());
  all.push_back(std::make_unique<ElasticPP>(3, ElasticPP::Params{2e5, 0.002, std::nullopt, 0.0}));
  all.push_back(
      std::make_unique<ElasticPPGap>(4, ElasticPPGap::Params{2e5, 400.0, 0.001, 0.0, false}));
  all.push_back(steel.clone());
  all.push_back(std::make_unique<Steel02>(5, Steel02::Params{400.0, 2.0e5, 0.01}));
  all.push_back(std::make_unique<Concrete01>(6, Concrete01::Params{-30.0, -0.002, -6.0, -0.006}));
  all.push_back(std::make_unique<Concrete02>(
      7, Concrete02::Params{-30.0, -0.002, -6.0, -0.006, 0.1, 3.0, 1500.0}));
  all.push_back(std::make_unique<Viscous>(8, Viscous::Params{10.0, 0.5, 1e-11}));
  all.push_back(std::make_unique<ENT>(9, ENT::Params{1000.0}));
  all.push_back(std::make_unique<Parallel>(10, Parallel::Params{{&steel, &spring}, {}}));
  all.push_back(std::make_unique<Series>(11, Series::Params{{&steel, &spring}}));
  Fatigue::Params fatigue;
  fatigue.material = &steel;
  fatigue.E0 = 0.012;  // fails along the path (as in FatigueTest): the failed branch is checked too
  fatigue.m = -0.5;
  all.push_back(std::make_unique<Fatigue>(12, fatigue));
  const long beforeClone = gAllocations.load();
  auto probe = steel.clone();  // proves the counting operator new is the one in use
  EXPECT_GT(gAllocations.load() - beforeClone, 0);
  const auto path = testing::cyclicPath(0.002);
  for (auto& m : all) {
    EXPECT_EQ(allocationsAlong(*m, path), 0) << "material tag " << m->tag();
  }
}

}  // namespace
}  // namespace dabs::materials
