// SPDX-License-Identifier: MIT
// Fiber sections and their geometry: closed-form moment-curvature of an elastic-perfectly-plastic
// rectangle, discretised section properties, FD tangent, commit/revert, patch and layer layouts.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <random>
#include <tuple>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ENT.h"
#include "materials/FourLanes.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/Steel02.h"
#include "materials/InputError.h"
#include "materials/section/FiberSection.h"
#include "materials/section/geometry/CircPatch.h"
#include "materials/section/geometry/QuadPatch.h"
#include "materials/section/geometry/StraightLayer.h"

namespace dabs::materials::section {
namespace {

constexpr double kE = 2.0e8, kFy = 4.0e5, kB = 0.3, kH = 0.5;
constexpr int kN = 400;          // fibers through the depth
constexpr double kFdTol = 1e-6;  // finite-difference tangent, relative
constexpr double kMpTol = 1e-4;  // discretisation error of the plastic moment (O(1/n^2))

ElasticPP epp() {
  ElasticPP::Params p;
  p.E = kE;
  p.epsyP = kFy / kE;
  p.validate();
  return ElasticPP(1, p);
}

/// Concrete and bars of the mixed sections below (tags 1 and 2).
Concrete02 concrete02() {
  return Concrete02(1, Concrete02::Params::withDefaults(-30e3, -0.002, -6e3, -0.006));
}
Steel02 steel02() {
  Steel02::Params p;
  p.Fy = 4e5;
  p.E = 2e8;
  p.b = 0.01;
  return Steel02(2, p);
}

template <int Ndm>
FiberSection<Ndm> rectangle(const UniaxialMaterial& mat, double gj = 0.0) {
  FiberList pts;
  QuadPatch::rect(1, kN, 3, -kH / 2, -kB / 2, kH / 2, kB / 2).discretize(pts);
  std::vector<typename FiberSection<Ndm>::Fiber> fibers;
  for (const auto& p : pts) fibers.push_back({p.y, p.z, p.area, &mat});
  return FiberSection<Ndm>(1, fibers, gj);
}

TEST(FiberSectionTest, ElasticPlasticRectangleMomentCurvature) {
  // M = Mp [1 - (1/3)(phi_y/phi)^2] for phi >= phi_y, Mp = fy b h^2/4, phi_y = 2 eps_y/h
  // (e.g. Gere & Timoshenko, Mechanics of Materials, sec. 6.10).
  const ElasticPP mat = epp();
  auto sec = rectangle<2>(mat);
  const double mp = kFy * kB * kH * kH / 4, phiY = 2 * kFy / kE / kH;
  for (double ratio : {1.5, 2.0, 4.0, 10.0}) {
    Eigen::Vector2d e(0.0, ratio * phiY);
    ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
    EXPECT_NEAR(sec.getStressResultant()(1), mp * (1 - 1.0 / (3 * ratio * ratio)), kMpTol * mp);
    EXPECT_NEAR(sec.getStressResultant()(0), 0.0, 1e-9 * kFy * kB * kH);
    // Tangent: only the elastic core (depth h phi_y/phi) contributes: E b (h/ratio)^3 / 12.
    const double core = kH / ratio;
    EXPECT_NEAR(sec.getSectionTangent()(1, 1), kE * kB * std::pow(core, 3) / 12,
                2e-2 * kE * kB * std::pow(core, 3) / 12);
  }
}

TEST(FiberSectionTest, ElasticPropertiesOfDiscretisedRectangle) {
  Elastic::Params p;
  p.E = kE;
  const Elastic mat(2, p);
  const double gj = 1234.0;
  auto sec = rectangle<3>(mat, gj);
  const Eigen::MatrixXd k = sec.getInitialTangent();
  // Midpoint rule over n equal strips: sum A y^2 = b h^3/12 (1 - 1/n^2).
  EXPECT_NEAR(k(0, 0), kE * kB * kH, 1e-9 * kE * kB * kH);
  EXPECT_NEAR(k(1, 1), kE * kB * std::pow(kH, 3) / 12 * (1 - 1.0 / (kN * kN)), 1e-9 * k(1, 1));
  EXPECT_NEAR(k(2, 2), kE * kH * std::pow(kB, 3) / 12 * (1 - 1.0 / 9), 1e-9 * k(2, 2));
  EXPECT_NEAR(k(3, 3), gj, 1e-12);
  EXPECT_NEAR(k(0, 1), 0.0, 1e-6 * k(0, 0));
}

TEST(FiberSectionTest, TangentMatchesFiniteDifferences3d) {
  const ElasticPP mat = epp();
  auto sec = rectangle<3>(mat, 500.0);
  Eigen::Vector4d e(2e-4, 0.012, -0.02, 0.003);
  ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
  const Eigen::MatrixXd k = sec.getSectionTangent();
  Eigen::Matrix4d kfd;
  for (int j = 0; j < 4; ++j) {
    const double h = 1e-8;
    Eigen::Vector4d ep = e, em = e;
    ep(j) += h;
    em(j) -= h;
    ASSERT_TRUE(ok(sec.setTrialDeformation(ep)));
    const Eigen::VectorXd sp = sec.getStressResultant();
    ASSERT_TRUE(ok(sec.setTrialDeformation(em)));
    kfd.col(j) = (sp - sec.getStressResultant()) / (2 * h);
  }
  // Fibers crossing a yield point inside +-h make FD differ; with 1200 fibers the share is small.
  EXPECT_LT((k - kfd).norm() / k.norm(), 1e-2);
  // Away from kinks (elastic state) the match is tight.
  ASSERT_TRUE(ok(sec.setTrialDeformation(Eigen::Vector4d(1e-5, 1e-4, -1e-4, 1e-3))));
  EXPECT_LT((sec.getSectionTangent() - sec.getInitialTangent()).norm() / k.norm(), kFdTol);
}

TEST(FiberSectionTest, CommitRevertAndClone) {
  const ElasticPP mat = epp();
  auto sec = rectangle<2>(mat);
  const double phiY = 2 * kFy / kE / kH;
  ASSERT_TRUE(ok(sec.setTrialDeformation(Eigen::Vector2d(0.0, 3 * phiY))));
  sec.commitState();
  ASSERT_TRUE(ok(sec.setTrialDeformation(Eigen::Vector2d(0.0, 0.0))));
  const double residual = sec.getStressResultant()(1);  // unloaded elastically from 3 phi_y
  EXPECT_LT(residual, 0.0);
  auto copy = sec.clone();
  sec.revertToLastCommit();
  const double mp = kFy * kB * kH * kH / 4;
  EXPECT_NEAR(sec.getStressResultant()(1), mp * (1 - 1.0 / 27), kMpTol * mp);
  EXPECT_NEAR(copy->getStressResultant()(1), residual, 1e-9 * mp);
  sec.revertToStart();
  EXPECT_EQ(sec.getStressResultant().norm(), 0.0);
}

TEST(FiberSectionTest, UnsymmetricSectionAboutItsAreaCentroid) {
  // Two fibers of one elastic material: A = 2 at y = 0.2 and A = 1 at y = -0.2 (z = 0.1 and
  // -0.3 in 3D). About the area centroid yBar = (2 0.2 - 0.2) / 3 = 1/15 (zBar = (0.2 - 0.3) / 3)
  // an axial strain gives no moment; about y = 0 it gives Mz = -E (2 0.2 - 0.2) eps.
  Elastic::Params ep;
  ep.E = kE;
  const Elastic mat(1, ep);
  using F2 = FiberSection<2>::Fiber;
  const std::vector<F2> fibers{{0.2, 0.1, 2.0, &mat}, {-0.2, -0.3, 1.0, &mat}};
  const FiberSection<2> about(1, fibers, 0.0, true), given(1, fibers, 0.0, false);
  const double yBar = 1.0 / 15.0;
  EXPECT_NEAR(about.centroidY(), yBar, 1e-15);
  EXPECT_EQ(given.centroidY(), 0.0);
  const Eigen::MatrixXd k = about.getInitialTangent(), k0 = given.getInitialTangent();
  EXPECT_NEAR(k(0, 0), 3.0 * kE, 1e-6);
  EXPECT_NEAR(k(0, 1), 0.0, 1e-6);
  const double iz = 2.0 * (0.2 - yBar) * (0.2 - yBar) + (-0.2 - yBar) * (-0.2 - yBar);
  EXPECT_NEAR(k(1, 1), kE * iz, 1e-6);
  EXPECT_NEAR(k0(0, 1), -kE * (2.0 * 0.2 - 0.2), 1e-6);
  EXPECT_NEAR(k0(1, 1), kE * (2.0 * 0.04 + 0.04), 1e-6);
  // The fibers keep their given coordinates for responses.
  EXPECT_EQ(about.fiberY(0), 0.2);
  using F3 = FiberSection<3>::Fiber;
  const std::vector<F3> fibers3{{0.2, 0.1, 2.0, &mat}, {-0.2, -0.3, 1.0, &mat}};
  FiberSection<3> about3(1, fibers3, 1.0, true);
  EXPECT_NEAR(about3.centroidZ(), (2.0 * 0.1 - 0.3) / 3.0, 1e-15);
  ASSERT_TRUE(ok(about3.setTrialDeformation(Eigen::Vector4d(1e-4, 0.0, 0.0, 0.0))));
  const Eigen::VectorXd s3 = about3.getStressResultant();
  EXPECT_NEAR(s3(0), 3.0 * kE * 1e-4, 1e-6);
  EXPECT_NEAR(s3(1), 0.0, 1e-6);  // Mz
  EXPECT_NEAR(s3(2), 0.0, 1e-6);  // My
}

TEST(FiberSectionTest, FiberStressStrainResponse) {
  const ElasticPP mat = epp();
  auto sec = rectangle<2>(mat);
  ASSERT_TRUE(ok(sec.setTrialDeformation(Eigen::Vector2d(1e-4, 0.0))));
  const std::vector<std::string> args{"fiber", "0.1", "0.0", "stressStrain"};
  const auto r = sec.response(args);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR((*r)(0), kE * 1e-4, 1e-6);
  EXPECT_NEAR((*r)(1), 1e-4, 1e-15);
}

TEST(SectionGeometryTest, CircPatchCellsAreExactSectors) {
  CircPatch c;
  c.materialTag = 1;
  c.divCirc = 16;
  c.divRad = 4;
  c.yCenter = 0.5;
  c.zCenter = -0.25;
  c.rInt = 0.2;
  c.rExt = 1.0;
  c.validate();
  FiberList f;
  c.discretize(f);
  ASSERT_EQ(f.size(), 64u);
  double area = 0.0, ay = 0.0, az = 0.0;
  for (const auto& p : f) {
    area += p.area;
    ay += p.area * p.y;
    az += p.area * p.z;
  }
  EXPECT_NEAR(area, std::numbers::pi * (1.0 - 0.04), 1e-12);  // annulus
  EXPECT_NEAR(ay / area, 0.5, 1e-12);
  EXPECT_NEAR(az / area, -0.25, 1e-12);
}

TEST(SectionGeometryTest, QuadPatchAndLayers) {
  QuadPatch q;
  q.divIJ = 3;
  q.divJK = 5;
  q.y = {0.0, 2.0, 2.5, -0.5};
  q.z = {0.0, 0.0, 1.0, 1.5};
  q.validate();
  FiberList f;
  q.discretize(f);
  double area = 0.0;
  for (const auto& p : f) area += p.area;
  // Shoelace area of the quadrilateral.
  EXPECT_NEAR(area,
              0.5 * ((0 * 0 - 2 * 0) + (2 * 1 - 2.5 * 0) + (2.5 * 1.5 - (-0.5) * 1) +
                     ((-0.5) * 0 - 0 * 1.5)),
              1e-12);
  std::swap(q.y[1], q.y[3]);  // clockwise
  std::swap(q.z[1], q.z[3]);
  EXPECT_THROW(q.validate(), InputError);

  FiberList bars;
  StraightLayer{3, 5, 0.01, -1.0, 0.0, 1.0, 2.0}.discretize(bars);
  ASSERT_EQ(bars.size(), 5u);
  EXPECT_DOUBLE_EQ(bars[2].y, 0.0);
  EXPECT_DOUBLE_EQ(bars[4].z, 2.0);
  bars.clear();
  CircLayer arc{3, 40, 0.01, 0.0, 0.0, 1.0, 0.0, 351.0};
  arc.discretize(bars);
  ASSERT_EQ(bars.size(), 40u);  // 351 degrees: bars at both ends, 9 degrees apart
  EXPECT_NEAR(std::atan2(bars[1].z, bars[1].y), 9.0 * std::numbers::pi / 180, 1e-12);
  EXPECT_NEAR(std::atan2(bars[39].z, bars[39].y), -9.0 * std::numbers::pi / 180, 1e-12);
  bars.clear();
  CircLayer full{3, 8, 0.01, 0.0, 0.0, 1.0, 0.0, 360.0};
  full.discretize(bars);
  EXPECT_NEAR(std::atan2(bars[1].z, bars[1].y), std::numbers::pi / 4, 1e-12);
}

TEST(FiberSectionTest, MixedMaterialsSumLikeTheFibersOneByOne) {
  // Fibers of three material types given interleaved (Concrete02 and Steel02 are kept in typed
  // groups, ENT in the general one): resultants, tangent and the fiber order must be those of
  // the fibers summed one by one with their own material copies, s = sum sigma A a and
  // k = sum Et A a a^T with a = [1, -y, z].
  const Concrete02 concrete = concrete02();
  const Steel02 steel = steel02();
  ENT::Params ep;
  ep.E = 1e6;
  const ENT ent(3, ep);
  const UniaxialMaterial* kinds[3] = {&concrete, &steel, &ent};
  std::vector<FiberSection3d::Fiber> fibers;
  std::vector<std::unique_ptr<UniaxialMaterial>> alone;
  for (int i = 0; i < 30; ++i) {
    const double y = 0.4 * std::cos(0.7 * i), z = 0.3 * std::sin(1.3 * i),
                 area = 0.01 + 0.001 * (i % 4);
    fibers.push_back({y, z, area, kinds[i % 3]});
    alone.push_back(kinds[i % 3]->clone());
  }
  FiberSection3d sec(7, fibers, 100.0);
  ASSERT_EQ(sec.numFibers(), 30);
  for (const Eigen::Vector4d& e :
       {Eigen::Vector4d(-4e-4, 2e-3, -1e-3, 1e-3), Eigen::Vector4d(1e-4, -3e-3, 2e-3, 0.0)}) {
    ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
    Eigen::Vector4d s = Eigen::Vector4d::Zero();
    Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
    for (int i = 0; i < 30; ++i) {
      const auto& f = fibers[static_cast<std::size_t>(i)];
      auto& m = *alone[static_cast<std::size_t>(i)];
      ASSERT_TRUE(ok(m.setTrialStrain(e(0) - f.y * e(1) + f.z * e(2))));
      const Eigen::Vector3d a(1.0, -f.y, f.z);
      s.head<3>() += m.getStress() * f.area * a;
      k.topLeftCorner<3, 3>() += m.getTangent() * f.area * a * a.transpose();
      EXPECT_EQ(sec.fiberMaterialTag(i), m.tag());
      EXPECT_EQ(sec.fiberY(i), f.y);
      EXPECT_DOUBLE_EQ(sec.fiberStress(i), m.getStress());
      EXPECT_DOUBLE_EQ(sec.fiberStrain(i), m.getStrain());
    }
    s(3) = 100.0 * e(3);
    k(3, 3) = 100.0;
    EXPECT_LT((sec.getStressResultant() - s).norm(), 1e-12 * s.norm());
    EXPECT_LT((sec.getSectionTangent() - k).norm(), 1e-12 * k.norm());
    sec.commitState();
    for (auto& m : alone) m->commitState();
  }
  EXPECT_EQ(sec.materialUpdates(), 60);
}

// A group of eight fibers or more sums into four partial sums, fiber i of the group into partial
// i % 4, the last four padded with fibers of no area, added as (0 + 1) + (2 + 3); a smaller group
// sums in fiber order. With AVX (four fibers at a time, the last one to three by masked loads) or
// without, a section's resultants, tangent and initial tangent, and its response after a revert,
// are those sums to the bit: here `nConcrete` Concrete02 fibers (7 to 12: both orders and every
// remainder) and 6 Steel02 bars, symmetric about the origin (so the centroid is the origin), in a
// plane or a 3D section.
template <int Ndm>
void expectPartialSums(std::size_t nConcrete) {
  SCOPED_TRACE(testing::Message() << Ndm << "D, " << nConcrete << " concrete fibers");
  const Concrete02 concrete = concrete02();
  const Steel02 steel = steel02();
  std::vector<typename FiberSection<Ndm>::Fiber> fibers;
  if (nConcrete % 2 == 1) fibers.push_back({0.0, 0.0, 0.012, &concrete});
  for (std::size_t j = 0; j < nConcrete / 2; ++j) {
    const double y = 0.3 * std::cos(0.37 * double(j) + 0.1);
    const double z = 0.2 * std::sin(0.61 * double(j) + 0.2), area = 0.01 + 0.001 * double(j % 3);
    fibers.push_back({y, z, area, &concrete});
    fibers.push_back({-y, -z, area, &concrete});
  }
  for (const double y : {0.25, 0.15, 0.05}) {
    fibers.push_back({y, 0.1 * y, 0.0005, &steel});
    fibers.push_back({-y, -0.1 * y, 0.0005, &steel});
  }
  FiberSection<Ndm> sec(1, fibers, 0.0);
  ASSERT_EQ(sec.numFibers(), static_cast<int>(nConcrete + 6));
  const double e0 = -3e-4, kz = 2e-3, ky = Ndm == 3 ? -1.5e-3 : 0.0;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(Ndm == 3 ? 4 : 2);
  e(0) = e0;
  e(1) = kz;
  if constexpr (Ndm == 3) e(2) = ky;
  ASSERT_TRUE(ok(sec.setTrialDeformation(e)));

  // The sums of the fibers' (stress, tangent) pairs in the order described above.
  const auto sumsOf = [&](auto response) {
    FiberSums sums;
    if (nConcrete >= 8) {
      FiberSums part[4];
      for (std::size_t i = 0; i < nConcrete; ++i) {
        const auto& f = fibers[i];
        const auto [stress, tangent] = response(i);
        part[i % 4].add(f.y, Ndm == 3 ? f.z : 0.0, stress * f.area, tangent * f.area);
      }
      for (std::size_t i = nConcrete; i % 4 != 0; ++i) part[i % 4].add(0.0, 0.0, 0.0, 0.0);
      for (double FiberSums::*x :
           {&FiberSums::p, &FiberSums::mz, &FiberSums::my, &FiberSums::kPP, &FiberSums::kPz,
            &FiberSums::kPy, &FiberSums::kzz, &FiberSums::kzy, &FiberSums::kyy})
        sums.*x += (part[0].*x + part[1].*x) + (part[2].*x + part[3].*x);
    } else {
      for (std::size_t i = 0; i < nConcrete; ++i) {
        const auto& f = fibers[i];
        const auto [stress, tangent] = response(i);
        sums.add(f.y, Ndm == 3 ? f.z : 0.0, stress * f.area, tangent * f.area);
      }
    }
    for (std::size_t i = nConcrete; i < fibers.size(); ++i) {
      const auto& f = fibers[i];
      const auto [stress, tangent] = response(i);
      sums.add(f.y, Ndm == 3 ? f.z : 0.0, stress * f.area, tangent * f.area);
    }
    return sums;
  };
  const auto strain = [&](const auto& f) {
    return Ndm == 3 ? e0 - f.y * kz + f.z * ky : e0 - f.y * kz;
  };
  const FiberSums trial = sumsOf([&](std::size_t i) {
    const auto& f = fibers[i];
    if (i < nConcrete) {
      Concrete02::State t;
      static_cast<void>(concrete.computeTrial(concrete.virginState(), t, strain(f)));
      return StressTangent{t.stress, t.tangent};
    }
    Steel02::State t;
    static_cast<void>(steel.computeTrial(steel.virginState(), t, strain(f)));
    return StressTangent{t.stress, t.tangent};
  });
  const FiberSums initial = sumsOf([&](std::size_t i) {
    return StressTangent{0.0,
                         i < nConcrete ? concrete.getInitialTangent() : steel.getInitialTangent()};
  });
  const auto expectSums = [](const auto& s, const auto& k, const FiberSums& expected,
                             bool withForces) {
    if (withForces) {
      EXPECT_EQ(s(0), expected.p);
      EXPECT_EQ(s(1), expected.mz);
      if constexpr (Ndm == 3) {
        EXPECT_EQ(s(2), expected.my);
      }
    }
    EXPECT_EQ(k(0, 0), expected.kPP);
    EXPECT_EQ(k(0, 1), expected.kPz);
    EXPECT_EQ(k(1, 1), expected.kzz);
    if constexpr (Ndm == 3) {
      EXPECT_EQ(k(0, 2), expected.kPy);
      EXPECT_EQ(k(1, 2), expected.kzy);
      EXPECT_EQ(k(2, 2), expected.kyy);
    }
  };
  expectSums(sec.getStressResultant(), sec.getSectionTangent(), trial, true);
  expectSums(sec.getStressResultant(), sec.getInitialTangent(), initial, false);
  // The same sums again from the committed state (the section's response after a revert).
  sec.commitState();
  sec.revertToLastCommit();
  expectSums(sec.getStressResultant(), sec.getSectionTangent(), trial, true);
}

TEST(FiberSectionTest, GroupsSumInFourPartialSums) {
  for (std::size_t nConcrete = 7; nConcrete <= 12; ++nConcrete) {
    expectPartialSums<2>(nConcrete);
    expectPartialSums<3>(nConcrete);
  }
}

// A fiber's stress as a response is the stress the section summed: eight Steel02 bars at
// distinct heights (one group, four at a time where the processor has AVX, whose powers may differ
// in the last bits from an update one at a time), yielded, committed and then reversed onto the
// curves of their new branches: the axial force is the four partial sums of the fibers' stresses
// times their areas, to the bit.
TEST(FiberSectionTest, FiberStressIsTheStressTheSectionSummed) {
  const Steel02 steel = steel02();
  std::vector<FiberSection<2>::Fiber> fibers;
  for (int j = 0; j < 8; ++j) fibers.push_back({-0.35 + 0.1 * j, 0.0, 0.0005 + 1e-5 * j, &steel});
  FiberSection<2> sec(1, fibers, 0.0);
  const double epsY = 4e5 / 2e8;
  Eigen::VectorXd e(2);
  e << 0.5 * epsY, 30.0 * epsY;  // bars from -10 to +11 yield strains
  ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
  sec.commitState();
  int onCurve = 0;
  for (const double back : {0.3, 0.6, 0.9}) {
    e(1) = 30.0 * epsY * (1.0 - back);  // every bar reverses
    ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
    double part[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 8; ++i) {
      part[i % 4] += sec.fiberStress(i) * sec.fiberArea(i);
      // Off the initial line of the new branch: the stress is not the elastic unloading one.
      onCurve += std::fabs(sec.fiberStress(i)) < 0.999 * 4e5 ? 1 : 0;
    }
    EXPECT_EQ(sec.getStressResultant()(0), (part[0] + part[1]) + (part[2] + part[3]));
  }
  EXPECT_GT(onCurve, 8);
}

// A group's fibers go through the law's update as in one call over the whole group, at strains
// the group forms from the section's: Steel02 bars (whose powers four at a time may differ in
// the last bits from those one at a time) in groups of 131 to 263 at distinct heights (and
// depths in 3D), yielded, committed, reversed and reloaded. Each bar's stress is the one
// Steel02::computeTrials gives over the whole array of states at strains e0 - y kz (+ z ky)
// formed here, each state committed by Steel02::commitTrial with its trial stress and tangent.
template <int Ndm>
void expectBarsUpdatedAsInOneCall(std::size_t n) {
  SCOPED_TRACE(testing::Message() << Ndm << "D, " << n << " bars");
  const Steel02 steel = steel02();
  const double epsY = 4e5 / 2e8;
  std::vector<typename FiberSection<Ndm>::Fiber> fibers;
  for (std::size_t j = 0; j < n; ++j) {
    const double t = double(j) / double(n);
    fibers.push_back({-0.35 + 0.7 * t, Ndm == 3 ? 0.2 * std::cos(9.0 * t) : 0.0, 0.0005, &steel});
  }
  FiberSection<Ndm> sec(1, fibers, 0.0);
  // The states as Steel02::computeTrials takes them, every lane virgin to begin with.
  std::vector<StateFours<Steel02::State>> states(
      (n + 3) / 4, StateFours<Steel02::State>::filledWith(steel.virginState()));
  std::vector<double> strains(n), stresses(n), tangents(n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(Ndm == 3 ? 4 : 2);
  int onCurve = 0;
  for (const double curvature : {30.0, 21.0, 12.0, 19.0, 3.0, 17.5}) {
    e(0) = 0.5 * epsY;
    e(1) = curvature * epsY;
    if constexpr (Ndm == 3) e(2) = -0.6 * curvature * epsY;
    ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
    for (std::size_t j = 0; j < n; ++j)
      strains[j] =
          Ndm == 3 ? e(0) - fibers[j].y * e(1) + fibers[j].z * e(2) : e(0) - fibers[j].y * e(1);
    steel.computeTrials(states.data(), FiberStrains::given(strains.data()),
                        Responses{stresses.data(), tangents.data()}, n);
    for (std::size_t j = 0; j < n; ++j) {
      ASSERT_EQ(sec.fiberStress(static_cast<int>(j)), stresses[j]) << "bar " << j;
      ASSERT_EQ(sec.fiberStrain(static_cast<int>(j)), strains[j]) << "bar " << j;
      onCurve += std::fabs(stresses[j]) < 0.999 * 4e5 && std::fabs(tangents[j]) < 0.99 * 2e8;
    }
    sec.commitState();
    for (std::size_t j = 0; j < n; ++j) {
      Steel02::State s = stateOf(states.data(), j);
      steel.commitTrial(s, strains[j], stresses[j], tangents[j]);
      states[j / 4].set(j % 4, s);
    }
  }
  EXPECT_GT(onCurve, static_cast<int>(n));  // many bars off the straight parts of their branches
}

TEST(FiberSectionTest, LongGroupsUpdateAsInOneCallOfTheLaw) {
  for (const std::size_t n : {131u, 132u, 133u, 135u, 258u, 263u}) {
    expectBarsUpdatedAsInOneCall<2>(n);
    expectBarsUpdatedAsInOneCall<3>(n);
  }
}

// Every fiber of a section follows its own law through any sequence of trials (new strains, the
// same ones, or one ulp apart), commits, reverts, returns to the start and copies: a 3D and a
// plane section of interleaved Steel02, Concrete01 and Concrete02 fibers (groups of 1 to 10, so
// every count of lanes in a group's last four), random steps. Each fiber's stress and strain,
// after every operation, are those of its law's computeTrial and commitTrial one fiber at a time
// (Steel02 in a group of four or more with steel02::LanePowers, as Steel02::computeTrials
// promises), to the bit.
template <int Ndm>
void expectEveryFiberFollowsItsLaw(std::size_t nSteel, std::size_t nConcrete01,
                                   std::size_t nConcrete02, unsigned seed) {
  SCOPED_TRACE(testing::Message() << Ndm << "D, " << nSteel << " Steel02, " << nConcrete01
                                  << " Concrete01, " << nConcrete02 << " Concrete02, seed "
                                  << seed);
  Steel02::Params steelParams = steel02().params();
  steelParams.sigInit = 30.0;
  const Steel02 steel(1, steelParams);
  const Concrete01 concrete1(2, Concrete01::Params{-30e3, -0.002, -6e3, -0.006});
  const Concrete02 concrete2 = concrete02();
  // Each fiber's committed and current states, advanced here one fiber at a time.
  struct OwnStates {
    int law;  // 0 Steel02, 1 Concrete01, 2 Concrete02
    double y, z;
    Steel02::State steel, steelNow;
    Concrete01::State concrete1, concrete1Now;
    Concrete02::State concrete2, concrete2Now;
  };
  std::vector<typename FiberSection<Ndm>::Fiber> fibers;
  std::vector<OwnStates> own;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-0.3, 0.3), unit(-1.0, 1.0);
  std::size_t left[3] = {nSteel, nConcrete01, nConcrete02};
  const UniaxialMaterial* laws[3] = {&steel, &concrete1, &concrete2};
  while (left[0] + left[1] + left[2] > 0) {
    const int law = static_cast<int>(random() % 3);
    if (left[law] == 0) continue;
    --left[law];
    OwnStates f{law,
                coordinate(random),
                coordinate(random),
                steel.virginState(),
                {},
                concrete1.virginState(),
                {},
                concrete2.virginState(),
                {}};
    own.push_back(f);
    fibers.push_back({f.y, f.z, 0.001, laws[law]});
  }
  auto sec = std::make_unique<FiberSection<Ndm>>(1, fibers, 1.0);
  enum class Phase { Committed, Trial, CommitPending } phase = Phase::Committed;
  double e0 = 0.0, kz = 0.0, ky = 0.0;
  const bool steelInLanes = Steel02::updatesFourAtOnce() && nSteel >= 4;
  const auto strainOf = [&](const OwnStates& f) {
    return Ndm == 2 ? e0 - f.y * kz : e0 - f.y * kz + f.z * ky;
  };
  for (int step = 0; step < 400; ++step) {
    const auto operation = static_cast<unsigned>(random() % 10);
    if (operation < 5) {
      const auto how = static_cast<unsigned>(random() % 4);
      if (how == 1) {
        e0 = std::nextafter(e0, 1.0);
      } else if (how > 1) {
        e0 = 0.0012 * unit(random);
        kz = 0.004 * unit(random) / 0.3;
        ky = Ndm == 3 ? 0.004 * unit(random) / 0.3 : 0.0;
      }  // how == 0: the same strains again
      if (phase == Phase::CommitPending) {
        for (auto& f : own) {
          f.steel = f.steelNow;
          f.concrete1 = f.concrete1Now;
          f.concrete2 = f.concrete2Now;
        }
      }
      Eigen::VectorXd e = Eigen::VectorXd::Zero(Ndm == 3 ? 4 : 2);
      e(0) = e0;
      e(1) = kz;
      if constexpr (Ndm == 3) e(2) = ky;
      ASSERT_TRUE(ok(sec->setTrialDeformation(e)));
      for (auto& f : own) {
        const double strain = strainOf(f);
        if (f.law == 0)
          static_cast<void>(steelInLanes ? steel.computeTrialWith<steel02::LanePowers>(
                                               f.steel, f.steelNow, strain)
                                         : steel.computeTrial(f.steel, f.steelNow, strain));
        else if (f.law == 1)
          static_cast<void>(concrete1.computeTrial(f.concrete1, f.concrete1Now, strain));
        else
          static_cast<void>(concrete2.computeTrial(f.concrete2, f.concrete2Now, strain));
      }
      phase = Phase::Trial;
    } else if (operation < 7) {
      sec->commitState();
      if (phase == Phase::Trial) {
        // The state the trial leaves (commitTrial with the trial's stress and tangent).
        for (auto& f : own) {
          const double strain = strainOf(f);
          if (f.law == 0) {
            Steel02::State c = f.steel;
            steel.commitTrial(c, strain, f.steelNow.stress, f.steelNow.tangent);
            f.steelNow = c;
          } else if (f.law == 1) {
            Concrete01::State c = f.concrete1;
            concrete1.commitTrial(c, strain, f.concrete1Now.stress, f.concrete1Now.tangent);
            f.concrete1Now = c;
          } else {
            Concrete02::State c = f.concrete2;
            concrete2.commitTrial(c, strain, f.concrete2Now.stress, f.concrete2Now.tangent);
            f.concrete2Now = c;
          }
        }
        phase = Phase::CommitPending;
      }
    } else if (operation < 8) {
      sec->revertToLastCommit();
      if (phase == Phase::Trial) phase = Phase::Committed;
    } else if (operation < 9) {
      if (random() % 4 == 0) {
        sec->revertToStart();
        for (auto& f : own) {
          f.steel = steel.virginState();
          f.concrete1 = concrete1.virginState();
          f.concrete2 = concrete2.virginState();
        }
        phase = Phase::Committed;
      }
    } else {
      auto copy = sec->clone();
      sec.reset(static_cast<FiberSection<Ndm>*>(copy.release()));
    }
    for (std::size_t i = 0; i < own.size(); ++i) {
      const OwnStates& f = own[i];
      const bool now = phase != Phase::Committed;
      double stress = 0.0, strain = 0.0;
      if (f.law == 0) {
        stress = now ? f.steelNow.stress : f.steel.stress;
        strain = now ? f.steelNow.strain : f.steel.strain;
      } else if (f.law == 1) {
        stress = now ? f.concrete1Now.stress : f.concrete1.stress;
        strain = now ? f.concrete1Now.strain : f.concrete1.strain;
      } else {
        stress = now ? f.concrete2Now.stress : f.concrete2.stress;
        strain = now ? f.concrete2Now.strain : f.concrete2.strain;
      }
      const int fiber = static_cast<int>(i);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(sec->fiberStress(fiber)),
                std::bit_cast<std::uint64_t>(stress))
          << "step " << step << " operation " << operation << " fiber " << i;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(sec->fiberStrain(fiber)),
                std::bit_cast<std::uint64_t>(strain))
          << "step " << step << " operation " << operation << " fiber " << i;
    }
  }
}

