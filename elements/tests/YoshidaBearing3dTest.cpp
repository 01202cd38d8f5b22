// SPDX-License-Identifier: MIT
// Over 400 lines: one test file for the bearing element, each test a separate check.
// Checks of the yoshidaBearing element: geometry, equilibrium, rigid-body motion,
// FD tangents, damage by shear strain, failure handling, mass, and Newton convergence on a
// bearing-mass oscillator under the Takatori record.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
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

// --- -afterFailure drop: rupture, drop by h onto a seat with Coulomb friction -------------
// Coincident nodes, node i fixed: local x (axis) = global Z (dof 8 of node j), local y = global
// X (dof 6), local z = global Y (dof 7). The girder's weight W acts at j as a force -W on dof 8.

constexpr double kDropH = 0.15;     // m, bearing height (rubber, plates, sole plate)
constexpr double kSeatKs = 4.0e5;   // kN/m, seat normal stiffness
constexpr double kSeatKst = 1.0e5;  // kN/m, seat stick stiffness
constexpr double kMuS = 0.6;
constexpr double kMuK = 0.4;
constexpr double kWeight = 2000.0;           // kN, girder reaction W
constexpr double kRuptureShear = 3.1 * kTr;  // m, past the failure strain 3.0

YoshidaBearing3d::Params dropParams() {
  YoshidaBearing3d::Params p = element();
  p.afterFailure = YoshidaBearing3d::AfterFailure::Drop;
  p.seat = {kDropH, kSeatKs, kMuS, kMuK, kSeatKst};
  return p;
}

/// A drop-mode bearing with failure committed: sheared to 3.1 Tr along global X with the rubber
/// compressed by W / Kv (the weight on the intact bearing). Returns the state at rupture.
TrialState rupture(YoshidaBearing3d& e) {
  TrialState s = zeroState();
  s.u(6) = kRuptureShear;
  s.u(8) = -kWeight / kKv;
  EXPECT_TRUE(ok(e.update(s.kinematics())));
  EXPECT_EQ(e.damage(), 2);
  // The failing step keeps the rubber's forces (the switch comes in the next step).
  EXPECT_GT(e.resistingForce()(6), 0.5 * kY0);
  EXPECT_NEAR(e.resistingForce()(8), -kWeight, 1e-9 * kWeight);
  EXPECT_FALSE(e.trialState().dropped);
  e.commitState();
  return s;
}

/// Newton solution of node j's translations (global X, Y, Z) for external force `load` with the
/// dofs in `held` fixed at their values in `s`; the element's tangent is used as is.
bool solveStatic(YoshidaBearing3d& e, TrialState& s, const Eigen::Vector3d& load,
                 const std::array<bool, 3>& held) {
  constexpr double kTol = 1e-9;  // kN
  for (int it = 0; it < 30; ++it) {
    if (!ok(e.update(s.kinematics()))) return false;
    Eigen::Vector3d r = load - Eigen::Vector3d(e.resistingForce().segment<3>(6));
    Eigen::Matrix3d k = e.tangentStiff().block<3, 3>(6, 6);
    for (int d = 0; d < 3; ++d)
      if (held[static_cast<std::size_t>(d)]) {
        r(d) = 0.0;
        k.row(d).setZero();
        k.col(d).setZero();
        k(d, d) = 1.0;
      }
    if (r.norm() < kTol) return true;
    s.u.segment<3>(6) += k.partialPivLu().solve(r);
  }
  return false;
}

