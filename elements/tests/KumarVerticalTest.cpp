// SPDX-License-Identifier: MIT
// Checks of the vertical law of Kumar, Whittaker and Constantinou (2014) (KumarVertical): the
// properties from the geometry and each branch against the paper's formulas written out here
// from the bearing's dimensions, the tangent (dN/du and dN/duh) against central differences in
// every branch, the damaged cavitation strength, and the validation of the parameters.
#include "elements/link/KumarVertical.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "materials/InputError.h"

namespace dabs::elements {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRel = 1e-12;    // closed forms evaluated the same way up to rounding
constexpr double kFdRel = 1e-6;   // central-difference tangents
constexpr double kFdStep = 1e-7;  // m

// A lead-free circular bearing (kN, m): Do 0.8 m with a 0.1 m hole, 20 layers of 10 mm rubber,
// 3 mm shims, G = 0.8 MPa, K = 2 GPa.
KumarVertical::Params bearing() {
  KumarVertical::Params p;
  p.G = 800.0;
  p.Kbulk = 2.0e6;
  p.Di = 0.1;
  p.Do = 0.8;
  p.ts = 0.003;
  p.tr = 0.01;
  p.n = 20.0;
  p.kc = 20.0;
  p.phi = 0.5;
  p.ac = 1.0;
  return p;
}

// The bearing's properties by hand from its dimensions (Kumar et al. 2014, section 2).
struct Hand {
  double A, r, Tr, h, Ec, Kv0, Fc, Pcr0;
};

Hand hand() {
  const double Do = 0.8, Di = 0.1, G = 800.0, K = 2.0e6, tr = 0.01, ts = 0.003, n = 20.0;
  Hand x{};
  x.A = kPi * (Do * Do - Di * Di) / 4.0;                                  // 0.494801 m^2
  const double I = kPi * (Do * Do * Do * Do - Di * Di * Di * Di) / 64.0;  // annulus
  x.r = std::sqrt(I / x.A);                 // = sqrt(Do^2 + Di^2)/4 for an annulus
  const double S = (Do - Di) / (4.0 * tr);  // 17.5
  const double a = Do / Di;                 // 8
  const double F = (a * a + 1.0) / ((a - 1.0) * (a - 1.0)) + (1.0 + a) / ((1.0 - a) * std::log(a));
  x.Ec = 1.0 / (1.0 / (6.0 * G * S * S * F) + 4.0 / (3.0 * K));
  x.Tr = n * tr;
  x.h = x.Tr + (n - 1.0) * ts;
  x.Kv0 = x.Ec * x.A / x.Tr;
  x.Fc = 3.0 * G * x.A;
  const double Pe = kPi * kPi * (x.Ec / 3.0) * (I * x.h / x.Tr) / (x.h * x.h);
  x.Pcr0 = std::sqrt(Pe * G * x.A * x.h / x.Tr);
  return x;
}

TEST(KumarVerticalTest, PropertiesFollowFromTheGeometry) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  EXPECT_NEAR(law.area(), x.A, kRel * x.A);
  EXPECT_NEAR(law.radiusOfGyration(), std::sqrt(0.8 * 0.8 + 0.1 * 0.1) / 4.0, kRel);
  EXPECT_NEAR(law.Tr(), 0.2, kRel);
  EXPECT_NEAR(law.height(), 0.257, kRel);
  EXPECT_NEAR(law.compressionModulus(), x.Ec, kRel * x.Ec);
  EXPECT_NEAR(law.Kv0(), x.Kv0, kRel * x.Kv0);
  EXPECT_NEAR(law.Fc(), x.Fc, kRel * x.Fc);
  EXPECT_NEAR(law.Pcr0(), x.Pcr0, kRel * x.Pcr0);
  // Without a hole F = 1: Ec = 1/(1/(6 G S^2) + 4/(3K)) with S = D/(4 tr).
  KumarVertical::Params solid = bearing();
  solid.Di = 0.0;
  const double S = 0.8 / 0.04;
  const double ec = 1.0 / (1.0 / (6.0 * 800.0 * S * S) + 4.0 / (3.0 * 2.0e6));
  EXPECT_NEAR(KumarVertical(solid).compressionModulus(), ec, kRel * ec);
}

