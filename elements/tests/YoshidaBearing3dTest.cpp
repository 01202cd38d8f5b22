// SPDX-License-Identifier: MIT
// Over 400 lines: one test file for the bearing element, each test a separate check.
// Checks of the yoshidaBearing element: geometry, equilibrium, rigid-body motion,
// FD tangents, damage by shear strain, failure handling, mass, and Newton convergence on a
// bearing-mass oscillator under the Takatori record.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "elements/link/YoshidaBearing3d.h"
#include "elements/tests/ElementChecks.h"
#include "materials/bearing/YoshidaBearingMaterial.h"

namespace dabs::elements {
namespace {

using testing::TrialState;
using Mat = materials::YoshidaBearingMaterial;
using Vec = Eigen::VectorXd;

constexpr double kY0 = 300.0;     // kN
constexpr double kU0 = 0.02;      // m
constexpr double kTr = 0.2;       // m
constexpr double kKv = 2.0e6;     // kN/m
constexpr double kKt = 500.0;     // kN m/rad
constexpr double kKry = 8000.0;   // kN m/rad, about local y
constexpr double kKrz = 20000.0;  // kN m/rad, about local z
constexpr double kFdRelTol = 1e-5;
constexpr double kZeroForce = 1e-9;  // kN, rigid-body force tolerance

Mat::Params material(bool full) {
  Mat::Params p;
  p.Y0 = kY0;
  p.U0 = kU0;
  p.n = 2.0;
  if (full) {
    p.alpha0 = 0.2;
    p.beta = 0.01;
    p.q = 1.2;
    p.gamma = 0.01;
    p.k = 1000.0;
    p.eta = 200.0;
  }
  return p;
}

YoshidaBearing3d::Params element() {
  YoshidaBearing3d::Params p;
  p.Tr = kTr;
  p.Kv = kKv;
  p.Kt = kKt;
  p.Kry = kKry;
  p.Krz = kKrz;
  return p;
}

TrialState zeroState(double dt = 0.0) {
  TrialState s;
  s.u = Vec::Zero(12);
  s.v = Vec::Zero(12);
  s.a = Vec::Zero(12);
  s.dt = dt;
  return s;
}

std::unique_ptr<YoshidaBearing3d> make(const NodalCoordinates& x, bool full = false,
                                       YoshidaBearing3d::Params p = element()) {
  p.validate();
  const Mat m(1, material(full));
  auto e = std::make_unique<YoshidaBearing3d>(1, 1, 2, m, p);
  e->initialize(x);
  return e;
}

const NodalCoordinates kCoincidentNodes = {Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1, 2, 3)};
const NodalCoordinates kInclined = {Eigen::Vector3d(0.5, -1.0, 2.0),
                                    Eigen::Vector3d(0.7, -0.8, 2.3)};

/// Six rigid-body motions (small rotations about the origin) of the two nodes.
std::vector<Vec> rigidModes(const NodalCoordinates& x) {
  std::vector<Vec> modes;
  for (int k = 0; k < 3; ++k) {
    Vec t = Vec::Zero(12);
    t(k) = t(6 + k) = 1.0;
    modes.push_back(t);
    Vec r = Vec::Zero(12);
    const Eigen::Vector3d th = Eigen::Vector3d::Unit(k);
    for (int node = 0; node < 2; ++node) {
      r.segment<3>(6 * node) = th.cross(x[node]);
      r.segment<3>(6 * node + 3) = th;
    }
    modes.push_back(r);
  }
  return modes;
}

TEST(YoshidaBearing3dTest, DefaultAxesForCoincidentNodes) {
  auto e = make(kCoincidentNodes);
  // local x = global Z, local y = global X, z = x cross y = global Y
  EXPECT_EQ(e->axes(), (Eigen::Matrix3d() << 0, 0, 1, 1, 0, 0, 0, 1, 0).finished());
  TrialState s = zeroState();
  const double d = 1e-6;  // elastic range
  s.u(6) = d;             // node j along global X: shear in local y
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const Vec def = *e->response(std::vector<std::string>{"deformation"});
  EXPECT_DOUBLE_EQ(def(1), d);
  EXPECT_NEAR(e->resistingForce()(6), kY0 / kU0 * d, 1e-6 * kY0 / kU0 * d);
  s.u.setZero();
  s.u(8) = d;  // global Z: axial
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->resistingForce()(8), kKv * d, 1e-9 * kKv * d);
  EXPECT_NEAR(e->resistingForce()(2), -kKv * d, 1e-9 * kKv * d);
}