TEST(YoshidaBearing3dTest, DropLowersNodeJOntoTheSeatByHPlusWOverKs) {
  auto e = make(kCoincidentNodes, false, dropParams());
  TrialState s = rupture(*e);
  // Next step: the rubber carries nothing; at the rupture position the seat is still h - W/Kv
  // below node j (open), so no force at all, shear included.
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_TRUE(e->trialState().dropped);
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(e->tangentStiff().norm(), 0.0);
  EXPECT_DOUBLE_EQ(e->trialState().seatGap, kDropH - kWeight / kKv);
  // Static equilibrium under W with node j's horizontal position free: start just below the
  // seat (in contact, where the tangent is not zero) and let Newton find the solution.
  s.u(8) = -kDropH - 1e-6;
  ASSERT_TRUE(solveStatic(*e, s, Eigen::Vector3d(0, 0, -kWeight), {false, false, false}));
  // Closed form: Ks (h + u_z) = -W, so u_z = -(h + W / Ks); no horizontal force, so j stays
  // where it was at the rupture (the stick point).
  EXPECT_NEAR(s.u(8), -(kDropH + kWeight / kSeatKs), 1e-12);
  EXPECT_NEAR(s.u(6), kRuptureShear, 1e-12);
  EXPECT_NEAR(s.u(7), 0.0, 1e-12);
  const Vec seat = *e->response(std::vector<std::string>{"seatForce"});
  EXPECT_NEAR(seat(0), kWeight, 1e-9 * kWeight);
  EXPECT_NEAR((*e->response(std::vector<std::string>{"seatGap"}))(0), -kWeight / kSeatKs, 1e-12);
  EXPECT_EQ((*e->response(std::vector<std::string>{"seatStatus"}))(0), 1.0);  // stick
  // No torsion or rocking after the drop (the girder rests on a seat point).
  s.u(9) = s.u(10) = s.u(11) = 1e-3;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().segment<3>(9).norm(), 0.0);
  // Tension: lifting j above the seat gives no force (compression only).
  s.u(8) = -kDropH + 0.01;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ((*e->response(std::vector<std::string>{"seatStatus"}))(0), 0.0);
}

TEST(YoshidaBearing3dTest, DroppedGirderSticksBelowMuSWThenSlidesAtMuKW) {
  auto e = make(kCoincidentNodes, false, dropParams());
  TrialState s = rupture(*e);
  s.u(8) = -kDropH - 1e-6;
  ASSERT_TRUE(solveStatic(*e, s, Eigen::Vector3d(0, 0, -kWeight), {false, false, false}));
  e->commitState();
  const double x0 = s.u(6);  // stick point
  const Eigen::Vector3d load(0, 0, -kWeight);
  const std::array<bool, 3> xHeld{true, false, false};  // imposed X, solve Y and Z
  auto tangential = [&] { return e->trialState().seatForce(1); };
  // Stick: just below the static limit the seat holds with Kst times the slip, above mu_k W.
  const double xStick = 0.99 * kMuS * kWeight / kSeatKst;
  s.u(6) = x0 + xStick;
  ASSERT_TRUE(solveStatic(*e, s, load, xHeld));
  EXPECT_FALSE(e->trialState().sliding);
  EXPECT_NEAR(tangential(), -kSeatKst * xStick, 1e-9 * kWeight);
  EXPECT_GT(-tangential(), kMuK * kWeight);
  EXPECT_NEAR(e->trialState().seatForce(0), kWeight, 1e-9 * kWeight);
  // Beyond mu_s W / Kst it slides; the force is mu_k N = mu_k W from then on, step after step.
  const double step = 0.01;
  for (int n = 1; n <= 10; ++n) {
    s.u(6) = x0 + xStick + n * step;
    ASSERT_TRUE(solveStatic(*e, s, load, xHeld)) << "step " << n;
    EXPECT_TRUE(e->trialState().sliding) << "step " << n;
    EXPECT_NEAR(tangential(), -kMuK * kWeight, 1e-9 * kWeight) << "step " << n;
    EXPECT_NEAR(s.u(8), -(kDropH + kWeight / kSeatKs), 1e-12);  // N = W: no vertical coupling
    EXPECT_EQ((*e->response(std::vector<std::string>{"seatStatus"}))(0), 2.0);
    e->commitState();
  }
  // Dissipated work: mu_k W times the plastic slip, the travel beyond the elastic mu_k W / Kst.
  const double travel = xStick + 10 * step;
  EXPECT_NEAR((*e->response(std::vector<std::string>{"seatDissipatedEnergy"}))(0),
              kMuK * kWeight * (travel - kMuK * kWeight / kSeatKst), 1e-9 * kWeight);
  // Reversal: sticks again (elastic unloading with Kst) from the slid-to stick point.
  const double back = 0.5 * kMuK * kWeight / kSeatKst;
  s.u(6) -= back;
  ASSERT_TRUE(solveStatic(*e, s, load, xHeld));
  EXPECT_FALSE(e->trialState().sliding);
  EXPECT_NEAR(tangential(), -kMuK * kWeight + kSeatKst * back, 1e-9 * kWeight);
}

