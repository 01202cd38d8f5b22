// SPDX-License-Identifier: MIT
// Force- and displacement-based beam-columns with fiber sections: exact elastic cantilever with
// one element, FD tangents in the inelastic range under every transformation, failure reporting.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "elements/beam/DispBeamColumn.h"
#include "elements/beam/ForceBeamColumn.h"
#include "elements/beam/QuadratureIntegration.h"
#include "elements/tests/ElementChecks.h"
#include "elements/transform/CorotationalTransf2d.h"
#include "elements/transform/CorotationalTransf3d.h"
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/Steel02.h"
#include "materials/section/FiberSection.h"
#include "materials/section/geometry/QuadPatch.h"

namespace dabs::elements {
namespace {

using materials::UniaxialMaterial;
using materials::section::FiberList;
using materials::section::FiberSection;
using materials::section::QuadPatch;
using testing::TrialState;

constexpr double kE = 2.0e8, kFy = 4.0e5, kB = 0.3, kH = 0.5, kL = 3.0, kGJ = 1.0e5;
constexpr int kNy = 20, kNz = 4;
constexpr double kTol = 1e-9;    // elastic closed form (relative)
constexpr double kFdTol = 1e-5;  // finite-difference tangent (relative)

std::unique_ptr<UniaxialMaterial> elastic() {
  materials::Elastic::Params p;
  p.E = kE;
  return std::make_unique<materials::Elastic>(1, p);
}
std::unique_ptr<UniaxialMaterial> plastic() {
  materials::ElasticPP::Params p;
  p.E = kE;
  p.epsyP = kFy / kE;
  return std::make_unique<materials::ElasticPP>(1, p);
}

template <int Ndm>
std::unique_ptr<FiberSection<Ndm>> rect(const UniaxialMaterial& m) {
  FiberList pts;
  QuadPatch::rect(1, kNy, kNz, -kH / 2, -kB / 2, kH / 2, kB / 2).discretize(pts);
  std::vector<typename FiberSection<Ndm>::Fiber> f;
  for (const auto& p : pts) f.push_back({p.y, p.z, p.area, &m});
  return std::make_unique<FiberSection<Ndm>>(1, f, kGJ);
}

template <int Ndm>
std::vector<BeamIntegrationPoint> points(const materials::section::SectionForceDeformation& s,
                                         int n) {
  const QuadratureIntegration rule(1, QuadratureIntegration::Rule::Lobatto, 1, n);
  std::vector<BeamIntegrationPoint> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back({s.clone(), rule.locations(kL)[i], rule.weights(kL)[i]});
  return pts;
}

// Discretised section stiffnesses (midpoint rule over equal strips: I (1 - 1/n^2)).
const double kEA = kE * kB * kH;
const double kEIz = kE * kB * std::pow(kH, 3) / 12 * (1 - 1.0 / (kNy * kNy));
const double kEIy = kE * kH * std::pow(kB, 3) / 12 * (1 - 1.0 / (kNz * kNz));

template <class El>
Eigen::VectorXd tipSolve(const El& e, const Eigen::VectorXd& load) {
  const int n = e.numDof() / 2;
  const Eigen::MatrixXd kff = e.tangentStiff().bottomRightCorner(n, n);
  return kff.ldlt().solve(load);
}

TEST(ForceBeamColumnTest, OneElementIsExactForElasticCantilever3d) {
  const auto mat = elastic();
  const auto sec = rect<3>(*mat);
  for (bool force : {true, false}) {
    std::unique_ptr<Element> e;
    auto t = std::make_unique<LinearTransf3d>(1, Eigen::Vector3d(0, 0, 1));
    if (force)
      e = std::make_unique<ForceBeamColumn3d>(1, 1, 2, points<3>(*sec, 3), std::move(t), 0.0);
    else
      e = std::make_unique<DispBeamColumn3d>(1, 1, 2, points<3>(*sec, 3), std::move(t), 0.0);
    e->initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
    const Eigen::MatrixXd kff = e->initialStiff().bottomRightCorner(6, 6);
    Eigen::Matrix<double, 6, 1> p;
    const double load = 10.0;
    // Tip loads along local y (= global Y), z (= global Z), axial, torsion.
    p << 0, load, 0, 0, 0, 0;
    Eigen::VectorXd d = kff.ldlt().solve(p);
    EXPECT_NEAR(d(1), load * std::pow(kL, 3) / (3 * kEIz), kTol * d(1)) << force;
    EXPECT_NEAR(d(5), load * kL * kL / (2 * kEIz), kTol * d(5)) << force;
    p << 0, 0, load, 0, 0, 0;
    d = kff.ldlt().solve(p);
    EXPECT_NEAR(d(2), load * std::pow(kL, 3) / (3 * kEIy), kTol * d(2)) << force;
    p << load, 0, 0, load, 0, 0;
    d = kff.ldlt().solve(p);
    EXPECT_NEAR(d(0), load * kL / kEA, kTol * d(0)) << force;
    EXPECT_NEAR(d(3), load * kL / kGJ, kTol * d(3)) << force;
  }
}

TEST(ForceBeamColumnTest, ElasticStateMatchesTangentAtLargeLoad) {
  // Force-based update on a linear section reproduces q = kb v for any v in one iteration.
  const auto mat = elastic();
  const auto sec = rect<2>(*mat);
  ForceBeamColumn2d e(1, 1, 2, points<2>(*sec, 5), std::make_unique<LinearTransf2d>(1), 0.0);
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u << 0, 0, 0, 1e-3, 0.02, -0.01;
  TrialState s{u, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  EXPECT_LT((e.resistingForce() - e.initialStiff() * u).norm(), 1e-9 * e.resistingForce().norm());
}

template <class El>
void expectFdTangent(El& e, const Eigen::VectorXd& u, const char* what) {
  TrialState s{u, Eigen::VectorXd::Zero(u.size()), Eigen::VectorXd::Zero(u.size())};
  ASSERT_TRUE(ok(e.update(s.kinematics()))) << what;
  const Eigen::MatrixXd k = e.tangentStiff();
  const Eigen::MatrixXd kfd = testing::numericalStiffness(e, s, 1e-7);
  EXPECT_LT(testing::relativeDifference(k, kfd), kFdTol) << what;
}

std::unique_ptr<CrdTransf2d> transf2d(int which) {
  if (which == 0) return std::make_unique<LinearTransf2d>(1);
  if (which == 1) return std::make_unique<PDeltaTransf2d>(1);
  return std::make_unique<CorotationalTransf2d>(1);
}

TEST(ForceBeamColumnTest, TangentMatchesFiniteDifferencesWhenYielding2d) {
  const auto mat = plastic();
  const auto sec = rect<2>(*mat);
  // Tip drift well past yield (phi_y L^2/3 ~ 0.012) with no chord rotation difference for PDelta
  // exactness: rotate both ends, keep the transverse displacements equal.
  Eigen::VectorXd u(6);
  u << 0.0, 0.0, 0.03, 2e-4, 0.0, -0.02;
  for (int which = 0; which < 3; ++which) {
    ForceBeamColumn2d f(1, 1, 2, points<2>(*sec, 5), transf2d(which), 0.0);
    f.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
    expectFdTangent(f, u, "force");
    EXPECT_GT(std::abs((*f.response(std::vector<std::string>{"plasticDeformation"}))(1)), 1e-4);
    DispBeamColumn2d d(1, 1, 2, points<2>(*sec, 5), transf2d(which), 0.0);
    d.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
    expectFdTangent(d, u, "disp");
  }
}

TEST(ForceBeamColumnTest, RevertToStartAfterYieldingEqualsAFreshElement) {
  // After a committed plastic excursion, revertToStart must give back the element as built:
  // no force, the initial tangent, and then the same response as a new element on a new path.
  const auto mat = plastic();
  const auto sec = rect<2>(*mat);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd yielded(6), next(6);
  yielded << 0.0, 0.0, 0.03, 2e-4, 0.0, -0.02;
  next << 0.0, 0.0, -0.01, -1e-4, 0.0, 0.015;
  ForceBeamColumn2d used(1, 1, 2, points<2>(*sec, 5), std::make_unique<LinearTransf2d>(1), 0.0);
  ForceBeamColumn2d fresh(1, 1, 2, points<2>(*sec, 5), std::make_unique<LinearTransf2d>(1), 0.0);
  for (ForceBeamColumn2d* e : {&used, &fresh})
    e->initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
  ASSERT_TRUE(ok(used.update(TrialState{yielded, zero, zero}.kinematics())));
  used.commitState();
  ASSERT_GT(std::abs((*used.response(std::vector<std::string>{"plasticDeformation"}))(1)), 1e-4);
  used.revertToStart();
  EXPECT_LT(used.resistingForce().norm(), 1e-9);
  EXPECT_LT(testing::relativeDifference(used.tangentStiff(), fresh.initialStiff()), 1e-12);
  for (ForceBeamColumn2d* e : {&used, &fresh})
    ASSERT_TRUE(ok(e->update(TrialState{next, zero, zero}.kinematics())));
  EXPECT_LT((used.resistingForce() - fresh.resistingForce()).norm(),
            1e-12 * fresh.resistingForce().norm());
}

TEST(ForceBeamColumnTest, UnchangedBasicDeformationsKeepTheStateWithoutSectionPasses) {
  // OpenSees' rule (ForceBeamColumn2d/3d::update): once updated and without member loads, an
  // update whose basic deformations did not change evaluates no section; the end forces still
  // follow the transformation. A rigid-body translation leaves the basic deformations as they
  // are; anything else, or a member load, iterates.
  const auto mat = plastic();
  const auto sec = rect<2>(*mat);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd yielded(6), translated(6), moved(6);
  yielded << 0.0, 0.0, 0.03, 2e-4, 0.0, -0.02;
  translated = yielded + (Eigen::VectorXd(6) << 0.01, -0.02, 0.0, 0.01, -0.02, 0.0).finished();
  moved = yielded;
  moved(5) += 1e-4;
  ForceBeamColumn2d e(1, 1, 2, points<2>(*sec, 5), std::make_unique<LinearTransf2d>(1), 0.0);
  e.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  e.commitState();
  const Eigen::VectorXd force = e.resistingForce();
  const Eigen::MatrixXd tangent = e.tangentStiff();
  const long evaluated = e.materialUpdates();
  ASSERT_GT(evaluated, 0);
  for (const Eigen::VectorXd& u : {yielded, translated}) {
    ASSERT_TRUE(ok(e.update(TrialState{u, zero, zero}.kinematics())));
    EXPECT_EQ(e.materialUpdates(), evaluated);
    // The linear transformation's end forces do not depend on a translation: the same bits.
    EXPECT_EQ(e.resistingForce(), force);
    EXPECT_EQ(e.tangentStiff(), tangent);
  }
  ASSERT_TRUE(ok(e.update(TrialState{moved, zero, zero}.kinematics())));
  EXPECT_GT(e.materialUpdates(), evaluated);
  // A member load is applied at unchanged deformations: the sections must take it.
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  const long beforeLoad = e.materialUpdates();
  BeamLoad load;
  load.w = Eigen::Vector3d(0.0, -50.0, 0.0);
  e.addLoad(load, 1.0);
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  EXPECT_GT(e.materialUpdates(), beforeLoad);
  EXPECT_NE(e.resistingForce(), force);
  // And so is its removal: back to the unloaded state's forces (to the local tolerance).
  const long beforeRemoval = e.materialUpdates();
  e.zeroLoad();
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  EXPECT_GT(e.materialUpdates(), beforeRemoval);
  EXPECT_LT((e.resistingForce() - force).norm(), 1e-9 * force.norm());
}

TEST(DispBeamColumnTest, KeepsItsStateAtTheSameDisplacementsOnlyWhenItsLawsDo) {
  // The analysis skips an element that says it keeps its state while no node moved (a transient
  // step's predictor). A displacement-based beam says so after an update, under a linear
  // transformation and with laws that keep their state at the same strain (Steel02, whose fibers
  // keep only their trial response and fold a commit into the next pass), and an update at the
  // same displacements then gives the same force and tangent, bit for bit, before and after a
  // commit, and the same again after a further step away and back. A revert or a member load ends
  // it; ElasticPP (not shown to keep its state) or a P-Delta transformation never says so.
  materials::Steel02::Params sp;
  sp.Fy = kFy;
  sp.E = kE;
  sp.b = 0.02;
  const materials::Steel02 steel(1, sp);
  const auto sec = rect<2>(steel);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(6);
  Eigen::VectorXd yielded(6), moved(6);
  yielded << 0.0, 0.0, 0.03, 2e-4, 0.01, -0.02;
  moved = yielded;
  moved(5) += 1e-4;
  const NodalCoordinates x{Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)};
  DispBeamColumn2d e(1, 1, 2, points<2>(*sec, 3), std::make_unique<LinearTransf2d>(1), 0.0);
  e.initialize(x);
  EXPECT_FALSE(e.keepsStateAtSameDisplacements());
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  EXPECT_TRUE(e.keepsStateAtSameDisplacements());
  const Eigen::VectorXd force = e.resistingForce();
  const Eigen::MatrixXd tangent = e.tangentStiff();
  for (const bool commit : {false, true}) {
    if (commit) e.commitState();
    EXPECT_TRUE(e.keepsStateAtSameDisplacements());
    const long before = e.materialUpdates();
    ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
    EXPECT_GT(e.materialUpdates(), before);  // evaluated, not skipped, here
    EXPECT_EQ(e.resistingForce(), force);
    EXPECT_EQ(e.tangentStiff(), tangent);
  }
  // The history too: committed again at the same displacements and moved on, it responds as a
  // twin that went from the first commit straight on.
  e.commitState();
  DispBeamColumn2d twin(4, 1, 2, points<2>(*sec, 3), std::make_unique<LinearTransf2d>(1), 0.0);
  twin.initialize(x);
  ASSERT_TRUE(ok(twin.update(TrialState{yielded, zero, zero}.kinematics())));
  twin.commitState();
  for (DispBeamColumn2d* beam : {&e, &twin})
    ASSERT_TRUE(ok(beam->update(TrialState{moved, zero, zero}.kinematics())));
  EXPECT_EQ(e.resistingForce(), twin.resistingForce());
  EXPECT_EQ(e.tangentStiff(), twin.tangentStiff());
  EXPECT_TRUE(e.keepsStateAtSameDisplacements());
  e.revertToLastCommit();
  EXPECT_FALSE(e.keepsStateAtSameDisplacements());
  ASSERT_TRUE(ok(e.update(TrialState{yielded, zero, zero}.kinematics())));
  BeamLoad load;
  load.w = Eigen::Vector3d(0.0, -50.0, 0.0);
  e.addLoad(load, 1.0);
  EXPECT_FALSE(e.keepsStateAtSameDisplacements());

  const auto pp = plastic();
  const auto ppSection = rect<2>(*pp);
  DispBeamColumn2d withElasticPP(2, 1, 2, points<2>(*ppSection, 3),
                                 std::make_unique<LinearTransf2d>(1), 0.0);
  DispBeamColumn2d withPDelta(3, 1, 2, points<2>(*sec, 3), std::make_unique<PDeltaTransf2d>(1),
                              0.0);
  for (DispBeamColumn2d* other : {&withElasticPP, &withPDelta}) {
    other->initialize(x);
    ASSERT_TRUE(ok(other->update(TrialState{yielded, zero, zero}.kinematics())));
    EXPECT_FALSE(other->keepsStateAtSameDisplacements());
  }
}

TEST(ForceBeamColumnTest, TangentMatchesFiniteDifferencesWhenYielding3d) {
  const auto mat = plastic();
  const auto sec = rect<3>(*mat);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.segment<3>(3) << 0.004, 0.02, 0.03;
  u.segment<3>(6) << 1e-4, 0.0, 0.0;
  u.segment<3>(9) << -0.003, -0.01, -0.02;
  for (int which = 0; which < 3; ++which) {
    auto t = [&]() -> std::unique_ptr<CrdTransf3d> {
      if (which == 1) return std::make_unique<PDeltaTransf3d>(1, Eigen::Vector3d(0, 0, 1));
      if (which == 2) return std::make_unique<CorotationalTransf3d>(1, Eigen::Vector3d(0, 0, 1));
      return std::make_unique<LinearTransf3d>(1, Eigen::Vector3d(0, 0, 1));
    };
    const std::string name = which == 0 ? "Linear" : which == 1 ? "PDelta" : "Corotational";
    ForceBeamColumn3d f(1, 1, 2, points<3>(*sec, 4), t(), 0.0);
    f.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
    expectFdTangent(f, u, ("force " + name).c_str());
    DispBeamColumn3d d(1, 1, 2, points<3>(*sec, 4), t(), 0.0);
    d.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
    expectFdTangent(d, u, ("disp " + name).c_str());
  }
}

TEST(ForceBeamColumnTest, PlasticMomentCapacityOfCantilever) {
  // A cantilever pushed past yield: the base moment follows the closed-form EPP moment-curvature
  // M = Mp [1 - (1/3)(phi_y/phi)^2] at the base section's curvature, and the tip force is M/L.
  const auto mat = plastic();
  const auto sec = rect<2>(*mat);
  ForceBeamColumn2d f(1, 1, 2, points<2>(*sec, 5), std::make_unique<LinearTransf2d>(1), 0.0, 50);
  f.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
  const double mp = kFy * kB * kH * kH / 4;
  // Impose tip displacement with the tip rotation chosen so the tip moment vanishes:
  // iterate the free rotation with Newton on the element alone.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  for (int step = 1; step <= 20; ++step) {
    u(4) = 0.1 * step / 20;
    for (int it = 0; it < 50; ++it) {
      TrialState s{u, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
      const Status st = f.update(s.kinematics());
      ASSERT_TRUE(ok(st)) << step << " " << it << " " << code(st) << " " << u.transpose();
      const double r = f.resistingForce()(5);
      if (std::abs(r) < 1e-8 * mp) break;
      u(5) -= r / f.tangentStiff()(5, 5);
    }
    f.commitState();
  }
  const auto base = f.response(std::vector<std::string>{"section", "1", "deformation"});
  ASSERT_TRUE(base.has_value());
  const double phi = std::abs((*base)(1)), phiY = 2 * kFy / kE / kH;
  ASSERT_GT(phi, 2 * phiY);
  const double expected = mp * (1 - phiY * phiY / (3 * phi * phi));
  EXPECT_NEAR(std::abs(f.basicForce()(1)), expected, 5e-3 * mp);  // 20-fiber discretisation
  EXPECT_NEAR(f.resistingForce()(4), std::abs(f.basicForce()(1)) / kL, 1e-6 * mp);
  // Basic deformation bookkeeping: section forces follow the linear moment diagram.
  const auto m1 = f.response(std::vector<std::string>{"section", "1", "force"});
  ASSERT_TRUE(m1.has_value());
  EXPECT_NEAR((*m1)(1), -f.basicForce()(1), 1e-9 * mp);
}

TEST(ForceBeamColumnTest, ReportsNonConvergenceInsteadOfHanging) {
  // A fully plastic section (no elastic core) has a singular tangent: the element must return a
  // failure status.
  const auto mat = plastic();
  const auto sec = rect<2>(*mat);
  ForceBeamColumn2d f(1, 1, 2, points<2>(*sec, 3), std::make_unique<LinearTransf2d>(1), 0.0);
  f.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0, 0)});
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u(3) = 0.1;  // axial strain 0.033 >> yield everywhere
  TrialState s{u, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
  EXPECT_FALSE(ok(f.update(s.kinematics())));
  f.revertToLastCommit();
  EXPECT_EQ(f.resistingForce().norm(), 0.0);
}

