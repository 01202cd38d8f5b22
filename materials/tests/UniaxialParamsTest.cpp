// SPDX-License-Identifier: MIT
// Params::validate() of every uniaxial material: each bad value throws InputError naming it.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ENT.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/ElasticPPGap.h"
#include "materials/InputError.h"
#include "materials/Parallel.h"
#include "materials/Series.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"
#include "materials/Viscous.h"

namespace dabs::materials {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

template <class P>
std::string rejectedField(const P& p) {
  try {
    p.validate();
  } catch (const InputError& e) {
    return e.field();
  }
  return "<accepted>";
}

TEST(UniaxialParamsTest, Elastic) {
  EXPECT_EQ(rejectedField(Elastic::Params{1.0, 0.0, std::nullopt}), "<accepted>");
  EXPECT_EQ(rejectedField(Elastic::Params{kNaN, 0.0, std::nullopt}), "E");
  EXPECT_EQ(rejectedField(Elastic::Params{1.0, -1.0, std::nullopt}), "eta");
  EXPECT_EQ(rejectedField(Elastic::Params{1.0, 0.0, kNaN}), "Eneg");
}

TEST(UniaxialParamsTest, ElasticPP) {
  EXPECT_EQ(rejectedField(ElasticPP::Params{1.0, 0.01, std::nullopt, 0.0}), "<accepted>");
  EXPECT_EQ(rejectedField(ElasticPP::Params{0.0, 0.01, std::nullopt, 0.0}), "E");
  EXPECT_EQ(rejectedField(ElasticPP::Params{1.0, -0.01, std::nullopt, 0.0}), "epsyP");
  EXPECT_EQ(rejectedField(ElasticPP::Params{1.0, 0.01, 0.01, 0.0}), "epsyN");
  EXPECT_EQ(rejectedField(ElasticPP::Params{1.0, 0.01, std::nullopt, kNaN}), "eps0");
}

TEST(UniaxialParamsTest, ElasticPPGap) {
  EXPECT_EQ(rejectedField(ElasticPPGap::Params{1.0, 1.0, 0.1, 0.0, false}), "<accepted>");
  EXPECT_EQ(rejectedField(ElasticPPGap::Params{-1.0, 1.0, 0.1, 0.0, false}), "E");
  EXPECT_EQ(rejectedField(ElasticPPGap::Params{1.0, 0.0, 0.1, 0.0, false}), "Fy");
  EXPECT_EQ(rejectedField(ElasticPPGap::Params{1.0, 1.0, kNaN, 0.0, false}), "gap");
  EXPECT_EQ(rejectedField(ElasticPPGap::Params{1.0, 1.0, 0.1, 1.0, false}), "eta");
}

TEST(UniaxialParamsTest, Steel01) {
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 0.01}), "<accepted>");
  EXPECT_EQ(rejectedField(Steel01::Params{-400.0, 2e5, 0.01}), "Fy");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 0.0, 0.01}), "E0");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 1.0}), "b");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, -0.05}), "<accepted>");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 0.01, -1.0, 55.0, 0.0, 55.0}), "a1");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 0.01, 0.0, 0.0, 0.0, 55.0}), "a2");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 0.01, 0.0, 55.0, -1.0, 55.0}), "a3");
  EXPECT_EQ(rejectedField(Steel01::Params{400.0, 2e5, 0.01, 0.0, 55.0, 0.0, -5.0}), "a4");
}

TEST(UniaxialParamsTest, Steel02) {
  const Steel02::Params good{400.0, 2e5, 0.01};
  EXPECT_EQ(rejectedField(good), "<accepted>");
  auto with = [&](auto change) {
    Steel02::Params p = good;
    change(p);
    return rejectedField(p);
  };
  EXPECT_EQ(with([](auto& p) { p.Fy = -400.0; }), "Fy");
  EXPECT_EQ(with([](auto& p) { p.E = 0.0; }), "E");
  EXPECT_EQ(with([](auto& p) { p.b = -0.1; }), "b");
  EXPECT_EQ(with([](auto& p) { p.R0 = 0.0; }), "R0");
  EXPECT_EQ(with([](auto& p) { p.cR1 = 1.5; }), "cR1");
  EXPECT_EQ(with([](auto& p) { p.cR2 = 0.0; }), "cR2");
  EXPECT_EQ(with([](auto& p) { p.a1 = -0.1; }), "a1");
  EXPECT_EQ(with([](auto& p) { p.a2 = 0.0; }), "a2");
  EXPECT_EQ(with([](auto& p) { p.a3 = kNaN; }), "a3");
  EXPECT_EQ(with([](auto& p) { p.a4 = -1.0; }), "a4");
  EXPECT_EQ(with([](auto& p) { p.sigInit = 500.0; }), "sigInit");
}

