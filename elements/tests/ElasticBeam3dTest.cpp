// SPDX-License-Identifier: MIT
// Tests of ElasticBeam3d with the spatial transformations: closed-form cantilever responses on an
// oblique member, local axes from vecxz, rigid-body modes, mass sums, finite-difference tangents.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>

#include "elements/BeamLoad.h"
#include "elements/beam/ElasticBeam3d.h"
#include "elements/tests/ElementChecks.h"
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"
#include "materials/InputError.h"

namespace dabs::elements {
namespace {

using testing::TrialState;

constexpr double kTol = 1e-10;    // closed-form checks on linear solves
constexpr double kFdTol = 1e-6;   // finite-difference tangent, relative
constexpr double kFdStep = 1e-7;  // FD perturbation
constexpr double kA = 0.02, kE = 2.0e8, kG = 8.0e7, kJ = 5.0e-4, kIy = 2.0e-4, kIz = 3.0e-4;
constexpr double kL = 3.0;

ElasticBeam3d::Params params(double mass = 0.0, bool consistent = false) {
  ElasticBeam3d::Params p{kA, kE, kG, kJ, kIy, kIz, mass, consistent};
  p.validate();
  return p;
}

const Eigen::Vector3d kXi(1.0, -2.0, 0.5);
Eigen::Vector3d axis() { return Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0; }  // unit, oblique
Eigen::Vector3d vecxz() { return Eigen::Vector3d(0.0, 0.0, 1.0); }

std::unique_ptr<ElasticBeam3d> makeBeam(const std::string& type, double mass = 0.0,
                                        bool consistent = false) {
  std::unique_ptr<CrdTransf3d> t;
  if (type == "Linear")
    t = std::make_unique<LinearTransf3d>(1, vecxz());
  else
    t = std::make_unique<PDeltaTransf3d>(1, vecxz());
  auto beam = std::make_unique<ElasticBeam3d>(1, 1, 2, params(mass, consistent), std::move(t));
  beam->initialize({kXi, Eigen::Vector3d(kXi + kL * axis())});
  return beam;
}

TrialState state(const Eigen::VectorXd& u) {
  return TrialState{u, Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12)};
}

/// Free-end displacements of a cantilever fixed at node i under global end load p (6 comps).
Eigen::Matrix<double, 6, 1> tip(const ElasticBeam3d& beam, const Eigen::Matrix<double, 6, 1>& p) {
  const Eigen::Matrix<double, 6, 6> kff = beam.initialStiff().block<6, 6>(6, 6);
  return kff.ldlt().solve(p);
}

Eigen::Matrix<double, 6, 1> force(const Eigen::Vector3d& f, const Eigen::Vector3d& m) {
  Eigen::Matrix<double, 6, 1> p;
  p << f, m;
  return p;
}

TEST(ElasticBeam3dTest, LocalAxesFollowVecxz) {
  const auto beamPtr = makeBeam("Linear");
  ElasticBeam3d& beam = *beamPtr;
  const Eigen::Matrix3d& r = beam.transformation().axes();
  const Eigen::Vector3d x = axis();
  const Eigen::Vector3d y = vecxz().cross(x).normalized();
  EXPECT_LT((r.row(0).transpose() - x).norm(), 1e-14);
  EXPECT_LT((r.row(1).transpose() - y).norm(), 1e-14);
  EXPECT_LT((r.row(2).transpose() - x.cross(y)).norm(), 1e-14);
  EXPECT_GT(r.row(2).dot(vecxz()), 0.0);  // vecxz lies in the x-z plane, on the +z side
}

TEST(ElasticBeam3dTest, CantileverMatchesBeamTheory) {
  const auto beamPtr = makeBeam("Linear");
  ElasticBeam3d& beam = *beamPtr;
  const Eigen::Matrix3d& r = beam.transformation().axes();
  const Eigen::Vector3d x = r.row(0), y = r.row(1), z = r.row(2);
  const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
  const double p = 5.0;
  // Load along local y: bending about z, delta = P L^3/3EIz, rotation about z = P L^2/2EIz.
  auto d = tip(beam, force(p * y, zero));
  EXPECT_NEAR(d.head<3>().dot(y), p * std::pow(kL, 3) / (3 * kE * kIz), kTol);
  EXPECT_NEAR(d.tail<3>().dot(z), p * kL * kL / (2 * kE * kIz), kTol);
  // Load along local z: bending about y, rotation about y = -P L^2/2EIy.
  d = tip(beam, force(p * z, zero));
  EXPECT_NEAR(d.head<3>().dot(z), p * std::pow(kL, 3) / (3 * kE * kIy), kTol);
  EXPECT_NEAR(d.tail<3>().dot(y), -p * kL * kL / (2 * kE * kIy), kTol);
  // Axial PL/EA and torsion TL/GJ.
  d = tip(beam, force(p * x, zero));
  EXPECT_NEAR(d.head<3>().dot(x), p * kL / (kE * kA), kTol);
  d = tip(beam, force(zero, p * x));
  EXPECT_NEAR(d.tail<3>().dot(x), p * kL / (kG * kJ), kTol);
  EXPECT_NEAR(d.head<3>().norm(), 0.0, kTol);
}

TEST(ElasticBeam3dTest, LocalForceFollowsOpenSeesSigns) {
  const auto beamPtr = makeBeam("Linear");
  ElasticBeam3d& beam = *beamPtr;
  const Eigen::Matrix3d& r = beam.transformation().axes();
  const double py = 5.0, pz = 3.0, t = 2.0;
  const Eigen::Vector3d f = py * r.row(1).transpose() + pz * r.row(2).transpose();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.tail<6>() = tip(beam, force(f, t * r.row(0).transpose()));
  ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
  const std::string name = "localForce";
  const Eigen::VectorXd local = *beam.response(std::span(&name, 1));
  // Statics of the cantilever: end j carries the loads; end i the reactions
  // Vy = -Py, Vz = -Pz, T = -T, My_i = +Pz L (about local y), Mz_i = -Py L.
  Eigen::VectorXd expected(12);
  expected << 0.0, -py, -pz, -t, pz * kL, -py * kL, 0.0, py, pz, t, 0.0, 0.0;
  EXPECT_LT((local - expected).norm(), 1e-8 * py * kL);
}

TEST(ElasticBeam3dTest, SixRigidBodyModes) {
  const auto beamPtr = makeBeam("Linear");
  ElasticBeam3d& beam = *beamPtr;
  const Eigen::MatrixXd k = beam.initialStiff();
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k);
  const Eigen::VectorXd lambda = eig.eigenvalues();
  const double scale = lambda.cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(lambda(i)), 1e-10 * scale) << i;
  for (int i = 6; i < 12; ++i) EXPECT_GT(lambda(i), 1e-8 * scale) << i;
}