// -cMass: the consistent mass of Przemieniecki (1968, eq. 11.42), rotated to global axes. Checks:
// total translational mass m L along each global direction (rigid translation: 1^T M 1), the
// closed-form 156/420 m L diagonal on a transverse dof for an axis-aligned member, and symmetry.
TEST(ForceBeamColumnTest, ConsistentMassSumsToTotalMassAndMatchesClosedForm) {
  constexpr double kMassTol = 1e-12;
  const auto mat = elastic();
  const auto sec = rect<3>(*mat);
  const double rho = 2.5;  // mass per length
  ForceBeamColumn3d e(1, 1, 2, points<3>(*sec, 4),
                      std::make_unique<LinearTransf3d>(1, Eigen::Vector3d(0.0, 0.0, 1.0)), rho);
  e.setConsistentMass(true);
  const Eigen::Vector3d xi(0.5, 1.0, -1.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(2.0, 1.0, 2.0) / 3.0;
  e.initialize({xi, Eigen::Vector3d(xi + kL * axis)});
  const Eigen::MatrixXd m = e.mass();
  for (int d = 0; d < 3; ++d) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(12);
    r(d) = r(d + 6) = 1.0;
    EXPECT_NEAR(r.dot(m * r), rho * kL, kMassTol * rho * kL) << "direction " << d;
  }
  EXPECT_LT((m - m.transpose()).norm(), kMassTol * m.norm());
  DispBeamColumn2d d2(2, 1, 2, points<2>(*rect<2>(*mat), 3), std::make_unique<LinearTransf2d>(1),
                      rho);
  d2.setConsistentMass(true);
  d2.initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d(kL, 0.0, 0.0)});
  EXPECT_NEAR(d2.mass()(1, 1), 156.0 / 420.0 * rho * kL, kMassTol * rho * kL);
  EXPECT_NEAR(d2.mass()(2, 2), 4.0 / 420.0 * rho * kL * kL * kL, kMassTol * rho * kL * kL * kL);
  EXPECT_NEAR(d2.mass()(0, 3), 70.0 / 420.0 * rho * kL, kMassTol * rho * kL);
}

}  // namespace
}  // namespace dabs::elements