TEST(FiberSectionTest, EveryFiberFollowsItsLawThroughCommitsRevertsAndCopies) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    for (std::size_t n = 1; n <= 9; ++n) {
      expectEveryFiberFollowsItsLaw<3>(n, n + 1, (n + 2) % 10 + 1, seed);
      expectEveryFiberFollowsItsLaw<2>(n, n + 1, (n + 2) % 10 + 1, seed);
    }
  }
}

TEST(FiberSectionTest, CopiesShareOnlyTheirGeometry) {
  // The copies of a section (one per integration point) share the fibers' coordinates and areas
  // but not their states: a copy and the original driven through different histories (trials,
  // commits, reverts) must each give what a section built afresh gives for its own history, bit
  // for bit, in resultants, tangent and fiber stresses and strains.
  const Concrete02 concrete = concrete02();
  const Steel02 steel = steel02();
  std::vector<FiberSection3d::Fiber> fibers;
  for (int i = 0; i < 24; ++i)
    fibers.push_back({0.4 * std::cos(0.9 * i), 0.3 * std::sin(1.1 * i), 0.01 + 0.002 * (i % 3),
                      i % 4 == 0 ? static_cast<const UniaxialMaterial*>(&steel) : &concrete});
  const FiberSection3d built(3, fibers, 50.0);
  auto copy = built.clone();
  auto original = built.clone();
  FiberSection3d freshA(3, fibers, 50.0), freshB(3, fibers, 50.0);
  // deformation k of history h: opposite curvatures for the two histories
  auto deformation = [](int k, double sign) {
    return Eigen::Vector4d(-2e-4 * k, sign * 1.5e-3 * k, -sign * 8e-4 * k, 1e-4 * k);
  };
  auto same = [](const SectionForceDeformation& a, const FiberSection3d& b) {
    EXPECT_EQ(a.getStressResultant(), b.getStressResultant());
    EXPECT_EQ(a.getSectionTangent(), b.getSectionTangent());
    const auto& fa = dynamic_cast<const FiberSection3d&>(a);
    for (int i = 0; i < b.numFibers(); ++i) {
      EXPECT_EQ(fa.fiberStress(i), b.fiberStress(i));
      EXPECT_EQ(fa.fiberStrain(i), b.fiberStrain(i));
      EXPECT_EQ(fa.fiberArea(i), b.fiberArea(i));
    }
  };
  for (int k = 1; k <= 6; ++k) {
    for (auto [section, fresh, sign] :
         {std::tuple{original.get(), &freshA, 1.0}, std::tuple{copy.get(), &freshB, -1.0}}) {
      ASSERT_TRUE(ok(section->setTrialDeformation(deformation(k + 3, sign))));  // overshoot
      ASSERT_TRUE(ok(section->setTrialDeformation(deformation(k, sign))));
      ASSERT_TRUE(ok(fresh->setTrialDeformation(deformation(k, sign))));
      same(*section, *fresh);
      if (k % 3 == 0) {  // a rejected step: back to the committed state
        section->revertToLastCommit();
        fresh->revertToLastCommit();
      } else {
        section->commitState();
        fresh->commitState();
      }
      same(*section, *fresh);
      if (k == 4) {  // a revert right after a commit keeps the committed state
        section->revertToLastCommit();
        fresh->revertToLastCommit();
        same(*section, *fresh);
      }
    }
  }
}