/// Drop of a mass m under gravity from the rupture position onto the seat, Newmark average
/// acceleration on node j's vertical dof, with an external dashpot c (0: undamped). Energy
/// ledger per step (exact for this scheme apart from the steps that open or close the seat):
/// W (u0 - u) = m v^2 / 2 + Ks max(0, -g)^2 / 2 + sum c v_mid^2 dt.
struct DropRun {
  double maxPenetration = 0.0;  // largest -g
  double worstLedger = 0.0;     // largest |energy balance| / (W h)
  double finalU = 0.0, finalV = 0.0;
  double seatEnergy = 0.0, damperWork = 0.0, potentialLost = 0.0;
};

DropRun dropMass(double mass, double c, double dt, double duration, bool stopAtRebound) {
  constexpr double kG = 9.81;
  auto e = make(kCoincidentNodes, false, dropParams());
  const double w = mass * kG;
  TrialState s = zeroState(dt);
  s.u(6) = kRuptureShear;
  s.u(8) = -w / kKv;
  EXPECT_TRUE(ok(e->update(s.kinematics())));
  e->commitState();  // failure committed at rest under W on the intact bearing
  const double u0 = s.u(8);
  double u = u0, v = 0.0;
  EXPECT_TRUE(ok(e->update(s.kinematics())));  // the rubber is gone: f = 0, a = -g
  double a = (-w - e->resistingForce()(8)) / mass;
  DropRun run;
  const int steps = static_cast<int>(std::lround(duration / dt));
  bool landed = false;
  for (int n = 1; n <= steps; ++n) {
    double un = u;
    bool converged = false;
    for (int it = 0; it < 30 && !converged; ++it) {
      const double an = 4.0 / (dt * dt) * (un - u) - 4.0 / dt * v - a;
      const double vn = v + 0.5 * dt * (a + an);
      s.u(8) = un;
      s.v(8) = vn;
      EXPECT_TRUE(ok(e->update(s.kinematics())));
      const double r = -w - mass * an - c * vn - e->resistingForce()(8);
      // Tolerance above the round-off of the inertia term (4 m / dt^2 times u ~ 0.2 m times 1e-16).
      if (std::abs(r) < 1e-7 * w) {
        converged = true;
        break;
      }
      un += r / (e->tangentStiff()(8, 8) + 4.0 * mass / (dt * dt) + 2.0 * c / dt);
    }
    EXPECT_TRUE(converged) << "step " << n;
    const double an = 4.0 / (dt * dt) * (un - u) - 4.0 / dt * v - a;
    const double vn = v + 0.5 * dt * (a + an);
    run.damperWork += c * 0.25 * (v + vn) * (v + vn) * dt;
    u = un, v = vn, a = an;
    e->commitState();
    const double gap = e->committedState().seatGap;
    run.maxPenetration = std::max(run.maxPenetration, -gap);
    run.seatEnergy = 0.5 * kSeatKs * std::pow(std::max(0.0, -gap), 2);
    run.potentialLost = w * (u0 - u);
    const double ledger = run.potentialLost - 0.5 * mass * v * v - run.seatEnergy - run.damperWork;
    run.worstLedger = std::max(run.worstLedger, std::abs(ledger) / (w * kDropH));
    landed = landed || gap < 0.0;
    if (stopAtRebound && landed && v > 0.0 && gap > 0.0) break;
  }
  run.finalU = u;
  run.finalV = v;
  return run;
}

