// SPDX-License-Identifier: MIT
#include "elements/link/ZeroLength.h"

#include <gtest/gtest.h>

#include <cmath>

#include "elements/tests/ElementChecks.h"
#include "materials/Elastic.h"
#include "materials/InputError.h"
#include "materials/Steel02.h"

namespace dabs::elements {
namespace {

constexpr double kTangentTolerance = 1e-6;
constexpr double kExact = 1e-12;

std::unique_ptr<materials::UniaxialMaterial> elastic(double E, double eta = 0.0) {
  materials::Elastic::Params p;
  p.E = E;
  p.eta = eta;
  return std::make_unique<materials::Elastic>(1, p);
}

std::unique_ptr<materials::UniaxialMaterial> steel() {
  materials::Steel02::Params p;
  p.Fy = 1.0;
  p.E = 100.0;
  p.b = 0.05;
  return std::make_unique<materials::Steel02>(2, p);
}

std::unique_ptr<ZeroLength> make3d(std::vector<int> dirs,
                                   std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats,
                                   Eigen::Vector3d x = {1, 0, 0}, Eigen::Vector3d yp = {0, 1, 0}) {
  ZeroLength::Params p;
  p.nodes = {1, 2};
  p.ndm = 3;
  p.ndf = 6;
  p.dirs = std::move(dirs);
  p.x = x;
  p.yp = yp;
  p.validate(mats.size());
  auto e = std::make_unique<ZeroLength>(1, p, std::move(mats));
  e->initialize({Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()});
  return e;
}

TEST(ZeroLengthTest, ForceIsStiffnessTimesProjectedRelativeDisplacement) {
  // Local x along (1,1,0)/sqrt2: a relative displacement (1, 0, 0) deforms it by 1/sqrt2.
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(elastic(10.0));
  auto ep = make3d({1}, std::move(mats), {1, 1, 0}, {-1, 1, 0});
  ZeroLength& e = *ep;
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.u(6) = 1.0;
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  const double d = 1.0 / std::sqrt(2.0);
  const double force = 10.0 * d;
  EXPECT_NEAR(e.resistingForce()(6), force * d, kExact);
  EXPECT_NEAR(e.resistingForce()(7), force * d, kExact);
  EXPECT_NEAR(e.resistingForce()(0), -force * d, kExact);
  EXPECT_NEAR((*e.response(std::vector<std::string>{"deformation"}))(0), d, kExact);
  EXPECT_NEAR(e.resistingForce().sum(), 0.0, kExact);  // equilibrium
}

TEST(ZeroLengthTest, RotationalDirectionActsOnRotations) {
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(elastic(5.0));
  auto ep = make3d({6}, std::move(mats));
  ZeroLength& e = *ep;  // rotation about local z = global Z
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.u(11) = 0.2;
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  EXPECT_NEAR(e.resistingForce()(11), 1.0, kExact);
  EXPECT_NEAR(e.resistingForce()(5), -1.0, kExact);
}

TEST(ZeroLengthTest, TangentMatchesFiniteDifferenceWhileYielding) {
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(steel());
  mats.push_back(steel());
  mats.push_back(elastic(30.0));
  auto ep = make3d({1, 2, 4}, std::move(mats), {0.6, 0.8, 0.0}, {0.0, 0.0, 1.0});
  ZeroLength& e = *ep;
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.u << 0.001, -0.002, 0.0, 0.01, 0.0, 0.0, 0.03, 0.02, 0.01, -0.02, 0.0, 0.0;
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  const Eigen::MatrixXd k = e.tangentStiff();
  const Eigen::MatrixXd kfd = testing::numericalStiffness(e, s, 1e-8);
  EXPECT_LT(testing::relativeDifference(k, kfd), kTangentTolerance);
}

TEST(ZeroLengthTest, MaterialDashpotGivesDampingTangent) {
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(elastic(10.0, 3.0));
  auto ep = make3d({2}, std::move(mats));
  ZeroLength& e = *ep;
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.v(7) = 0.5;
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  EXPECT_NEAR(e.resistingForce()(7), 1.5, kExact);  // eta * relative velocity
  const Eigen::MatrixXd cfd = testing::numericalDamping(e, s, 1e-6);
  EXPECT_LT(testing::relativeDifference(e.dampingTangent(), cfd), kTangentTolerance);
}

TEST(ZeroLengthTest, RevertRestoresCommittedMaterialState) {
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(steel());
  auto ep = make3d({1}, std::move(mats));
  ZeroLength& e = *ep;
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.u(6) = 0.05;  // yields
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  e.revertToLastCommit();
  EXPECT_NEAR(e.resistingForce().norm(), 0.0, kExact);
}

// The analysis skips an element that says it keeps its state while no node moved (a transient
// step's predictor). A zeroLength says so after an update when all its laws keep their state at
// the same strain (Steel02, Elastic without damping), and an update at the same displacements
// then gives the same force and tangent, bit for bit, before and after a commit; a revert ends
// it; a dashpot (Elastic with eta) never says so.
TEST(ZeroLengthTest, KeepsItsStateAtTheSameDisplacementsOnlyWhenItsLawsDo) {
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
  mats.push_back(steel());
  mats.push_back(elastic(30.0));
  auto ep = make3d({1, 2}, std::move(mats), {0.6, 0.8, 0.0}, {0.0, 0.0, 1.0});
  ZeroLength& e = *ep;
  testing::TrialState s{Eigen::VectorXd::Zero(12), Eigen::VectorXd::Zero(12),
                        Eigen::VectorXd::Zero(12)};
  s.u << 0.001, -0.002, 0.0, 0.0, 0.0, 0.0, 0.05, 0.02, 0.0, 0.0, 0.0, 0.0;  // yields
  EXPECT_FALSE(e.keepsStateAtSameDisplacements());
  ASSERT_TRUE(ok(e.update(s.kinematics())));
  EXPECT_TRUE(e.keepsStateAtSameDisplacements());
  const Eigen::VectorXd force = e.resistingForce();
  const Eigen::MatrixXd tangent = e.tangentStiff();
  for (const bool commit : {false, true}) {
    if (commit) e.commitState();
    EXPECT_TRUE(e.keepsStateAtSameDisplacements());
    ASSERT_TRUE(ok(e.update(s.kinematics())));
    EXPECT_EQ(e.resistingForce(), force);
    EXPECT_EQ(e.tangentStiff(), tangent);
  }
  e.revertToLastCommit();
  EXPECT_FALSE(e.keepsStateAtSameDisplacements());

  std::vector<std::unique_ptr<materials::UniaxialMaterial>> damped;
  damped.push_back(elastic(10.0, 3.0));
  auto dashpot = make3d({2}, std::move(damped));
  ASSERT_TRUE(ok(dashpot->update(s.kinematics())));
  EXPECT_FALSE(dashpot->keepsStateAtSameDisplacements());
}

TEST(ZeroLengthTest, BadInputIsRejected) {
  ZeroLength::Params p;
  p.nodes = {1, 2};
  p.ndm = 2;
  p.ndf = 3;
  p.dirs = {4};
  EXPECT_THROW(p.validate(1), InputError);  // 2D with 3 dofs carries dirs 1..3
  p.dirs = {1, 2};
  EXPECT_THROW(p.validate(1), InputError);  // one direction per material
  p.dirs = {1};
  p.yp = p.x;
  EXPECT_THROW(p.validate(1), InputError);  // yp parallel to x
  p.yp = {0, 1, 0};
  p.ndf = 5;
  EXPECT_THROW(p.validate(1), InputError);  // unsupported dofs per node
}

}  // namespace
}  // namespace dabs::elements