TEST(KumarVerticalTest, StiffnessFallsWithShearAsInKumarEtAl) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  EXPECT_NEAR(law.stiffness(0.0), x.Kv0, kRel * x.Kv0);
  // At uh = r: Kv = Kv0 / (1 + 3/pi^2).
  EXPECT_NEAR(law.stiffness(x.r), x.Kv0 / (1.0 + 3.0 / (kPi * kPi)), kRel * x.Kv0);
  // At uh = Do/2: Kv = Kv0 / (1 + 3/pi^2 (0.4/r)^2).
  const double k = x.Kv0 / (1.0 + 3.0 / (kPi * kPi) * (0.4 / x.r) * (0.4 / x.r));
  EXPECT_NEAR(law.stiffness(0.4), k, kRel * x.Kv0);
  // The compression force before buckling is Kv(uh) u.
  const auto r = law.evaluate(-0.002, 0.4, {});
  EXPECT_NEAR(r.N, -0.002 * k, kRel * x.Kv0);
  EXPECT_EQ(r.state.branch, 0);
  KumarVertical::Params off = bearing();
  off.kvShear = false;
  EXPECT_NEAR(KumarVertical(off).stiffness(0.4), x.Kv0, kRel * x.Kv0);
}

TEST(KumarVerticalTest, TensionIsLinearToThreeGAThenFollowsThePostCavitationCurve) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  const double uc = x.Fc / x.Kv0;
  const auto below = law.evaluate(0.9 * uc, 0.0, {});
  EXPECT_NEAR(below.N, 0.9 * x.Fc, kRel * x.Fc);
  EXPECT_NEAR(below.dNdu, x.Kv0, kRel * x.Kv0);
  EXPECT_EQ(below.state.branch, 0);
  // Past uc: N = Fc (1 + (1 - exp(-kc (u - uc)))/(kc Tr)), slope Fc/Tr exp(-kc (u - uc)).
  const double kc = 20.0;
  for (double u : {uc * (1.0 + 1e-6), 0.01, 0.05, 0.3}) {
    const auto r = law.evaluate(u, 0.0, {});
    const double e = std::exp(-kc * (u - uc));
    EXPECT_NEAR(r.N, x.Fc * (1.0 + (1.0 - e) / (kc * x.Tr)), kRel * x.Fc) << u;
    EXPECT_NEAR(r.dNdu, x.Fc / x.Tr * e, kRel * x.Kv0) << u;
    EXPECT_EQ(r.state.branch, 1);
    EXPECT_DOUBLE_EQ(r.state.umax, u);
  }
  // The slope just after cavitation is 3GA/Tr, far below Kv0 (the bearing softens).
  EXPECT_LT(x.Fc / x.Tr, 0.01 * x.Kv0);
  // Far out the force tends to Fc (1 + 1/(kc Tr)).
  EXPECT_NEAR(law.evaluate(10.0, 0.0, {}).N, x.Fc * (1.0 + 1.0 / (kc * x.Tr)), 1e-9 * x.Fc);
}