TEST(YoshidaBearing3dTest, DropEnergyBalancesAndTheMassComesToRestOnTheSeat) {
  constexpr double kMass = 200.0;  // t, W = 1962 kN
  constexpr double kG = 9.81;
  constexpr double kLedgerTol = 1e-5;  // of W h; only steps that open or close the seat err
  const double w = kMass * kG;
  const double fall = kDropH - w / kKv;  // free fall from the rupture position to the seat
  // Undamped, until the rebound leaves the seat: no dissipation, so the largest penetration
  // satisfies W (fall + p) = Ks p^2 / 2 (closed form), and the ledger balances at every step.
  const DropRun free = dropMass(kMass, 0.0, 2e-5, 1.0, true);
  const double pMax = w / kSeatKs + std::sqrt(std::pow(w / kSeatKs, 2) + 2.0 * w * fall / kSeatKs);
  EXPECT_NEAR(free.maxPenetration, pMax, 1e-5 * pMax);
  EXPECT_LT(free.worstLedger, kLedgerTol);
  EXPECT_LT(free.damperWork, 1e-300);
  // With a dashpot (20 % of critical on the seat) the mass comes to rest at -(h + W/Ks), and
  // W (fall + W/Ks) = W^2 / (2 Ks) + the dashpot's work.
  const double c = 2.0 * 0.2 * std::sqrt(kSeatKs * kMass);
  const DropRun damped = dropMass(kMass, c, 1e-4, 3.0, false);
  EXPECT_NEAR(damped.finalU, -(kDropH + w / kSeatKs), 1e-9);
  EXPECT_NEAR(damped.finalV, 0.0, 1e-7);
  EXPECT_NEAR(damped.seatEnergy, w * w / (2.0 * kSeatKs), 1e-6 * w * kDropH);
  EXPECT_NEAR(damped.potentialLost, w * (fall + w / kSeatKs), 1e-9 * w * kDropH);
  EXPECT_NEAR(damped.potentialLost, damped.seatEnergy + damped.damperWork, kLedgerTol * w * kDropH);
  EXPECT_LT(damped.worstLedger, kLedgerTol);
  if (std::getenv("DABS_PRINT_DROP"))
    std::printf("free: p %.9g (closed %.9g) ledger %.3g; damped: u %.12g ledger %.3g\n",
                free.maxPenetration, pMax, free.worstLedger, damped.finalU, damped.worstLedger);
}

TEST(YoshidaBearing3dTest, DroppedTangentMatchesFiniteDifference) {
  constexpr double kFdStep = 1e-8;
  for (const auto& x : {kCoincidentNodes, kInclined}) {
    auto e = make(x, false, dropParams());
    // Rupture: shear along local y, then commit; the next step is on the seat.
    const Eigen::Matrix3d R = e->axes();
    TrialState s = zeroState();
    s.u.segment<3>(6) = R.transpose() * Eigen::Vector3d(0.0, kRuptureShear, 0.0);
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    e->commitState();
    const Eigen::Vector3d base(0.0, kRuptureShear, 0.0);  // local position of j at the rupture
    struct Case {
      const char* name;
      Eigen::Vector3d local;  // local (axial, y, z) displacement of j
      Eigen::Vector3d rot;    // rotations of j (global)
      int status;             // expected seatStatus
    };
    const double pen = 0.004;  // penetration into the seat: N = Ks pen = 1600 kN
    const double stick = 0.3 * kMuS * kSeatKs * pen / kSeatKst;
    const double slide = 5.0 * kMuS * kSeatKs * pen / kSeatKst;
    const std::vector<Case> cases = {
        {"open", Eigen::Vector3d(-0.5 * kDropH, 0.01, -0.02), Eigen::Vector3d(0.01, 0, 0), 0},
        {"stick", Eigen::Vector3d(-kDropH - pen, 0.6 * stick, -0.8 * stick),
         Eigen::Vector3d(0.002, -0.001, 0.003), 1},
        {"slide", Eigen::Vector3d(-kDropH - pen, 0.6 * slide, -0.8 * slide),
         Eigen::Vector3d(0.002, -0.001, 0.003), 2},
    };
    for (const Case& c : cases) {
      TrialState t = zeroState();
      t.u.segment<3>(6) = R.transpose() * (base + c.local);
      t.u.segment<3>(9) = c.rot;
      ASSERT_TRUE(ok(e->update(t.kinematics())));
      EXPECT_EQ((*e->response(std::vector<std::string>{"seatStatus"}))(0), c.status) << c.name;
      EXPECT_TRUE(e->hasNonSymmetricTangent());
      const Eigen::MatrixXd k = e->tangentStiff();
      const Eigen::MatrixXd fd = testing::numericalStiffness(*e, t, kFdStep);
      if (c.status == 0) {
        EXPECT_EQ(fd.norm(), 0.0) << c.name;
      } else {
        EXPECT_LT(testing::relativeDifference(k, fd), kFdRelTol) << c.name;
      }
      EXPECT_EQ(k.norm() == 0.0, c.status == 0) << c.name;
      if (c.status == 2) {
        EXPECT_GT((k - k.transpose()).norm(), 1e-3 * k.norm()) << c.name;
      }
      // Rigid-body motions give no force change.
      for (const Vec& mode : rigidModes(x))
        EXPECT_LT((k * mode).norm(), 1e-8 * std::max(1.0, k.norm())) << c.name;
    }
  }
}