TEST(YoshidaBearing3dTest, RockingStiffnessPerLocalAxis) {
  // Coincident nodes: local y = global X, local z = global Y. A relative rotation theta of node j
  // about global X is rocking about local y (M = Kry theta), about global Y rocking about local z
  // (M = Krz theta); no shear, so no other force.
  auto e = make(kCoincidentNodes);
  TrialState s = zeroState();
  const double theta = 1e-4;
  s.u(9) = theta;  // node j, rotation about global X
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->resistingForce()(9), kKry * theta, 1e-12 * kKry);
  EXPECT_NEAR(e->resistingForce()(3), -kKry * theta, 1e-12 * kKry);
  s.u.setZero();
  s.u(10) = theta;  // about global Y
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->resistingForce()(10), kKrz * theta, 1e-12 * kKrz);
  EXPECT_NEAR(e->resistingForce()(9), 0.0, 1e-12 * kKrz);
}

TEST(YoshidaBearing3dTest, ShearMomentIsSharedBetweenEnds) {
  const double h = 0.4;  // vertical bearing of height h
  auto e = make({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, h)});
  TrialState s = zeroState();
  s.u(6) = 0.05;  // top moves along global X by 2.5 U0
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const Vec f = e->resistingForce();
  const double v = f(6);
  EXPECT_GT(v, 0.5 * kY0);
  EXPECT_NEAR(f(0), -v, 1e-12 * v);
  // The shear pair (+V at the top, -V at the bottom) has moment +V h about global Y; the end
  // moments balance it, each -V h / 2 (the moment shared equally between the ends).
  EXPECT_NEAR(f(4), -v * h / 2, 1e-12 * v);
  EXPECT_NEAR(f(10), -v * h / 2, 1e-12 * v);
}

TEST(YoshidaBearing3dTest, RigidBodyMotionGivesNoForceAndForcesBalance) {
  for (const auto& x : {kCoincidentNodes, kInclined}) {
    auto e = make(x, true);
    for (const Vec& mode : rigidModes(x)) {
      TrialState s = zeroState(0.01);
      s.u = 1e-3 * mode;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      EXPECT_LT(e->resistingForce().norm(), kZeroForce);
      EXPECT_LT((e->tangentStiff() * mode).norm(), 1e-8 * e->tangentStiff().norm());
      EXPECT_LT((e->initialStiff() * mode).norm(), 1e-8 * e->initialStiff().norm());
    }
    // A general deformed state: resultant force and moment (about the origin) vanish.
    TrialState s = zeroState(0.01);
    s.u << 0.01, -0.02, 0.001, 0.01, -0.02, 0.03, 0.05, 0.01, -0.002, -0.01, 0.02, 0.04;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    const Vec f = e->resistingForce();
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
    for (int node = 0; node < 2; ++node) {
      force += f.segment<3>(6 * node);
      moment += x[node].cross(Eigen::Vector3d(f.segment<3>(6 * node))) + f.segment<3>(6 * node + 3);
    }
    EXPECT_LT(force.norm(), 1e-9 * f.norm());
    EXPECT_LT(moment.norm(), 1e-9 * f.norm());
  }
}

