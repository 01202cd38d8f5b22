// SPDX-License-Identifier: MIT
// Tests of ElasticBeam2d with the planar transformations (Linear, PDelta, Corotational):
// closed-form cantilever responses, rigid-body modes, mass sums, finite-difference tangents.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "elements/beam/ElasticBeam2d.h"
#include "elements/tests/ElementChecks.h"
#include "elements/transform/CorotationalTransf2d.h"
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"
#include "materials/InputError.h"

namespace dabs::elements {
namespace {

using testing::TrialState;

constexpr double kTol = 1e-10;    // closed-form checks on linear solves
constexpr double kFdTol = 1e-6;   // finite-difference tangent, relative
constexpr double kFdStep = 1e-7;  // FD perturbation of displacements (lengths ~1)
constexpr double kA = 0.02, kE = 2.0e8, kI = 3.0e-4, kL = 3.0;

ElasticBeam2d::Params params(double mass = 0.0, bool consistent = false) {
  ElasticBeam2d::Params p{kA, kE, kI, mass, consistent};
  p.validate();
  return p;
}

std::unique_ptr<CrdTransf2d> makeTransf(const std::string& type) {
  if (type == "Linear") return std::make_unique<LinearTransf2d>(1);
  if (type == "PDelta") return std::make_unique<PDeltaTransf2d>(1);
  return std::make_unique<CorotationalTransf2d>(1);
}

/// Beam of length kL at angle `angle` from the global X axis, starting at (1, 2).
std::unique_ptr<ElasticBeam2d> makeBeam(const std::string& type, double angle, double mass = 0.0,
                                        bool consistent = false) {
  auto beam = std::make_unique<ElasticBeam2d>(1, 1, 2, params(mass, consistent), makeTransf(type));
  const Eigen::Vector3d xi(1.0, 2.0, 0.0);
  const Eigen::Vector3d xj = xi + kL * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
  beam->initialize({xi, xj});
  return beam;
}

TrialState state(const Eigen::VectorXd& u) {
  return TrialState{u, Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6)};
}

/// Displacements of the free end of a cantilever fixed at node i under end load `p`
/// (global components at node j), from the initial stiffness.
Eigen::Vector3d cantileverTip(const ElasticBeam2d& beam, const Eigen::Vector3d& p) {
  const Eigen::Matrix3d kff = beam.initialStiff().block<3, 3>(3, 3);
  return kff.ldlt().solve(p);
}

TEST(ElasticBeam2dTest, CantileverMatchesBeamTheory) {
  const double angle = 0.7;  // oblique member: the transformation must recover local results
  const auto beamPtr = makeBeam("Linear", angle);
  ElasticBeam2d& beam = *beamPtr;
  const Eigen::Vector2d x(std::cos(angle), std::sin(angle)), y(-std::sin(angle), std::cos(angle));
  const double p = 5.0;
  // Transverse load: delta = P L^3 / 3EI, theta = P L^2 / 2EI.
  Eigen::Vector3d tip = cantileverTip(beam, Eigen::Vector3d(p * y(0), p * y(1), 0.0));
  EXPECT_NEAR(tip.head<2>().dot(y), p * std::pow(kL, 3) / (3 * kE * kI), kTol);
  EXPECT_NEAR(tip(2), p * kL * kL / (2 * kE * kI), kTol);
  // Axial load: P L / EA.
  tip = cantileverTip(beam, Eigen::Vector3d(p * x(0), p * x(1), 0.0));
  EXPECT_NEAR(tip.head<2>().dot(x), p * kL / (kE * kA), kTol);
  EXPECT_NEAR(tip.head<2>().dot(y), 0.0, kTol);
  // End moment: theta = M L / EI.
  tip = cantileverTip(beam, Eigen::Vector3d(0.0, 0.0, p));
  EXPECT_NEAR(tip(2), p * kL / (kE * kI), kTol);
}

TEST(ElasticBeam2dTest, LocalForceFollowsOpenSeesSigns) {
  const auto beamPtr = makeBeam("Linear", 0.0);
  ElasticBeam2d& beam = *beamPtr;
  const double p = 5.0;
  const Eigen::Vector3d tip = cantileverTip(beam, Eigen::Vector3d(0.0, p, 0.0));
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u.tail<3>() = tip;
  ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
  const std::string name = "localForce";
  const Eigen::VectorXd local = *beam.response(std::span(&name, 1));
  // Support reaction -P and moment -P L at i; the load P at j (element end forces).
  Eigen::VectorXd expected(6);
  expected << 0.0, -p, -p * kL, 0.0, p, 0.0;
  EXPECT_LT((local - expected).norm(), 1e-8 * p * kL);
  const std::string global = "globalForce";
  EXPECT_NEAR((*beam.response(std::span(&global, 1)))(4), p, 1e-8 * p);
}

TEST(ElasticBeam2dTest, ThreeRigidBodyModes) {
  const auto beamPtr = makeBeam("Linear", 0.3);
  ElasticBeam2d& beam = *beamPtr;
  const Eigen::MatrixXd k = beam.initialStiff();
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  const Eigen::VectorXd lambda = eig.eigenvalues();  // ascending
  const double scale = lambda.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(lambda(i)), 1e-10 * scale) << i;
  for (int i = 3; i < 6; ++i) EXPECT_GT(lambda(i), 1e-6 * scale) << i;
}