TEST(YoshidaBearing3dTest, DroppedStateRoundTripsAndRevertToStartIsIntact) {
  auto e = make(kCoincidentNodes, false, dropParams());
  TrialState s = rupture(*e);
  s.u(8) = -kDropH - 0.004;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->commitState();
  s.u(6) += 0.2;  // slide
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  ASSERT_TRUE(e->trialState().sliding);
  e->commitState();
  const YoshidaBearing3d::State committed = e->committedState();
  const Vec fCommitted = e->resistingForce();
  // A trial that slides further, then reverted: the trial state is the committed one again,
  // stick point included, and updating at the committed displacement gives the committed force.
  TrialState t = s;
  t.u(6) += 0.3;
  t.u(7) -= 0.1;
  ASSERT_TRUE(ok(e->update(t.kinematics())));
  EXPECT_NE(e->trialState().stickPoint, committed.stickPoint);
  e->revertToLastCommit();
  const YoshidaBearing3d::State& r = e->trialState();
  EXPECT_EQ(r.stickPoint, committed.stickPoint);
  EXPECT_EQ(r.sliding, committed.sliding);
  EXPECT_EQ(r.seatForce, committed.seatForce);
  EXPECT_EQ(r.seatDissipated, committed.seatDissipated);
  EXPECT_EQ(r.dropped, committed.dropped);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  // Same displacement from the same committed state; the committed state was sliding, so the
  // kinetic limit applies and the force is mu_k N in the same direction.
  EXPECT_TRUE(e->resistingForce().isApprox(fCommitted, 1e-12));
  // revertToStart: the intact bearing, as a new one.
  e->revertToStart();
  EXPECT_EQ(e->damage(), 0);
  EXPECT_FALSE(e->trialState().dropped);
  EXPECT_FALSE(e->committedState().dropped);
  EXPECT_EQ(e->committedState().stickPoint, Eigen::Vector2d::Zero());
  EXPECT_EQ(e->committedState().seatDissipated, 0.0);
  EXPECT_EQ(e->resistingForce().norm(), 0.0);
  EXPECT_EQ(Eigen::MatrixXd(e->tangentStiff()), Eigen::MatrixXd(e->initialStiff()));
  auto fresh = make(kCoincidentNodes, false, dropParams());
  TrialState intact = zeroState();
  intact.u(6) = 0.03;
  intact.u(8) = -1e-3;
  ASSERT_TRUE(ok(e->update(intact.kinematics())));
  ASSERT_TRUE(ok(fresh->update(intact.kinematics())));
  EXPECT_EQ(e->resistingForce(), fresh->resistingForce());
  EXPECT_EQ(e->tangentStiff(), fresh->tangentStiff());
  EXPECT_FALSE(e->hasNonSymmetricTangent());
}

TEST(YoshidaBearing3dTest, ValidateRejectsBadSeat) {
  auto expectField = [](const YoshidaBearing3d::Params& p, const std::string& field) {
    try {
      p.validate();
      ADD_FAILURE() << "accepted bad " << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field);
    }
  };
  YoshidaBearing3d::Params p = dropParams();
  EXPECT_NO_THROW(p.validate());
  p.seat.h = -0.1;
  expectField(p, "h");
  p = dropParams();
  p.seat.h = NAN;
  expectField(p, "h");
  p = dropParams();
  p.seat.muK = 0.7;  // above mu_s
  expectField(p, "mu_k");
  p = dropParams();
  p.seat.muS = -0.1;
  expectField(p, "mu_s");
  p = dropParams();
  p.seat.Ks = 0.0;
  expectField(p, "Ks");
  p = dropParams();
  p.seat.Kst = -1.0;
  expectField(p, "Kst");
  // The seat is not looked at in the other modes (their behaviour is unchanged).
  p = element();
  p.seat.h = -1.0;
  EXPECT_NO_THROW(p.validate());
}