TEST(YoshidaBearing3dTest, TangentMatchesFiniteDifference) {
  for (const auto& x : {kCoincidentNodes, kInclined}) {
    for (bool full : {false, true}) {
      auto e = make(x, full);
      const double dt = full ? 0.01 : 0.0;
      // loading from the virgin state
      TrialState s = zeroState(dt);
      s.u << 0.001, 0.002, -0.001, 0.002, 0.001, -0.003, 0.03, -0.02, 0.001, 0.001, -0.002, 0.004;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      Eigen::MatrixXd k = e->tangentStiff();
      EXPECT_LT(testing::relativeDifference(k, testing::numericalStiffness(*e, s, 1e-8)), kFdRelTol)
          << "loading, full = " << full;
      e->commitState();
      // unloading
      TrialState s2 = s;
      s2.u.segment<3>(6) *= 0.4;
      ASSERT_TRUE(ok(e->update(s2.kinematics())));
      k = e->tangentStiff();
      EXPECT_LT(testing::relativeDifference(k, testing::numericalStiffness(*e, s2, 1e-8)),
                kFdRelTol)
          << "unloading, full = " << full;
      // near a zero increment
      TrialState s3 = s;
      s3.u(6) += 2e-6;
      s3.u(7) -= 1e-6;
      ASSERT_TRUE(ok(e->update(s3.kinematics())));
      k = e->tangentStiff();
      EXPECT_LT(testing::relativeDifference(k, testing::numericalStiffness(*e, s3, 1e-10)),
                kFdRelTol)
          << "near zero increment, full = " << full;
      // the element's own damping tangent is zero: the Maxwell force depends on u, not v
      EXPECT_LT(testing::numericalDamping(*e, s3, 1e-6).norm(), 1e-9);
    }
  }
}

TEST(YoshidaBearing3dTest, DamageFlagAtExactlyFailureStrainInObliqueDirection) {
  auto e = make(kCoincidentNodes);
  const double angle = 0.7;  // oblique in the shear plane (global X-Y for default axes)
  const Eigen::Vector3d dir(std::cos(angle), std::sin(angle), 0.0);
  auto setShear = [&](double strain, double time) {
    TrialState s = zeroState();
    s.time = time;
    s.u.segment<3>(6) = strain * kTr * dir;
    EXPECT_TRUE(ok(e->update(s.kinematics())));
  };
  std::vector<std::string> name{"damage"};
  setShear(2.4, 1.0);
  EXPECT_EQ((*e->response(name))(0), 0);
  e->commitState();
  setShear(2.5, 2.0);  // design limit
  EXPECT_EQ((*e->response(name))(0), 1);
  e->commitState();
  setShear(2.0, 3.0);  // damage does not heal
  EXPECT_EQ((*e->response(name))(0), 1);
  e->commitState();
  setShear(3.0, 4.0);  // |U| = 3 Tr exactly
  EXPECT_EQ((*e->response(name))(0), 2);
  EXPECT_NEAR((*e->response(std::vector<std::string>{"shearStrain"}))(0), 3.0, 1e-12);
  EXPECT_EQ((*e->response(std::vector<std::string>{"failureTime"}))(0), 4.0);
  e->commitState();
  setShear(1.0, 5.0);
  EXPECT_EQ((*e->response(name))(0), 2);
  EXPECT_EQ((*e->response(std::vector<std::string>{"failureTime"}))(0), 4.0);
}

TEST(YoshidaBearing3dTest, RevertedTrialDoesNotFail) {
  auto e = make(kCoincidentNodes);
  TrialState s = zeroState();
  s.u(6) = 3.2 * kTr;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->damage(), 2);
  e->revertToLastCommit();
  s.u(6) = 0.5 * kTr;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->damage(), 0);
  EXPECT_EQ(e->trialState().failureTime, -1.0);
}

TEST(YoshidaBearing3dTest, AfterFailureReleaseDropsShearOnlyAfterCommit) {
  for (auto mode :
       {YoshidaBearing3d::AfterFailure::Keep, YoshidaBearing3d::AfterFailure::Release}) {
    YoshidaBearing3d::Params p = element();
    p.afterFailure = mode;
    auto e = make(kCoincidentNodes, false, p);
    TrialState s = zeroState();
    s.u(7) = 3.1 * kTr;
    s.u(8) = 1e-4;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_GT(std::abs(e->resistingForce()(7)), 0.5 * kY0);  // failing step keeps its force
    e->commitState();
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    const bool release = mode == YoshidaBearing3d::AfterFailure::Release;
    if (release) {
      EXPECT_EQ(e->resistingForce()(7), 0.0);
      EXPECT_EQ(e->tangentStiff()(7, 7), 0.0);
    } else {
      EXPECT_GT(std::abs(e->resistingForce()(7)), 0.5 * kY0);
      EXPECT_GT(e->tangentStiff()(7, 7), 0.0);
    }
    EXPECT_NEAR(e->resistingForce()(8), kKv * 1e-4, 1e-9 * kKv);  // axial spring unaffected
    e->revertToStart();
    EXPECT_EQ(e->damage(), 0);
    EXPECT_EQ(e->resistingForce().norm(), 0.0);
  }
}