TEST(ElasticBeam2dTest, MassSumsToTotalMass) {
  const double rho = 7.5;
  for (bool consistent : {false, true}) {
    const auto beamPtr = makeBeam("Linear", 0.4, rho, consistent);
    ElasticBeam2d& beam = *beamPtr;
    const Eigen::MatrixXd m = beam.mass();
    for (int dir = 0; dir < 2; ++dir) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(6);
      e(dir) = e(dir + 3) = 1.0;
      EXPECT_NEAR(e.dot(m * e), rho * kL, 1e-12 * rho * kL) << consistent;
    }
    EXPECT_LT((m - m.transpose()).norm(), 1e-12 * m.norm());
    if (!consistent) {
      EXPECT_EQ(m(2, 2), 0.0);
    }  // no rotational mass when lumped (OpenSees)
  }
}

TEST(ElasticBeam2dTest, TangentMatchesFiniteDifferences) {
  Eigen::VectorXd u(6);
  u << 0.01, -0.02, 0.03, -0.004, 0.05, -0.02;
  for (const char* type : {"Linear", "Corotational"}) {
    const auto beamPtr = makeBeam(type, 0.9);
    ElasticBeam2d& beam = *beamPtr;
    const TrialState s = state(u);
    ASSERT_TRUE(ok(beam.update(s.kinematics())));
    const Eigen::MatrixXd k = beam.tangentStiff();
    const Eigen::MatrixXd kfd = testing::numericalStiffness(beam, s, kFdStep);
    EXPECT_LT(testing::relativeDifference(k, kfd), kFdTol) << type;
    EXPECT_LT((k - k.transpose()).norm(), 1e-10 * k.norm()) << type;
  }
}

TEST(ElasticBeam2dTest, PDeltaTangentExactWithoutChordRotation) {
  // Equal transverse end displacements (no chord rotation): the OpenSees P-Delta tangent is the
  // exact derivative of its resisting force.
  const double angle = 0.0;
  const auto beamPtr = makeBeam("PDelta", angle);
  ElasticBeam2d& beam = *beamPtr;
  Eigen::VectorXd u(6);
  u << 0.0, 0.03, 0.01, -0.002, 0.03, -0.02;
  const TrialState s = state(u);
  ASSERT_TRUE(ok(beam.update(s.kinematics())));
  EXPECT_LT(testing::relativeDifference(beam.tangentStiff(),
                                        testing::numericalStiffness(beam, s, kFdStep)),
            kFdTol);
}