TEST(YoshidaBearing3dTest, DropResponsesHaveTheirSizes) {
  auto e = make(kCoincidentNodes, false, dropParams());
  TrialState s = zeroState();
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const std::vector<std::pair<std::string, int>> sizes = {{"dropped", 1},
                                                          {"seatGap", 1},
                                                          {"seatForce", 3},
                                                          {"seatStatus", 1},
                                                          {"seatDissipatedEnergy", 1}};
  for (const auto& [name, size] : sizes) {
    const auto r = e->response(std::vector<std::string>{name});
    ASSERT_TRUE(r.has_value()) << name;
    EXPECT_EQ(r->size(), size) << name;
    EXPECT_EQ(r->norm(), 0.0) << name;  // intact: nothing dropped, no seat force
  }
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

// --- the Kumar vertical law (-vertical kumar) ----------------------------------------------

/// The bearing of KumarVerticalTest (kN, m): Do 0.8, Di 0.1, 20 x 10 mm rubber, 3 mm shims.
KumarVertical::Params kumar() {
  KumarVertical::Params v;
  v.G = 800.0;
  v.Kbulk = 2.0e6;
  v.Di = 0.1;
  v.Do = 0.8;
  v.ts = 0.003;
  v.tr = 0.01;
  v.n = 20.0;
  v.kc = 20.0;
  return v;
}

YoshidaBearing3d::Params kumarElement() {
  YoshidaBearing3d::Params p = element();
  p.Tr = 0.0;  // both follow from the geometry
  p.Kv = 0.0;
  p.vertical = kumar();
  return p;
}

TEST(YoshidaBearing3dTest, KumarVerticalReplacesTrAndKvAndFollowsTheLaw) {
  auto e = make(kCoincidentNodes, false, kumarElement());
  const KumarVertical law(kumar());
  ASSERT_NE(e->verticalLaw(), nullptr);
  EXPECT_DOUBLE_EQ(e->params().Tr, 0.2);
  EXPECT_DOUBLE_EQ(e->params().Kv, law.Kv0());
  EXPECT_TRUE(e->hasNonSymmetricTangent());
  // Coincident nodes: local x = global Z (axial), local y = global X. Offset 0.3 m in X, then
  // tension past cavitation: N is the law's at (u, |U|).
  TrialState s = zeroState();
  s.u(6) = 0.3;
  s.u(8) = 0.01;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  const auto r = law.evaluate(0.01, 0.3, {});
  EXPECT_EQ(r.state.branch, 1);
  EXPECT_NEAR(e->trialState().basicForce(0), r.N, 1e-12 * law.Fc());
  EXPECT_NEAR(e->resistingForce()(8), r.N, 1e-12 * law.Fc());
  EXPECT_NEAR((*e->response(std::vector<std::string>{"verticalStiffness"}))(0), law.stiffness(0.3),
              1e-9 * law.Kv0());
  EXPECT_EQ((*e->response(std::vector<std::string>{"verticalBranch"}))(0), 1.0);
  EXPECT_NEAR((*e->response(std::vector<std::string>{"criticalLoad"}))(0), law.criticalLoad(0.3),
              1e-9 * law.Pcr0());
}

TEST(YoshidaBearing3dTest, KumarVerticalTangentMatchesFiniteDifferenceInEveryBranch) {
  const KumarVertical law(kumar());
  for (const auto& x : {kCoincidentNodes, kInclined}) {
    auto e = make(x, true, kumarElement());
    const Eigen::Matrix3d R = e->axes();  // rows: local x, y, z in global coordinates
    // Node j moved by a local axial d0 and a local shear (d1, d2), rotations zero.
    auto at = [&](double d0, double d1, double d2) {
      TrialState s = zeroState(0.01);
      s.u.segment<3>(6) = R.transpose() * Eigen::Vector3d(d0, d1, d2);
      return s;
    };
    struct Case {
      const char* what;
      double d0, d1, d2;
      int branch;
      bool commit;
    };
    // In order: each case starts from the state the earlier committed ones left. The shear
    // increments avoid whole multiples of the material's sub-step (0.02 U0): there the number of
    // sub-steps, and with it the discrete shear force, jumps.
    const Case cases[] = {{"elastic compression with shear", -0.004, 0.2, -0.1, 0, false},
                          {"buckled with shear", -0.03, 0.25, 0.1, 3, false},
                          {"post-cavitation envelope", 0.03, 0.2, 0.1, 1, true},
                          {"after cavitation, between ucn and umax", 0.015, 0.2231, 0.1, 2, false},
                          {"after cavitation, elastic", 0.0003, 0.2231, 0.1, 0, false}};
    for (const Case& c : cases) {
      const TrialState s = at(c.d0, c.d1, c.d2);
      ASSERT_TRUE(ok(e->update(s.kinematics()))) << c.what;
      ASSERT_EQ(e->trialState().vertical.branch, c.branch) << c.what;
      const Eigen::MatrixXd k = e->tangentStiff();
      const Eigen::MatrixXd kfd = testing::numericalStiffness(*e, s, 1e-8);
      EXPECT_LT(testing::relativeDifference(k, kfd), kFdRelTol) << c.what;
      // The coupling itself (the axial force at j against j's shear displacement), which is
      // small beside Kv in the matrix norm: the global rows of the axial force at j.
      const Eigen::Vector3d ax = R.row(0).transpose();
      for (int dir = 1; dir <= 2; ++dir) {
        const Eigen::Vector3d shear = R.row(dir).transpose();
        const double kc = ax.dot(k.block<3, 3>(6, 6) * shear);
        const double kcfd = ax.dot(kfd.block<3, 3>(6, 6) * shear);
        EXPECT_NEAR(kc, kcfd, 1e-5 * std::max(std::abs(kcfd), law.Fc())) << c.what << " " << dir;
      }
      if (c.commit) e->commitState();
    }
    // The coupling of N with the shear does not vanish (Kv and Pcr fall with |U|).
    ASSERT_TRUE(ok(e->update(at(-0.03, 0.25, 0.1).kinematics())));
    const Eigen::MatrixXd k = e->tangentStiff();
    EXPECT_GT(std::abs(R.row(0) * k.block<3, 3>(6, 6) * R.row(1).transpose()), 1.0);
  }
}

TEST(YoshidaBearing3dTest, KumarVerticalCommitRevertAndRevertToStart) {
  auto e = make(kCoincidentNodes, false, kumarElement());
  const KumarVertical law(kumar());
  TrialState s = zeroState();
  s.u(8) = 0.05;  // cavitates and damages
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  e->commitState();
  const KumarVertical::State committed = e->committedState().vertical;
  EXPECT_DOUBLE_EQ(committed.umax, 0.05);
  EXPECT_LT(committed.cavitationRatio, 1.0);
  // A larger trial excursion, reverted: the history is the committed one again.
  s.u(8) = 0.2;
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_DOUBLE_EQ(e->trialState().vertical.umax, 0.2);
  e->revertToLastCommit();
  EXPECT_DOUBLE_EQ(e->trialState().vertical.umax, committed.umax);
  EXPECT_DOUBLE_EQ(e->trialState().vertical.cavitationRatio, committed.cavitationRatio);
  s.u(8) = 0.01;  // on the unloading path of the committed history
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().basicForce(0), law.evaluate(0.01, 0.0, committed).N,
              1e-12 * law.Fc());
  EXPECT_EQ(e->trialState().vertical.branch, 2);
  e->revertToStart();
  EXPECT_DOUBLE_EQ(e->committedState().vertical.umax, 0.0);
  EXPECT_DOUBLE_EQ(e->committedState().vertical.cavitationRatio, 1.0);
  ASSERT_TRUE(ok(e->update(s.kinematics())));
  EXPECT_NEAR(e->trialState().basicForce(0), law.evaluate(0.01, 0.0, {}).N, 1e-12 * law.Fc());
}