TEST(ElasticBeam3dTest, MassSumsToTotalMass) {
  const double rho = 7.5;
  for (bool consistent : {false, true}) {
    const auto beamPtr = makeBeam("Linear", rho, consistent);
    ElasticBeam3d& beam = *beamPtr;
    const Eigen::MatrixXd m = beam.mass();
    for (int dir = 0; dir < 3; ++dir) {
      Eigen::VectorXd e = Eigen::VectorXd::Zero(12);
      e(dir) = e(dir + 6) = 1.0;
      EXPECT_NEAR(e.dot(m * e), rho * kL, 1e-12 * rho * kL) << consistent;
    }
    // Rigid twist about the member axis: polar mass rho J/A L with -cMass, none when lumped.
    Eigen::VectorXd twist = Eigen::VectorXd::Zero(12);
    twist.segment<3>(3) = twist.segment<3>(9) = axis();
    EXPECT_NEAR(twist.dot(m * twist), consistent ? rho * kJ / kA * kL : 0.0, 1e-12 * rho * kL);
    EXPECT_LT((m - m.transpose()).norm(), 1e-12 * m.norm());
  }
}

TEST(ElasticBeam3dTest, TangentMatchesFiniteDifferences) {
  Eigen::VectorXd u(12);
  u << 0.01, -0.02, 0.03, -0.004, 0.05, -0.02, 0.003, 0.01, -0.02, 0.01, 0.02, 0.03;
  const auto beamPtr = makeBeam("Linear");
  ElasticBeam3d& beam = *beamPtr;
  const TrialState s = state(u);
  ASSERT_TRUE(ok(beam.update(s.kinematics())));
  EXPECT_LT(testing::relativeDifference(beam.tangentStiff(),
                                        testing::numericalStiffness(beam, s, kFdStep)),
            kFdTol);
}

TEST(ElasticBeam3dTest, PDeltaTangentExactWithoutChordRotation) {
  const auto beamPtr = makeBeam("PDelta");
  ElasticBeam3d& beam = *beamPtr;
  // Same translation at both ends plus an elongation along the axis, and end rotations.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  const Eigen::Vector3d shift(0.01, -0.02, 0.015);
  u.segment<3>(0) = shift;
  u.segment<3>(6) = shift - 2e-4 * axis();
  u.segment<3>(3) << 0.01, -0.02, 0.005;
  u.segment<3>(9) << -0.01, 0.03, 0.002;
  const TrialState s = state(u);
  ASSERT_TRUE(ok(beam.update(s.kinematics())));
  EXPECT_LT(beam.basicForce()(0), 0.0);  // compressed
  const Eigen::MatrixXd k = beam.tangentStiff();
  EXPECT_LT(testing::relativeDifference(k, testing::numericalStiffness(beam, s, kFdStep)), kFdTol);
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
}