TEST(YoshidaBearing3dTest, MassIsLumpedOnTranslations) {
  YoshidaBearing3d::Params p = element();
  p.mass = 12.0;
  auto e = make(kInclined, false, p);
  const Eigen::MatrixXd m = e->mass();
  for (int k = 0; k < 3; ++k) {
    EXPECT_DOUBLE_EQ(m(k, k) + m(6 + k, 6 + k), 12.0);
    EXPECT_DOUBLE_EQ(m(3 + k, 3 + k), 0.0);
  }
  EXPECT_DOUBLE_EQ(m.sum(), 36.0);
  EXPECT_FALSE(e->rayleighByDefault());
}

TEST(YoshidaBearing3dTest, ResponsesHaveTheirSizes) {
  auto e = make(kCoincidentNodes, true);
  TrialState s = zeroState(0.01);
  s.u(6) = 0.03;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const std::vector<std::pair<std::string, int>> sizes = {
      {"force", 12},          {"localForce", 12},    {"basicForce", 6}, {"deformation", 6},
      {"shearStrain", 1},     {"maxShearStrain", 1}, {"damage", 1},     {"failureTime", 1},
      {"hystereticForce", 2}, {"viscousForce", 2},   {"backForce", 2},  {"dissipatedEnergy", 1}};
  for (const auto& [name, size] : sizes) {
    const auto r = e->response(std::vector<std::string>{name});
    ASSERT_TRUE(r.has_value()) << name;
    EXPECT_EQ(r->size(), size) << name;
  }
  EXPECT_FALSE(e->response(std::vector<std::string>{"nonsense"}).has_value());
  // shear force = hysteretic + viscous, in local y-z
  const Vec q = *e->response(std::vector<std::string>{"basicForce"});
  const Vec f1 = *e->response(std::vector<std::string>{"hystereticForce"});
  const Vec f2 = *e->response(std::vector<std::string>{"viscousForce"});
  EXPECT_NEAR(q(1), f1(0) + f2(0), 1e-12 * std::abs(q(1)));
}

TEST(YoshidaBearing3dTest, ValidateAndInitializeRejectBadInput) {
  auto expectField = [](const YoshidaBearing3d::Params& p, const std::string& field) {
    try {
      p.validate();
      ADD_FAILURE() << "accepted bad " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field);
    }
  };
  YoshidaBearing3d::Params p = element();
  p.Tr = 0.0;
  expectField(p, "Tr");
  p = element();
  p.Kv = -1.0;
  expectField(p, "Kv");
  p = element();
  p.Kt = -1.0;
  expectField(p, "Kt");
  p = element();
  p.Kry = NAN;
  expectField(p, "Kr");
  p = element();
  p.Krz = -1.0;
  expectField(p, "Kr");
  p = element();
  p.mass = -1.0;
  expectField(p, "mass");
  p = element();
  p.designLimit = 3.5;
  expectField(p, "failure");
  p = element();
  p.orientX = Eigen::Vector3d(0, 0, 1);
  p.orientY = Eigen::Vector3d(0, 0, 2);
  expectField(p, "orient");
  // orient x across the axis of nodes that are apart
  p = element();
  p.orientX = Eigen::Vector3d(1, 0, 0);
  p.orientY = Eigen::Vector3d(0, 1, 0);
  EXPECT_THROW(make({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1)}, false, p), InputError);
  // default y (global X) along the axis falls back to global Y
  auto e = make({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0)});
  EXPECT_EQ(e->axes().row(1), Eigen::RowVector3d(0, 1, 0));
  // orient y parallel to the axis of nodes that are apart
  p = element();
  p.orientX = Eigen::Vector3d(0, 0, 1);
  p.orientY = Eigen::Vector3d(1, 0, 0);
  EXPECT_NO_THROW(make({Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 1)}, false, p));
}

