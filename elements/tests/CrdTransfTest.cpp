// SPDX-License-Identifier: MIT
// Every coordinate transformation, 2D and 3D, on its own (no element): with a basic force law
// q = kb v + q0 (kb symmetric positive definite, q0 a prestress so that the geometric terms
// show), the global tangent globalStiffness(kb, q) is the central difference of the global
// force globalForce(q(v(u))); the P-Delta tangent differs from it by exactly the term OpenSees
// omits (d(N)/du times the chord rotation); the split into the initial stiffness plus the
// geometric part equals the full tangent; and the local end forces rotated to global axes are
// the global end forces of the Linear transformation (equilibrium of the basic system).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>
#include <string_view>

#include "elements/transform/CorotationalTransf2d.h"
#include "elements/transform/CorotationalTransf3d.h"
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"

namespace dabs::elements {
namespace {

constexpr double kFdStep = 1e-7;  // FD perturbation of the displacements (element length ~2.4)
constexpr double kFdTol = 1e-6;   // FD tangent, relative to the tangent's norm
constexpr double kExactTol = 1e-12;

template <template <int> class T, int Ndm>
std::unique_ptr<CrdTransfNd<Ndm>> build() {
  if constexpr (Ndm == 2)
    return std::make_unique<T<2>>(1);
  else
    return std::make_unique<T<3>>(1, Eigen::Vector3d(0.0, 0.3, 1.0));
}

/// Transformation `type` of an inclined member (2D: in the X-Y plane), length about 2.4.
template <int Ndm>
std::unique_ptr<CrdTransfNd<Ndm>> make(std::string_view type) {
  std::unique_ptr<CrdTransfNd<Ndm>> t = type == "Linear"   ? build<LinearTransf, Ndm>()
                                        : type == "PDelta" ? build<PDeltaTransf, Ndm>()
                                                           : build<CorotationalTransf, Ndm>();
  t->initialize(Eigen::Vector3d(1.0, -2.0, Ndm == 3 ? 0.5 : 0.0),
                Eigen::Vector3d(2.0, 0.0, Ndm == 3 ? 2.0 : 0.0));
  return t;
}

/// The basic force law: an SPD kb with coupling, and a compressive prestress q0.
template <int Ndm>
struct Law {
  using Basic = typename FrameTraits<Ndm>::Basic;
  using BasicMatrix = typename FrameTraits<Ndm>::BasicMatrix;
  BasicMatrix kb;
  Basic q0;
  Law() {
    constexpr int nb = FrameTraits<Ndm>::kBasic;
    kb = BasicMatrix::Identity() * 3.0e3;
    for (int i = 0; i + 1 < nb; ++i) kb(i, i + 1) = kb(i + 1, i) = 1.0e3;
    kb(0, 0) = 5.0e4;  // axial much stiffer, as in a beam
    q0 = Basic::Constant(20.0);
    q0(0) = -400.0;
  }
  Basic q(const Basic& v) const { return kb * v + q0; }
};

/// A general displacement of both ends (translations and rotations of a few percent of L).
template <int Ndm>
typename FrameTraits<Ndm>::Global motion() {
  typename FrameTraits<Ndm>::Global u;
  if constexpr (Ndm == 2)
    u << 0.02, -0.05, 0.03, -0.01, 0.04, -0.06;
  else
    u << 0.02, -0.05, 0.03, 0.04, -0.02, 0.05, -0.01, 0.04, -0.06, -0.03, 0.02, 0.01;
  return u;
}

/// Central difference of u -> globalForce(q(v(u))) at u; leaves t updated at u.
template <int Ndm>
typename FrameTraits<Ndm>::GlobalMatrix numericalTangent(
    CrdTransfNd<Ndm>& t, const Law<Ndm>& law, const typename FrameTraits<Ndm>::Global& u) {
  typename FrameTraits<Ndm>::GlobalMatrix k;
  for (int j = 0; j < u.size(); ++j) {
    auto up = u, um = u;
    up(j) += kFdStep;
    um(j) -= kFdStep;
    t.update(up);
    const auto fp = t.globalForce(law.q(t.basicDeformation()));
    t.update(um);
    const auto fm = t.globalForce(law.q(t.basicDeformation()));
    k.col(j) = (fp - fm) / (2.0 * kFdStep);
  }
  t.update(u);
  return k;
}

template <class M>
double relative(const M& a, const M& b) {
  return (a - b).norm() / b.norm();
}

template <class Dim>
class CrdTransfTest : public ::testing::Test {};

template <int N>
struct Dim {
  static constexpr int value = N;
};
using Dims = ::testing::Types<Dim<2>, Dim<3>>;
TYPED_TEST_SUITE(CrdTransfTest, Dims);

TYPED_TEST(CrdTransfTest, TangentMatchesFiniteDifferences) {
  constexpr int Ndm = TypeParam::value;
  const Law<Ndm> law;
  for (const char* type : {"Linear", "Corotational"}) {
    auto t = make<Ndm>(type);
    const auto u = motion<Ndm>();
    const auto kFd = numericalTangent(*t, law, u);
    const auto k = t->globalStiffness(law.kb, law.q(t->basicDeformation()));
    EXPECT_LT(relative(k, kFd), kFdTol) << type;
  }
}

TYPED_TEST(CrdTransfTest, PDeltaTangentMissesOnlyTheAxialForceVariation) {
  constexpr int Ndm = TypeParam::value;
  constexpr int n = FrameTraits<Ndm>::kDofPerNode;
  const Law<Ndm> law;
  auto t = make<Ndm>("PDelta");
  const auto u = motion<Ndm>();
  const auto kFd = numericalTangent(*t, law, u);
  const auto k = t->globalStiffness(law.kb, law.q(t->basicDeformation()));
  // The P-Delta end shears are +-N delta_a / L on the local transverse translations a, with
  // delta_a = ul_a(i) - ul_a(j); their derivative through N is (shear pattern) (delta_a / L)
  // dN/du, dN/du = kb.row(0) B0 (B0 = compatibility at u = 0, the Linear transformation's).
  auto linear = make<Ndm>("Linear");
  typename FrameTraits<Ndm>::Compat b0;
  for (int j = 0; j < 2 * n; ++j) {
    typename FrameTraits<Ndm>::Global e = FrameTraits<Ndm>::Global::Zero();
    e(j) = 1.0;
    linear->update(e);
    b0.col(j) = linear->basicDeformation();
  }
  const Eigen::Matrix<double, 1, 2 * n> dN = law.kb.row(0) * b0;
  typename FrameTraits<Ndm>::GlobalMatrix omitted = FrameTraits<Ndm>::GlobalMatrix::Zero();
  const Eigen::Matrix<double, Ndm, Ndm>& axes = t->axes();
  for (int a = 1; a < Ndm; ++a) {
    const double ui = axes.row(a) * u.template segment<Ndm>(0);
    const double uj = axes.row(a) * u.template segment<Ndm>(n);
    typename FrameTraits<Ndm>::Global pattern = FrameTraits<Ndm>::Global::Zero();
    pattern.template segment<Ndm>(0) = axes.row(a).transpose();
    pattern.template segment<Ndm>(n) = -axes.row(a).transpose();
    omitted += pattern * ((ui - uj) / t->initialLength()) * dN;
  }
  EXPECT_GT(omitted.norm(), 1e3 * kFdTol * k.norm());  // the case does test the difference
  EXPECT_LT(relative(typename FrameTraits<Ndm>::GlobalMatrix(k + omitted), kFd), kFdTol);
}

TYPED_TEST(CrdTransfTest, PDeltaTangentExactWithoutChordRotation) {
  constexpr int Ndm = TypeParam::value;
  constexpr int n = FrameTraits<Ndm>::kDofPerNode;
  const Law<Ndm> law;
  auto t = make<Ndm>("PDelta");
  // The same translation at both ends, end rotations: no chord rotation, so N delta stays 0.
  auto u = motion<Ndm>();
  u.template segment<Ndm>(n) = u.template segment<Ndm>(0);
  const auto kFd = numericalTangent(*t, law, u);
  EXPECT_LT(relative(t->globalStiffness(law.kb, law.q(t->basicDeformation())), kFd), kFdTol);
}

TYPED_TEST(CrdTransfTest, ConstantCompatibilitySplitEqualsFullTangent) {
  constexpr int Ndm = TypeParam::value;
  const Law<Ndm> law;
  for (const char* type : {"Linear", "PDelta"}) {
    auto t = make<Ndm>(type);
    ASSERT_TRUE(t->hasConstantCompatibility());
    t->update(motion<Ndm>());
    const auto q = law.q(t->basicDeformation());
    auto split = t->initialGlobalStiffness(law.kb);
    t->addGeometricStiffness(split, q);
    EXPECT_LT(relative(split, t->globalStiffness(law.kb, q)), kExactTol) << type;
  }
}

TYPED_TEST(CrdTransfTest, LocalEndForcesRotateToGlobalEndForces) {
  constexpr int Ndm = TypeParam::value;
  auto t = make<Ndm>("Linear");
  typename FrameTraits<Ndm>::Basic q;
  q.setLinSpaced(-3.0, 5.0);
  const auto global = t->globalForce(q);
  EXPECT_LT(relative(t->globalFromLocal(t->localForce(q)), global), kExactTol);
  // The matrix form is T^T m T: for m = p p^T it is (T^T p)(T^T p)^T.
  const auto p = t->localForce(q);
  const typename FrameTraits<Ndm>::GlobalMatrix m = p * p.transpose();
  const typename FrameTraits<Ndm>::GlobalMatrix expected = global * global.transpose();
  EXPECT_LT(relative(t->globalFromLocal(m), expected), kExactTol);
}

}  // namespace
}  // namespace dabs::elements
