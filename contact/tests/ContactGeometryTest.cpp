// SPDX-License-Identifier: MIT
#include "contact/ContactGeometry.h"

#include <gtest/gtest.h>

#include "materials/InputError.h"

namespace dabs::contact {
namespace {

constexpr double kTol = 1e-12;

TEST(ContactGeometryTest, NormalFollowsRightHandRuleOverABCD) {
  const std::array<Eigen::Vector3d, 4> q{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0),
                                         Eigen::Vector3d(2, 3, 0), Eigen::Vector3d(0, 3, 0)};
  const SurfaceFrame f = makeSurfaceFrame(q);
  EXPECT_NEAR((f.n - Eigen::Vector3d::UnitZ()).norm(), 0.0, kTol);
  EXPECT_NEAR((f.t1 - Eigen::Vector3d::UnitX()).norm(), 0.0, kTol);
  EXPECT_NEAR((f.t2 - Eigen::Vector3d::UnitY()).norm(), 0.0, kTol);
  // Listing the nodes the other way round flips the normal: (b-a) x (d-a) = -z.
  const SurfaceFrame g = makeSurfaceFrame({q[0], q[3], q[2], q[1]});
  EXPECT_NEAR((g.n + Eigen::Vector3d::UnitZ()).norm(), 0.0, kTol);
  EXPECT_NEAR(f.size, std::sqrt(13.0), kTol);
}

TEST(ContactGeometryTest, DegenerateOrTwistedQuadIsAnInputError) {
  const Eigen::Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), xy(1, 1, 0);
  EXPECT_THROW(makeSurfaceFrame({o, o, o, o}), InputError);
  EXPECT_THROW(makeSurfaceFrame({o, x, 2 * x, 3 * x}), InputError);  // collinear: zero area
  EXPECT_THROW(makeSurfaceFrame({o, x, y, xy}), InputError);         // bow-tie (c and d swapped)
}

TEST(ContactGeometryTest, InverseBilinearRecoversParametricPoint) {
  // A general (non-parallelogram) quad; S(xi) from the shape functions, then invert.
  const std::array<Eigen::Vector2d, 4> s{Eigen::Vector2d(0, 0), Eigen::Vector2d(3, 0.2),
                                         Eigen::Vector2d(2.5, 2.0), Eigen::Vector2d(-0.3, 1.5)};
  for (const Eigen::Vector2d& xi : {Eigen::Vector2d(0.3, -0.7), Eigen::Vector2d(1, 1),
                                    Eigen::Vector2d(-1, 0.25), Eigen::Vector2d(1.4, -1.2)}) {
    const auto N = shapeFunctions(xi.x(), xi.y());
    const Eigen::Vector2d p = N[0] * s[0] + N[1] * s[1] + N[2] * s[2] + N[3] * s[3];
    const auto found = inverseBilinear(s, p, 1e-13);
    ASSERT_TRUE(found.has_value());
    EXPECT_NEAR((*found - xi).norm(), 0.0, 1e-10);
  }
}

TEST(ContactGeometryTest, ShapeFunctionsPartitionUnityAndDerivativesSumToZero) {
  const auto N = shapeFunctions(0.2, -0.9);
  EXPECT_NEAR(N[0] + N[1] + N[2] + N[3], 1.0, kTol);
  const auto dN = shapeDerivatives(0.2, -0.9);
  for (int a = 0; a < 2; ++a) EXPECT_NEAR(dN[a][0] + dN[a][1] + dN[a][2] + dN[a][3], 0.0, kTol);
  // Central difference of N_c in xi.
  const double h = 1e-6;
  EXPECT_NEAR(dN[0][2],
              (shapeFunctions(0.2 + h, -0.9)[2] - shapeFunctions(0.2 - h, -0.9)[2]) / (2 * h),
              1e-9);
}

TEST(ContactGeometryTest, OnQuadIncludesEdgesAndCorners) {
  EXPECT_TRUE(onQuad(Eigen::Vector2d(1, 1)));
  EXPECT_TRUE(onQuad(Eigen::Vector2d(-1, 0.3)));
  EXPECT_FALSE(onQuad(Eigen::Vector2d(1.001, 0)));
  EXPECT_FALSE(onQuad(Eigen::Vector2d(0, -1.01)));
}

}  // namespace
}  // namespace dabs::contact