TEST(YoshidaBearing3dTest, WithoutTheVerticalOptionTheAxialSpringStaysLinear) {
  auto e = make(kCoincidentNodes);
  EXPECT_EQ(e->verticalLaw(), nullptr);
  EXPECT_FALSE(e->hasNonSymmetricTangent());
  for (double d0 : {0.05, -0.05}) {
    TrialState s = zeroState();
    s.u(6) = 0.15;
    s.u(8) = d0;
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    EXPECT_EQ(e->trialState().basicForce(0), kKv * d0);  // bit for bit
    EXPECT_EQ(e->tangentStiff()(8, 8), kKv);
    EXPECT_EQ(e->tangentStiff()(8, 6), 0.0);
  }
  EXPECT_FALSE(e->response(std::vector<std::string>{"verticalStiffness"}).has_value());
}

TEST(YoshidaBearing3dTest, KumarVerticalValidation) {
  YoshidaBearing3d::Params p = kumarElement();
  EXPECT_NO_THROW(p.validate());  // Tr and Kv need not be given
  p.vertical->Do = 0.05;          // below Di
  try {
    p.validate();
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "Di");
  }
}

TEST(YoshidaBearing3dTest, PDeltaMomentsAreHalfTheAxialForceTimesTheShearAtEachEnd) {
  for (bool kumarLaw : {false, true}) {
    YoshidaBearing3d::Params p = kumarLaw ? kumarElement() : element();
    p.pDelta = true;
    auto e = make(kCoincidentNodes, false, p);
    EXPECT_TRUE(e->hasNonSymmetricTangent());
    // Coincident nodes: local x = global Z, y = global X, z = global Y. Compression with shear.
    TrialState s = zeroState();
    s.u(6) = 0.12;    // d1
    s.u(7) = -0.05;   // d2
    s.u(8) = -0.002;  // d0
    ASSERT_TRUE(ok(e->update(s.kinematics())));
    const double n = e->trialState().basicForce(0);
    ASSERT_LT(n, 0.0);
    const Eigen::VectorXd fl = *e->response(std::vector<std::string>{"localForce"});
    // Rotations are zero, so the rocking springs carry nothing: the moments are P-Delta alone.
    EXPECT_NEAR(fl(5), 0.5 * n * 0.12, 1e-12 * std::abs(n));    // Mz at i
    EXPECT_NEAR(fl(11), 0.5 * n * 0.12, 1e-12 * std::abs(n));   // Mz at j
    EXPECT_NEAR(fl(4), -0.5 * n * -0.05, 1e-12 * std::abs(n));  // My at i
    EXPECT_NEAR(fl(10), -0.5 * n * -0.05, 1e-12 * std::abs(n));
    // The end moments balance the couple of the axial forces (N at j offset by d from i):
    // sum of local moments about z = N d1, about y = -N d2.
    EXPECT_NEAR(fl(5) + fl(11), n * 0.12, 1e-12 * std::abs(n));
    // Without -pDelta the same state has no end moments.
    p.pDelta = false;
    auto plain = make(kCoincidentNodes, false, p);
    ASSERT_TRUE(ok(plain->update(s.kinematics())));
    EXPECT_EQ((*plain->response(std::vector<std::string>{"localForce"}))(5), 0.0);
  }
}

TEST(YoshidaBearing3dTest, PDeltaTangentMatchesFiniteDifference) {
  for (const auto& x : {kCoincidentNodes, kInclined}) {
    for (bool kumarLaw : {false, true}) {
      YoshidaBearing3d::Params p = kumarLaw ? kumarElement() : element();
      p.pDelta = true;
      auto e = make(x, true, p);
      TrialState s = zeroState(0.01);
      s.u << 0.001, 0.002, -0.001, 0.002, 0.001, -0.003, 0.13, -0.07, -0.02, 0.001, -0.002, 0.004;
      ASSERT_TRUE(ok(e->update(s.kinematics())));
      const Eigen::MatrixXd k = e->tangentStiff();
      const Eigen::MatrixXd kfd = testing::numericalStiffness(*e, s, 1e-8);
      EXPECT_LT(testing::relativeDifference(k, kfd), kFdRelTol) << kumarLaw;
      // The moment rows alone (small beside the axial stiffness in the matrix norm).
      for (int row : {3, 4, 5, 9, 10, 11})
        EXPECT_LT((k.row(row) - kfd.row(row)).norm(), 1e-5 * std::max(1.0, kfd.row(row).norm()))
            << "row " << row << " kumar " << kumarLaw;
    }
  }
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
