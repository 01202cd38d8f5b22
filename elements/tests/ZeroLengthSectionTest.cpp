// SPDX-License-Identifier: MIT
// zeroLengthSection: deformations are relative motions in local axes, elastic section closed form,
// moment-curvature of an elastic-perfectly-plastic fiber rectangle, FD tangent (2D and 3D,
// oblique axes, aggregated section), bad input; and the constant-B path of the elastic beams
// (Linear/PDelta stiffness formed once) against the general transformation formula.
#include <gtest/gtest.h>

#include <cmath>

#include "elements/beam/ElasticBeam3d.h"
#include "elements/beam/ZeroLengthSection.h"
#include "elements/tests/ElementChecks.h"
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/InputError.h"
#include "materials/Steel02.h"
#include "materials/section/ElasticSection.h"
#include "materials/section/FiberSection.h"
#include "materials/section/SectionAggregator.h"
#include "materials/section/geometry/QuadPatch.h"

namespace dabs::elements {
namespace {

using materials::section::ElasticSection;
using materials::section::SectionCode;
using testing::TrialState;

constexpr double kTol = 1e-12;    // linear algebra round-off, relative
constexpr double kFdTol = 1e-6;   // finite-difference tangent, relative
constexpr double kFdStep = 1e-8;  // FD perturbation (deformations of order 1e-3)

TrialState state(const Eigen::VectorXd& u) {
  return TrialState{u, Eigen::VectorXd::Zero(u.size()), Eigen::VectorXd::Zero(u.size())};
}

std::unique_ptr<ElasticSection> elastic3d() {
  materials::section::ElasticSectionParams p;
  p.ndm = 3;
  p.modulus = 2.0e8;
  p.area = 0.02;
  p.inertiaZ = 3.0e-4;
  p.inertiaY = 2.0e-4;
  p.shearModulus = 8.0e7;
  p.torsion = 5.0e-4;
  p.alphaY = 5.0 / 6.0;
  p.alphaZ = 0.9;
  return std::make_unique<ElasticSection>(1, p);
}

TEST(ZeroLengthSectionTest, DeformationsAreRelativeMotionsInLocalAxes) {
  // Local x along global (0,1,0), yp along global (-1,0,0): local y = (-1,0,0), z = (0,0,1).
  ZeroLengthSection3d e(1, 1, 2, elastic3d(), {0.0, 1.0, 0.0}, {-1.0, 0.0, 0.0});
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.segment<3>(0) << 0.1, 0.2, 0.3;      // node i translation
  u.segment<3>(3) << 0.01, 0.02, 0.03;   // node i rotation
  u.segment<3>(6) << 0.5, 0.7, -0.1;     // node j translation
  u.segment<3>(9) << -0.02, 0.05, 0.04;  // node j rotation
  ASSERT_TRUE(ok(e.update(state(u).kinematics())));
  const Eigen::VectorXd d = e.section().getDeformation();
  // Codes P, Mz, Vy, My, Vz, T.
  EXPECT_NEAR(d(0), 0.7 - 0.2, kTol);        // P: along local x = global Y
  EXPECT_NEAR(d(1), 0.04 - 0.03, kTol);      // Mz: about local z = global Z
  EXPECT_NEAR(d(2), -(0.5 - 0.1), kTol);     // Vy: along local y = -X
  EXPECT_NEAR(d(3), -(-0.02 - 0.01), kTol);  // My: about local y = -X
  EXPECT_NEAR(d(4), -0.1 - 0.3, kTol);       // Vz: along local z = Z
  EXPECT_NEAR(d(5), 0.05 - 0.02, kTol);      // T: about local x = Y
  // Forces: node j gets A^T s, node i the opposite; equilibrium.
  const Eigen::VectorXd f = e.resistingForce();
  EXPECT_LT((f.head<6>() + f.tail<6>()).norm(), kTol * f.norm());
}

TEST(ZeroLengthSectionTest, EppFiberMomentCurvatureMatchesClosedForm) {
  // Rectangle of ElasticPP fibers: M = Mp (1 - (phi_y/phi)^2 / 3) (Gere & Timoshenko sec. 6.10).
  constexpr double kE = 2.0e8, kFy = 4.0e5, kB = 0.3, kH = 0.5;
  constexpr int kLayers = 400;
  constexpr double kMomentTol = 2e-5;  // discretisation error of 400 layers
  materials::ElasticPP::Params mp;
  mp.E = kE;
  mp.epsyP = kFy / kE;
  mp.validate();
  const materials::ElasticPP mat(1, mp);
  materials::section::FiberList pts;
  materials::section::QuadPatch::rect(1, kLayers, 1, -kH / 2, -kB / 2, kH / 2, kB / 2)
      .discretize(pts);
  std::vector<materials::section::FiberSection2d::Fiber> fibers;
  for (const auto& p : pts) fibers.push_back({p.y, p.z, p.area, &mat});
  ZeroLengthSection2d e(1, 1, 2, std::make_unique<materials::section::FiberSection2d>(1, fibers));
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  const double phiY = 2.0 * kFy / (kE * kH), mp0 = kFy * kB * kH * kH / 4.0;
  for (double r : {1.0, 1.5, 3.0}) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
    u(5) = r * phiY;
    ASSERT_TRUE(ok(e.update(state(u).kinematics())));
    EXPECT_NEAR(e.resistingForce()(5), mp0 * (1.0 - 1.0 / (3.0 * r * r)), kMomentTol * mp0);
    EXPECT_NEAR(e.resistingForce()(2), -e.resistingForce()(5), kTol * mp0);
  }
}

TEST(ZeroLengthSectionTest, TangentMatchesFiniteDifferences3d) {
  // Aggregated section: elastic base plus a yielding Steel02 in Vy, on oblique axes.
  materials::Steel02::Params sp;
  sp.Fy = 300.0;
  sp.E = 1.0e5;
  sp.b = 0.02;
  sp.validate();
  const materials::Steel02 steel(7, sp);
  materials::section::ElasticSectionParams ep;
  ep.ndm = 3;
  ep.modulus = 1.0e5;
  ep.area = 0.5;
  ep.inertiaZ = 0.02;
  ep.inertiaY = 0.03;
  ep.shearModulus = 4.0e4;
  ep.torsion = 0.01;
  const ElasticSection base(2, ep);
  auto agg = std::make_unique<materials::section::SectionAggregator>(
      3, std::vector<materials::section::SectionAggregator::Part>{{&steel, SectionCode::Vy}},
      &base);
  ZeroLengthSection3d e(1, 1, 2, std::move(agg), {1.0, 1.0, 0.5}, {-1.0, 1.0, 0.3});
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  Eigen::VectorXd u(12);
  u << 0.001, -0.002, 0.0005, 0.003, -0.001, 0.002, 0.004, 0.001, -0.003, -0.002, 0.0015, 0.0035;
  const TrialState s = state(u);
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  const Eigen::MatrixXd kNum = testing::numericalStiffness(e, s, kFdStep);
  EXPECT_LT(testing::relativeDifference(e.tangentStiff(), kNum), kFdTol);
  // The steel yielded in shear (tangent below the elastic one), so the check is not trivial.
  EXPECT_LT(e.tangentStiff().norm(), e.initialStiff().norm());
}

TEST(ZeroLengthSectionTest, RejectsBadInput) {
  EXPECT_THROW(ZeroLengthSection3d(1, 1, 2, elastic3d(), {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}),
               InputError);  // x parallel to yp
  EXPECT_THROW(ZeroLengthSection3d(1, 1, 2, elastic3d(), {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}),
               InputError);  // zero x
  // A 3D section (My, T) in a 2D model.
  EXPECT_THROW(ZeroLengthSection2d(1, 1, 2, elastic3d()), InputError);
  ZeroLengthSection3d e(1, 1, 2, elastic3d());
  EXPECT_THROW(e.initialize({Eigen::Vector3d::Zero()}), InputError);  // one node
}

// The elastic beam forms B^T kb B once for Linear and PDelta and adds only the geometric part:
// the result must equal the transformation's general formula at any state.
TEST(ZeroLengthSectionTest, ElasticBeamConstantBStiffnessEqualsGeneralFormula) {
  ElasticBeam3d::Params p{0.02, 2.0e8, 8.0e7, 5.0e-4, 2.0e-4, 3.0e-4, 0.0, false};
  p.validate();
  for (const bool pdelta : {false, true}) {
    std::unique_ptr<CrdTransf3d> t;
    if (pdelta)
      t = std::make_unique<PDeltaTransf3d>(1, Eigen::Vector3d(0.0, 0.0, 1.0));
    else
      t = std::make_unique<LinearTransf3d>(1, Eigen::Vector3d(0.0, 0.0, 1.0));
    ElasticBeam3d beam(1, 1, 2, p, std::move(t));
    beam.initialize({Eigen::Vector3d(1.0, -2.0, 0.5), Eigen::Vector3d(2.0, 0.0, 2.5)});
    Eigen::VectorXd u(12);
    u << 0.001, -0.002, 0.0005, 0.003, -0.001, 0.002, -0.004, 0.001, -0.003, -0.002, 0.0015, 0.0035;
    ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
    const auto& tr = beam.transformation();
    // Reference: a fresh transformation evaluated with the general formula.
    std::unique_ptr<CrdTransf> copy = tr.clone();
    auto& t3 = static_cast<CrdTransf3d&>(*copy);
    t3.update(u);
    CrdTransf3d::BasicMatrix kb = CrdTransf3d::BasicMatrix::Zero();
    const double l = tr.initialLength(), e = p.modulus / l;
    kb(0, 0) = e * p.area;
    kb(1, 1) = kb(2, 2) = 4.0 * e * p.inertiaZ;
    kb(1, 2) = kb(2, 1) = 2.0 * e * p.inertiaZ;
    kb(3, 3) = kb(4, 4) = 4.0 * e * p.inertiaY;
    kb(3, 4) = kb(4, 3) = 2.0 * e * p.inertiaY;
    kb(5, 5) = p.shearModulus * p.torsion / l;
    const CrdTransf3d::Basic q = kb * t3.basicDeformation();
    const Eigen::MatrixXd kRef = t3.globalStiffness(kb, q);
    EXPECT_LT(testing::relativeDifference(beam.tangentStiff(), kRef), kTol) << "PDelta " << pdelta;
    if (pdelta)
      EXPECT_GT((beam.tangentStiff() - beam.initialStiff()).norm(), 0.0);
    else
      EXPECT_EQ((beam.tangentStiff() - beam.initialStiff()).norm(), 0.0);
  }
}

}  // namespace
}  // namespace dabs::elements