// --- Newton convergence on a bearing-mass oscillator under the Takatori record ------------

std::vector<double> readAt2(const std::string& path, double& dt) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 3; ++i) std::getline(in, line);
  std::getline(in, line);
  const auto p = line.find("DT=");
  dt = std::stod(line.substr(p + 3));
  std::vector<double> a;
  double v;
  while (in >> v) a.push_back(v);
  return a;
}

TEST(YoshidaBearing3dTest, NewtonConvergesQuadraticallyUnderTakatori) {
  double dtRecord = 0.0;
  const std::vector<double> ag =
      readAt2(std::string(DABS_DATA_DIR) + "/RSN1120_KOBE_TAK090.AT2", dtRecord);
  ASSERT_EQ(ag.size(), 4096u);
  ASSERT_DOUBLE_EQ(dtRecord, 0.01);
  auto e = make(kCoincidentNodes, true);
  const double mass = 500.0;  // t; isolated period 2 pi sqrt(M / (K0 c/(1+c))) ~ 2.7 s
  const double g = 9.81;
  const double angle = 0.5;  // direction of the record in the horizontal plane
  const Eigen::Vector2d dir(std::cos(angle), std::sin(angle));
  const double dt = dtRecord;
  // Newmark average acceleration on the two horizontal dofs of node j (global X, Y).
  Eigen::Vector2d u = Eigen::Vector2d::Zero(), v = u, a = u;
  TrialState s = zeroState(dt);
  const double tol = 1e-9 * mass * g;
  constexpr double kResidualFloor = 1e-8;  // kN
  int maxIter = 0;
  std::vector<double> orders;
  for (std::size_t n = 0; n + 1 < 2000; ++n) {
    const Eigen::Vector2d p = -mass * g * ag[n + 1] * dir;
    Eigen::Vector2d un = u;
    std::vector<double> res;
    bool converged = false;
    for (int it = 0; it < 20; ++it) {
      const Eigen::Vector2d an = 4.0 / (dt * dt) * (un - u) - 4.0 / dt * v - a;
      const Eigen::Vector2d vn = v + 0.5 * dt * (a + an);
      s.u.segment<2>(6) = un;
      s.v.segment<2>(6) = vn;
      s.time = static_cast<double>(n + 1) * dt;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      const Eigen::Vector2d r = p - mass * an - e->resistingForce().segment<2>(6);
      res.push_back(r.norm());
      if (r.norm() < tol) {
        converged = true;
        maxIter = std::max(maxIter, it);
        break;
      }
      const Eigen::Matrix2d k = e->tangentStiff().block<2, 2>(6, 6) +
                                4.0 * mass / (dt * dt) * Eigen::Matrix2d::Identity();
      un += k.partialPivLu().solve(r);
    }
    ASSERT_TRUE(converged) << "step " << n;
    if (std::getenv("DABS_PRINT_NEWTON") && res.size() > 3) {
      for (double r : res) std::printf("%.3e ", r);
      std::printf("\n");
    }
    // Convergence order from three successive residuals, the last above the round-off floor
    // (about 1e-10 kN here: 4M/dt^2 = 2e7 kN/m times u ~ 0.1 m times 1e-16).
    for (std::size_t i = 2; i < res.size(); ++i)
      if (res[i] > kResidualFloor && res[i - 1] < res[i - 2])
        orders.push_back(std::log(res[i] / res[i - 1]) / std::log(res[i - 1] / res[i - 2]));
    const Eigen::Vector2d an = 4.0 / (dt * dt) * (un - u) - 4.0 / dt * v - a;
    v = v + 0.5 * dt * (a + an);
    a = an;
    u = un;
    e->commitState();
  }
  EXPECT_GT(e->committedState().maxShearStrain, 0.5);  // the bearing did go well into yield
  EXPECT_LE(maxIter, 6);
  ASSERT_FALSE(orders.empty());
  std::sort(orders.begin(), orders.end());
  // Steps whose iterates cross a kink of the model (|U| passing Umax, reversal) converge more
  // slowly there; the typical (median) step converges quadratically.
  EXPECT_GT(orders[orders.size() / 2], 1.8) << "median observed order";
}

}  // namespace
}  // namespace dabs::elements
