// SPDX-License-Identifier: MIT
#include "elements/link/Truss.h"

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

std::unique_ptr<Truss> makeTruss(std::unique_ptr<materials::UniaxialMaterial> m, double rho = 0.0,
                                 bool consistent = false, bool corotational = false) {
  Truss::Params p;
  p.corotational = corotational;
  p.nodes = {1, 2};
  p.ndm = 3;
  p.ndf = 3;
  p.area = 2.0;
  p.rho = rho;
  p.consistentMass = consistent;
  p.validate();
  auto t = std::make_unique<Truss>(1, p, std::move(m));
  t->initialize({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(3, 4, 0)});  // L = 5
  return t;
}

std::unique_ptr<materials::UniaxialMaterial> elastic(double E) {
  materials::Elastic::Params p;
  p.E = E;
  return std::make_unique<materials::Elastic>(1, p);
}

TEST(TrussTest, AxialForceIsEAOverLTimesElongation) {
  auto tp = makeTruss(elastic(100.0));
  Truss& t = *tp;
  testing::TrialState s{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                        Eigen::VectorXd::Zero(6)};
  s.u(3) = 0.3;  // node j moves 0.3 along x: elongation 0.3 * 3/5
  ASSERT_TRUE(ok(t.update(s.kinematics())));
  const double N = 100.0 * 2.0 / 5.0 * 0.18;  // EA/L * elongation
  EXPECT_NEAR((*t.response(std::vector<std::string>{"axialForce"}))(0), N, kExact);
  EXPECT_NEAR(t.resistingForce()(3), N * 0.6, kExact);
  EXPECT_NEAR(t.resistingForce()(4), N * 0.8, kExact);
  EXPECT_NEAR((*t.response(std::vector<std::string>{"deformation"}))(0), 0.18, kExact);
}

TEST(TrussTest, TangentMatchesFiniteDifferenceWhileYielding) {
  materials::Steel02::Params p;
  p.Fy = 1.0;
  p.E = 100.0;
  p.b = 0.02;
  auto tp = makeTruss(std::make_unique<materials::Steel02>(1, p));
  Truss& t = *tp;
  testing::TrialState s{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                        Eigen::VectorXd::Zero(6)};
  s.u << 0.0, 0.01, 0.0, 0.1, 0.05, 0.02;
  ASSERT_TRUE(ok(t.update(s.kinematics())));
  EXPECT_LT(testing::relativeDifference(t.tangentStiff(), testing::numericalStiffness(t, s, 1e-8)),
            kTangentTolerance);
}

TEST(TrussTest, MassSumsToRhoL) {
  auto lumpedp = makeTruss(elastic(1.0), 2.0, false);
  Truss& lumped = *lumpedp;
  auto consistentp = makeTruss(elastic(1.0), 2.0, true);
  Truss& consistent = *consistentp;
  // Total translational mass in x: r^T M r with r = 1 at both x dofs = rho L = 10.
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6);
  r(0) = r(3) = 1.0;
  EXPECT_NEAR(r.dot(lumped.mass() * r), 10.0, kExact);
  EXPECT_NEAR(r.dot(consistent.mass() * r), 10.0, kExact);
}

TEST(TrussTest, BadInputIsRejected) {
  Truss::Params p;
  p.nodes = {1, 2};
  p.area = -1.0;
  EXPECT_THROW(p.validate(), InputError);
  p.area = 1.0;
  p.rho = -1.0;
  EXPECT_THROW(p.validate(), InputError);
  p.rho = 0.0;
  p.validate();
  Truss t(1, p, elastic(1.0));
  EXPECT_THROW(t.initialize({Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 1)}), InputError);
}

TEST(TrussTest, CorotationalTrussRotatesRigidlyWithoutForce) {
  // A rigid rotation by 90 degrees about z (node j from (3, 4, 0) to (-4, 3, 0)) leaves the
  // length, hence the force, at zero; the small-displacement truss would stretch.
  auto t = makeTruss(elastic(100.0), 0.0, false, true);
  testing::TrialState s{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                        Eigen::VectorXd::Zero(6)};
  s.u(3) = -7.0;
  s.u(4) = -1.0;
  ASSERT_TRUE(ok(t->update(s.kinematics())));
  EXPECT_LT(t->resistingForce().norm(), kExact);
  EXPECT_EQ(t->typeName(), "corotTruss");
}

TEST(TrussTest, CorotationalTrussForceFollowsTheDeformedAxis) {
  // Node j moved to (0, 10, 0): length 10, engineering strain (10 - 5)/5 = 1, force A E along
  // the new axis (global y).
  auto t = makeTruss(elastic(100.0), 0.0, false, true);
  testing::TrialState s{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                        Eigen::VectorXd::Zero(6)};
  s.u(3) = -3.0;
  s.u(4) = 6.0;
  ASSERT_TRUE(ok(t->update(s.kinematics())));
  const double n = 2.0 * 100.0 * 1.0;
  EXPECT_NEAR(t->resistingForce()(4), n, kExact * n);
  EXPECT_NEAR(t->resistingForce()(1), -n, kExact * n);
  EXPECT_NEAR(t->resistingForce()(3), 0.0, kExact * n);
}

TEST(TrussTest, CorotationalTrussTangentMatchesFiniteDifferences) {
  materials::Steel02::Params p;
  p.Fy = 3.0;
  p.E = 100.0;
  p.b = 0.02;
  p.validate();
  auto t = makeTruss(std::make_unique<materials::Steel02>(1, p), 0.0, false, true);
  testing::TrialState s{Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6),
                        Eigen::VectorXd::Zero(6)};
  s.u << 0.1, -0.2, 0.05, -1.5, 0.8, 0.4;  // large rotation and stretch past yield
  ASSERT_TRUE(ok(t->update(s.kinematics())));
  const Eigen::MatrixXd k = t->tangentStiff();
  EXPECT_LT(testing::relativeDifference(k, testing::numericalStiffness(*t, s, 1e-7)),
            kTangentTolerance);
  EXPECT_LT((k - k.transpose()).norm(), 1e-12 * k.norm());
}

}  // namespace
}  // namespace dabs::elements