TEST(ElasticBeam2dTest, PDeltaTangentOmitsOnlyAxialForceVariation) {
  // With chord rotation, FD - K equals the term OpenSees omits: the local shear pair
  // (1, -1) (ul1 - ul4)/L times d(N)/du = EA/L * (row 0 of B).
  const auto beamPtr = makeBeam("PDelta", 0.0);
  ElasticBeam2d& beam = *beamPtr;
  Eigen::VectorXd u(6);
  u << 0.0, 0.01, 0.0, -0.001, 0.04, 0.0;
  const TrialState s = state(u);
  ASSERT_TRUE(ok(beam.update(s.kinematics())));
  const Eigen::MatrixXd kfd = testing::numericalStiffness(beam, s, kFdStep);
  Eigen::VectorXd shear = Eigen::VectorXd::Zero(6);
  shear(1) = 1.0;
  shear(4) = -1.0;
  Eigen::VectorXd dN = Eigen::VectorXd::Zero(6);
  dN(0) = -kE * kA / kL;
  dN(3) = kE * kA / kL;
  const Eigen::MatrixXd omitted = shear * dN.transpose() * (u(1) - u(4)) / kL;
  EXPECT_LT(testing::relativeDifference(Eigen::MatrixXd(beam.tangentStiff()) + omitted, kfd),
            kFdTol);
}

TEST(ElasticBeam2dTest, PDeltaLateralStiffnessOfCompressedCantilever) {
  // Column along Y under axial compression P: lateral tip stiffness 3EI/L^3 - P/L with the
  // rotation free (condensation of the P-Delta tangent).
  const auto beamPtr = makeBeam("PDelta", std::numbers::pi / 2);
  ElasticBeam2d& beam = *beamPtr;
  const double shortening = 1e-4;  // axial displacement of the top (global -Y)
  const double n = -kE * kA / kL * shortening;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u(4) = -shortening;
  ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
  const Eigen::Matrix3d kff = beam.tangentStiff().block<3, 3>(3, 3);
  const double flex = kff.inverse()(0, 0);  // lateral = global X
  EXPECT_NEAR(1.0 / flex, 3 * kE * kI / std::pow(kL, 3) + n / kL, 1e-9 * kE * kI / std::pow(kL, 3));
  EXPECT_NEAR(beam.basicForce()(0), n, 1e-9 * std::abs(n));
}

TEST(ElasticBeam2dTest, CorotationalRigidRotationIsStressFree) {
  const double angle = 0.4, turn = 1.1;  // a large rigid rotation about node i
  const auto beamPtr = makeBeam("Corotational", angle);
  ElasticBeam2d& beam = *beamPtr;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u(3) = kL * (std::cos(angle + turn) - std::cos(angle));
  u(4) = kL * (std::sin(angle + turn) - std::sin(angle));
  u(2) = u(5) = turn;
  ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
  EXPECT_LT(beam.resistingForce().norm(), 1e-9 * kE * kA);
  // The Linear transformation would see strains under the same motion.
  const auto linearPtr = makeBeam("Linear", angle);
  ElasticBeam2d& linear = *linearPtr;
  ASSERT_TRUE(ok(linear.update(state(u).kinematics())));
  EXPECT_GT(linear.resistingForce().norm(), 1e-3 * kE * kA);
}

TEST(ElasticBeam2dTest, RevertRestoresCommittedForces) {
  const auto beamPtr = makeBeam("Corotational", 0.2);
  ElasticBeam2d& beam = *beamPtr;
  Eigen::VectorXd u1 = Eigen::VectorXd::Zero(6), u2 = Eigen::VectorXd::Zero(6);
  u1(4) = 0.01;
  u2(4) = 0.05;
  ASSERT_TRUE(ok(beam.update(state(u1).kinematics())));
  const Eigen::VectorXd f1 = beam.resistingForce();
  beam.commitState();
  ASSERT_TRUE(ok(beam.update(state(u2).kinematics())));
  EXPECT_GT((beam.resistingForce() - f1).norm(), 1.0);
  beam.revertToLastCommit();
  EXPECT_LT((beam.resistingForce() - f1).norm(), 1e-12 * f1.norm());
  beam.revertToStart();
  EXPECT_EQ(beam.resistingForce().norm(), 0.0);
}

TEST(ElasticBeam2dTest, RejectsBadInput) {
  EXPECT_THROW((ElasticBeam2d::Params{0.0, kE, kI}.validate()), InputError);
  EXPECT_THROW((ElasticBeam2d::Params{kA, kE, kI, -1.0}.validate()), InputError);
  ElasticBeam2d beam(1, 1, 2, params(), std::make_unique<LinearTransf2d>(1));
  const Eigen::Vector3d x(1.0, 1.0, 0.0);
  EXPECT_THROW(beam.initialize({x, x}), InputError);
}

}  // namespace
}  // namespace dabs::elements