TEST(ElasticBeam3dTest, PDeltaLateralStiffnessOfCompressedCantilever) {
  // Lateral stiffness along local y and z of a compressed cantilever: 3EI/L^3 - P/L.
  const auto beamPtr = makeBeam("PDelta");
  ElasticBeam3d& beam = *beamPtr;
  const double shortening = 1e-4;
  const double n = -kE * kA / kL * shortening;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(12);
  u.segment<3>(6) = -shortening * axis();
  ASSERT_TRUE(ok(beam.update(state(u).kinematics())));
  const Eigen::Matrix<double, 6, 6> flex = beam.tangentStiff().block<6, 6>(6, 6).inverse();
  const Eigen::Matrix3d& r = beam.transformation().axes();
  const Eigen::Vector3d y = r.row(1), z = r.row(2);
  const double fy = y.dot(flex.topLeftCorner<3, 3>() * y);
  const double fz = z.dot(flex.topLeftCorner<3, 3>() * z);
  const double scale = 3 * kE * kIy / std::pow(kL, 3);
  EXPECT_NEAR(1.0 / fy, 3 * kE * kIz / std::pow(kL, 3) + n / kL, 1e-9 * scale);
  EXPECT_NEAR(1.0 / fz, 3 * kE * kIy / std::pow(kL, 3) + n / kL, 1e-9 * scale);
}

TEST(ElasticBeam3dTest, RejectsBadGeometry) {
  ElasticBeam3d parallel(1, 1, 2, params(), std::make_unique<LinearTransf3d>(1, axis() * 2.0));
  EXPECT_THROW(parallel.initialize({kXi, Eigen::Vector3d(kXi + kL * axis())}), InputError);
  ElasticBeam3d zero(1, 1, 2, params(), std::make_unique<LinearTransf3d>(1, vecxz()));
  EXPECT_THROW(zero.initialize({kXi, kXi}), InputError);
  EXPECT_THROW((ElasticBeam3d::Params{kA, kE, 0.0, kJ, kIy, kIz}.validate()), InputError);
}

TEST(ElasticBeam3dTest, UpdateAtTheSameDisplacementsFollowsLoadsAndReverts) {
  // The beam keeps its state when updated at the same displacements; what else changes the
  // state (member loads, a revert) must still show. Expected forces: k0 u, plus for a uniform
  // load w along local y the end shears -w L / 2 and end moments -+w L^2 / 12 in local axes.
  auto beam = makeBeam("Linear");
  Eigen::VectorXd u1(12), u2(12);
  for (int i = 0; i < 12; ++i) {
    u1(i) = 1e-4 * (i + 1) * (i % 2 == 0 ? 1.0 : -1.0);
    u2(i) = 2.5 * u1(i);
  }
  const Eigen::MatrixXd k0 = beam->initialStiff();
  auto expectForce = [&](const Eigen::VectorXd& expected) {
    EXPECT_LT((beam->resistingForce() - expected).norm(), kTol * expected.norm());
  };
  ASSERT_TRUE(ok(beam->update(state(u1).kinematics())));
  expectForce(k0 * u1);
  // The analysis forms such a force as k0 u itself while the beam says so: not under a member
  // load, and never under P-Delta (checked at the end).
  EXPECT_TRUE(beam->forceIsInitialStiffnessTimesDisplacements());
  BeamLoad w;
  w.w = Eigen::Vector3d(0.0, 10.0, 0.0);
  beam->addLoad(w, 1.0);
  EXPECT_FALSE(beam->forceIsInitialStiffnessTimesDisplacements());
  ASSERT_TRUE(ok(beam->update(state(u1).kinematics())));    // same displacements, new load
  const Eigen::Matrix3d r = beam->transformation().axes();  // rows: local x, y, z
  Eigen::VectorXd reactions = Eigen::VectorXd::Zero(12);
  const double wl = 10.0 * kL;
  reactions.segment<3>(0) = r.transpose() * Eigen::Vector3d(0.0, -wl / 2, 0.0);
  reactions.segment<3>(3) = r.transpose() * Eigen::Vector3d(0.0, 0.0, -wl * kL / 12);
  reactions.segment<3>(6) = r.transpose() * Eigen::Vector3d(0.0, -wl / 2, 0.0);
  reactions.segment<3>(9) = r.transpose() * Eigen::Vector3d(0.0, 0.0, wl * kL / 12);
  expectForce(k0 * u1 + reactions);
  beam->zeroLoad();
  EXPECT_TRUE(beam->forceIsInitialStiffnessTimesDisplacements());
  ASSERT_TRUE(ok(beam->update(state(u1).kinematics())));
  expectForce(k0 * u1);
  beam->commitState();
  ASSERT_TRUE(ok(beam->update(state(u2).kinematics())));
  expectForce(k0 * u2);
  beam->revertToLastCommit();
  expectForce(k0 * u1);
  ASSERT_TRUE(ok(beam->update(state(u2).kinematics())));
  expectForce(k0 * u2);
  EXPECT_FALSE(makeBeam("PDelta")->forceIsInitialStiffnessTimesDisplacements());
}

}  // namespace
}  // namespace dabs::elements