TEST(KumarVerticalTest, UnloadingAfterCavitationGoesThroughTheDamagedStrength) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  const double uc = x.Fc / x.Kv0, kc = 20.0, phi = 0.5, ac = 1.0;
  const double umax = 0.05;
  const auto peak = law.evaluate(umax, 0.0, {});
  // Damaged cavitation force (Kumar et al. 2014): Fcn = Fc (1 - phi (1 - exp(-ac (umax-uc)/uc))).
  const double fcn = x.Fc * (1.0 - phi * (1.0 - std::exp(-ac * (umax - uc) / uc)));
  EXPECT_NEAR(peak.state.cavitationRatio * x.Fc, fcn, kRel * x.Fc);
  // Here (umax - uc)/uc is large, so Fcn is close to (1 - phi) Fc.
  EXPECT_NEAR(fcn, (1.0 - phi) * x.Fc, 1e-6 * x.Fc);

  const double fmax = x.Fc * (1.0 + (1.0 - std::exp(-kc * (umax - uc))) / (kc * x.Tr));
  const double ucn = fcn / x.Kv0;
  const double slope = (fmax - fcn) / (umax - ucn);
  for (double u : {0.04, 0.01, 2.0 * ucn}) {
    const auto r = law.evaluate(u, 0.0, peak.state);
    EXPECT_NEAR(r.N, fcn + slope * (u - ucn), kRel * x.Fc) << u;
    EXPECT_NEAR(r.dNdu, slope, kRel * x.Kv0);
    EXPECT_EQ(r.state.branch, 2);
    EXPECT_DOUBLE_EQ(r.state.umax, umax);  // the history does not move on this path
  }
  // Below ucn the elastic line through the origin; reloading past umax rejoins the curve.
  const auto low = law.evaluate(0.5 * ucn, 0.0, peak.state);
  EXPECT_NEAR(low.N, 0.5 * fcn, kRel * x.Fc);
  EXPECT_EQ(low.state.branch, 0);
  const auto again = law.evaluate(0.08, 0.0, peak.state);
  EXPECT_NEAR(again.N, x.Fc * (1.0 + (1.0 - std::exp(-kc * (0.08 - uc))) / (kc * x.Tr)),
              kRel * x.Fc);
  EXPECT_EQ(again.state.branch, 1);
  // Small excursions show the damage's growth (here the exponent is -1, then -3): a larger
  // excursion damages more, and the damage never heals.
  const auto small = law.evaluate(2.0 * uc, 0.0, {});
  EXPECT_NEAR(small.state.cavitationRatio, 1.0 - phi * (1.0 - std::exp(-1.0)), kRel);
  const auto larger = law.evaluate(4.0 * uc, 0.0, small.state);
  EXPECT_NEAR(larger.state.cavitationRatio, 1.0 - phi * (1.0 - std::exp(-3.0)), kRel);
  EXPECT_DOUBLE_EQ(law.evaluate(0.5 * uc, 0.0, larger.state).state.cavitationRatio,
                   larger.state.cavitationRatio);
}

TEST(KumarVerticalTest, CompressionIsLimitedByTheCriticalLoadOfTheOverlapArea) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  EXPECT_NEAR(law.criticalLoad(0.0), x.Pcr0, kRel * x.Pcr0);
  // At uh = Do/2: d = 2 acos(1/2) = 2 pi/3, Ar/A = (d - sin d)/pi = 2/3 - sqrt(3)/(2 pi).
  const double ratio = 2.0 / 3.0 - std::sqrt(3.0) / (2.0 * kPi);
  EXPECT_NEAR(law.criticalLoad(0.4), ratio * x.Pcr0, kRel * x.Pcr0);
  // Ar/A below 0.2 and uh >= Do: the floor 0.2 Pcr0.
  EXPECT_NEAR(law.criticalLoad(0.7), 0.2 * x.Pcr0, kRel * x.Pcr0);
  EXPECT_NEAR(law.criticalLoad(1.5), 0.2 * x.Pcr0, kRel * x.Pcr0);

  // Past u = -Pcr/Kv the force stays at -Pcr with the small stiffness Kv0/1e4.
  const double kv = law.stiffness(0.4), pcr = ratio * x.Pcr0;
  const double ucr = -pcr / kv;
  const auto r = law.evaluate(ucr - 0.01, 0.4, {});
  EXPECT_NEAR(r.N, -pcr - 1e-4 * x.Kv0 * 0.01, kRel * x.Pcr0);
  EXPECT_NEAR(r.dNdu, 1e-4 * x.Kv0, kRel * x.Kv0);
  EXPECT_EQ(r.state.branch, 3);
  const auto before = law.evaluate(ucr * 0.99, 0.4, {});
  EXPECT_NEAR(before.N, 0.99 * ucr * kv, kRel * x.Pcr0);
  EXPECT_EQ(before.state.branch, 0);
  // Without buckling the line goes on.
  KumarVertical::Params off = bearing();
  off.buckling = false;
  EXPECT_NEAR(KumarVertical(off).evaluate(ucr - 0.01, 0.4, {}).N, kv * (ucr - 0.01), kRel * x.Kv0);
}