TEST(FiberSectionTest, FibersAtOneStrainPointAreEvaluatedOnce) {
  // A plane section given with 4 fibers across the width at each of 10 depths, and 3 bars at one
  // depth: fibers of one material at one y share their strain history, so the section evaluates
  // 10 + 1 of them. Its resultants and tangent must be those of a section given the 11 fibers
  // with the summed areas (to round-off), and every fiber as given keeps its place and area.
  const Concrete02 concrete = concrete02();
  const Steel02 steel = steel02();
  std::vector<FiberSection2d::Fiber> given, summed;
  for (int iy = 0; iy < 10; ++iy) {
    const double y = -0.225 + 0.05 * iy;
    for (int iz = 0; iz < 4; ++iz) given.push_back({y, -0.15 + 0.1 * iz, 0.0125, &concrete});
    summed.push_back({y, 0.0, 4 * 0.0125, &concrete});
  }
  for (int bar = 0; bar < 3; ++bar) given.push_back({0.2, -0.1 + 0.1 * bar, 5e-4, &steel});
  summed.push_back({0.2, 0.0, 3 * 5e-4, &steel});
  FiberSection2d sec(1, given), reference(2, summed);
  ASSERT_EQ(sec.numFibers(), 43);
  EXPECT_EQ(sec.fiberArea(41), 5e-4);
  EXPECT_EQ(sec.fiberZ(42), 0.1);
  const double phiY = 2e-3 / 0.45;
  for (double phi : {0.5 * phiY, 2.0 * phiY, -1.0 * phiY, 4.0 * phiY}) {
    const Eigen::Vector2d e(-3e-4, phi);
    ASSERT_TRUE(ok(sec.setTrialDeformation(e)));
    ASSERT_TRUE(ok(reference.setTrialDeformation(e)));
    EXPECT_LT((sec.getStressResultant() - reference.getStressResultant()).norm(),
              1e-14 * reference.getStressResultant().norm());
    EXPECT_LT((sec.getSectionTangent() - reference.getSectionTangent()).norm(),
              1e-14 * reference.getSectionTangent().norm());
    EXPECT_EQ(sec.fiberStress(40), reference.fiberStress(10));  // a bar: the merged one's
    EXPECT_EQ(sec.fiberStrain(5), reference.fiberStrain(1));    // depth 1, third across
    sec.commitState();
    reference.commitState();
  }
  EXPECT_EQ(sec.materialUpdates(), 4 * 11);
  // In 3D the strain depends on z too: the same fibers are all evaluated.
  std::vector<FiberSection3d::Fiber> spatial;
  for (const auto& f : given) spatial.push_back({f.y, f.z, f.area, f.material});
  FiberSection3d sec3(3, spatial);
  ASSERT_TRUE(ok(sec3.setTrialDeformation(Eigen::Vector4d(-3e-4, phiY, phiY, 0.0))));
  EXPECT_EQ(sec3.materialUpdates(), 43);
}