TEST(UniaxialParamsTest, Concrete01) {
  EXPECT_EQ(rejectedField(Concrete01::Params{-30.0, -0.002, -6.0, -0.006}), "<accepted>");
  EXPECT_EQ(rejectedField(Concrete01::Params{30.0, 0.002, 6.0, 0.006}), "<accepted>");
  EXPECT_EQ(rejectedField(Concrete01::Params{0.0, -0.002, -6.0, -0.006}), "fpc");
  EXPECT_EQ(rejectedField(Concrete01::Params{-30.0, 0.0, -6.0, -0.006}), "epsc0");
  EXPECT_EQ(rejectedField(Concrete01::Params{-30.0, -0.002, -40.0, -0.006}), "fpcu");
  // epsU > epsc0 (crushing before the peak)
  EXPECT_EQ(rejectedField(Concrete01::Params{-30.0, -0.002, -6.0, -0.001}), "epsU");
}

TEST(UniaxialParamsTest, Concrete02) {
  const Concrete02::Params good{-30.0, -0.002, -6.0, -0.006, 0.1, 3.0, 1500.0};
  EXPECT_EQ(rejectedField(good), "<accepted>");
  auto with = [&](auto change) {
    Concrete02::Params p = good;
    change(p);
    return rejectedField(p);
  };
  EXPECT_EQ(with([](auto& p) { p.fpc = 30.0; }), "fpc");
  EXPECT_EQ(with([](auto& p) { p.epsc0 = 0.002; }), "epsc0");
  EXPECT_EQ(with([](auto& p) { p.fpcu = 1.0; }), "fpcu");
  EXPECT_EQ(with([](auto& p) { p.epsU = -0.001; }), "epsU");
  EXPECT_EQ(with([](auto& p) { p.lambda = 1.0; }), "lambda");
  EXPECT_EQ(with([](auto& p) { p.ft = -3.0; }), "ft");
  EXPECT_EQ(with([](auto& p) { p.Ets = 0.0; }), "Ets");
}

TEST(UniaxialParamsTest, ViscousAndENT) {
  EXPECT_EQ(rejectedField(Viscous::Params{1.0, 0.5, 1e-11}), "<accepted>");
  EXPECT_EQ(rejectedField(Viscous::Params{-1.0, 0.5, 1e-11}), "C");
  EXPECT_EQ(rejectedField(Viscous::Params{1.0, 0.0, 1e-11}), "alpha");
  EXPECT_EQ(rejectedField(Viscous::Params{1.0, 0.5, 0.0}), "minVel");
  EXPECT_EQ(rejectedField(ENT::Params{1.0}), "<accepted>");
  EXPECT_EQ(rejectedField(ENT::Params{0.0}), "E");
}

TEST(UniaxialParamsTest, ParallelAndSeries) {
  const Elastic a(1, Elastic::Params{1.0, 0.0, std::nullopt});
  EXPECT_EQ(rejectedField(Parallel::Params{{&a}, {}}), "<accepted>");
  EXPECT_EQ(rejectedField(Parallel::Params{{}, {}}), "materials");
  EXPECT_EQ(rejectedField(Parallel::Params{{&a, nullptr}, {}}), "materials");
  EXPECT_EQ(rejectedField(Parallel::Params{{&a, &a}, {1.0}}), "-factors");
  EXPECT_EQ(rejectedField(Series::Params{{&a, &a}}), "<accepted>");
  EXPECT_EQ(rejectedField(Series::Params{{&a}}), "materials");
  Series::Params p{{&a, &a}};
  p.maxIterations = 0;
  EXPECT_EQ(rejectedField(p), "maxIterations");
}

}  // namespace
}  // namespace dabs::materials