// dN/du and dN/duh against central differences at points inside each branch.
TEST(KumarVerticalTest, TangentMatchesFiniteDifferencesInEveryBranch) {
  const KumarVertical law(bearing());
  const Hand x = hand();
  const auto peak = law.evaluate(0.05, 0.2, {});  // a cavitated history (at uh = 0.2)
  struct Point {
    double u, uh;
    KumarVertical::State history;
    int branch;
  };
  const Point points[] = {{0.0004, 0.3, {}, 0},
                          {-0.004, 0.3, {}, 0},
                          {0.02, 0.3, {}, 1},
                          {0.02, 0.05, {}, 1},
                          {0.01, 0.3, peak.state, 2},
                          {0.03, 0.1, peak.state, 2},
                          {0.0002, 0.3, peak.state, 0},
                          {-0.03, 0.3, {}, 3},
                          {-0.03, 0.05, {}, 3},
                          {-0.05, 0.75, {}, 3},
                          {0.0012, 0.3, {0.001, 0.8, 0}, 2}};
  for (const Point& p : points) {
    const auto r = law.evaluate(p.u, p.uh, p.history);
    ASSERT_EQ(r.state.branch, p.branch) << p.u << " " << p.uh;
    const double h = kFdStep;
    const double dNdu =
        (law.evaluate(p.u + h, p.uh, p.history).N - law.evaluate(p.u - h, p.uh, p.history).N) /
        (2 * h);
    const double dNduh =
        (law.evaluate(p.u, p.uh + h, p.history).N - law.evaluate(p.u, p.uh - h, p.history).N) /
        (2 * h);
    EXPECT_NEAR(r.dNdu, dNdu, kFdRel * x.Kv0) << p.u << " " << p.uh;
    EXPECT_NEAR(r.dNduh, dNduh, kFdRel * std::max(std::abs(r.dNduh), x.Fc)) << p.u << " " << p.uh;
  }
}

TEST(KumarVerticalTest, ValidateNamesTheBadParameter) {
  auto field = [](auto change) {
    KumarVertical::Params p = bearing();
    change(p);
    try {
      p.validate();
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string("(none)");
  };
  EXPECT_EQ(field([](auto&) {}), "(none)");
  EXPECT_EQ(field([](auto& p) { p.G = 0.0; }), "G");
  EXPECT_EQ(field([](auto& p) { p.Kbulk = -1.0; }), "Kbulk");
  EXPECT_EQ(field([](auto& p) { p.Di = 0.8; }), "Di");
  EXPECT_EQ(field([](auto& p) { p.Di = -0.1; }), "Di");
  EXPECT_EQ(field([](auto& p) { p.Do = 0.0; }), "Do");
  EXPECT_EQ(field([](auto& p) { p.ts = -0.001; }), "ts");
  EXPECT_EQ(field([](auto& p) { p.tr = 0.0; }), "tr");
  EXPECT_EQ(field([](auto& p) { p.n = 2.5; }), "n");
  EXPECT_EQ(field([](auto& p) { p.n = 0.0; }), "n");
  EXPECT_EQ(field([](auto& p) { p.tc = -0.01; }), "tc");
  EXPECT_EQ(field([](auto& p) { p.kc = 0.0; }), "kc");
  EXPECT_EQ(field([](auto& p) { p.phi = 1.0; }), "phi");
  EXPECT_EQ(field([](auto& p) { p.ac = 0.0; }), "ac");
  EXPECT_EQ(field([](auto& p) { p.G = NAN; }), "G");
}

}  // namespace
}  // namespace dabs::elements