TEST(FiberSectionTest, NonFiniteFiberStressFailsTheSection) {
  // An infinite strain drives Steel02's Menegotto-Pinto ratio to inf / inf (NaN), which the
  // material alone reports as NonFinite; the section must report the same, in 2D and in 3D, and
  // a later finite deformation must work again from the committed state.
  Steel02::Params sp;
  sp.Fy = 4e5;
  sp.E = 2e8;
  sp.b = 0.01;
  const Steel02 steel(2, sp);
  auto alone = steel.clone();
  const double inf = std::numeric_limits<double>::infinity();
  ASSERT_EQ(alone->setTrialStrain(inf), Status::NonFinite);
  auto sec2 = rectangle<2>(steel);
  EXPECT_EQ(sec2.setTrialDeformation(Eigen::Vector2d(inf, 0.0)), Status::NonFinite);
  sec2.revertToLastCommit();
  EXPECT_TRUE(ok(sec2.setTrialDeformation(Eigen::Vector2d(1e-4, 0.0))));
  EXPECT_NEAR(sec2.getStressResultant()(0), sp.E * 1e-4 * kB * kH, 1e-9 * sp.E * 1e-4 * kB * kH);
  auto sec3 = rectangle<3>(steel, 1.0);
  EXPECT_EQ(sec3.setTrialDeformation(Eigen::Vector4d(0.0, inf, 0.0, 0.0)), Status::NonFinite);
}

}  // namespace
}  // namespace dabs::materials::section
