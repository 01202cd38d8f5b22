// SPDX-License-Identifier: MIT
#pragma once

// The uniaxial material contract (style.md section 2 and 7) as a typed, parameterised
// GoogleTest suite, in the pattern of Akantu's material fixtures
// (allamaprabhuani/akantu2:test/test_model/test_solid_mechanics_model/test_materials/
// test_material_fixtures.hh). Any test file can run it for its own materials:
//
//   struct MyCase {
//     static std::unique_ptr<dabs::materials::UniaxialMaterial> make();
//     static std::vector<double> path();   // strains, each committed before the next
//     static double strainScale();         // yield (or gap) strain: sets the FD step
//     static constexpr bool kRateDependent = false;  // true: also check getDampTangent
//   };
//   using MyCases = ::testing::Types<MyCase>;
//   INSTANTIATE_TYPED_TEST_SUITE_P(MyPrefix, MaterialContract, MyCases);
//
// Checks: trial idempotence (e1 then e2 == e2 alone); commit / revertToLastCommit /
// revertToStart round trips; clone independence; getters report the last trial; tangent equals
// the central difference of stress with h = 1e-6*max(|eps|, eps_y) to 1e-5 relative along the
// path, skipping stencils that straddle a branch switch; damping tangent likewise in the rate.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials::testing {

/// Time step used to turn the strain path into strain rates (rate = d(strain)/kPathDt).
constexpr double kPathDt = 0.01;
/// FD step as a fraction of max(|eps|, eps_y) (Kratos tangent_operator_calculator_utility.h).
constexpr double kFdStepFraction = 1e-6;
/// Relative tolerance between the analytical tangent and the central difference.
constexpr double kFdRelTol = 1e-5;
/// Absolute floor of that comparison, as a fraction of the initial (or a reference) modulus,
/// for tangents that are zero or nearly so.
constexpr double kFdAbsTolFraction = 1e-7;
/// Two one-sided slopes (h apart, on either side of the point) differing by more than this
/// relative amount mean a branch switch lies within 2h: the point is skipped.
constexpr double kKinkRelTol = 1e-3;
/// At least this fraction of the path points must be checked by the FD test.
constexpr double kMinCheckedFraction = 0.5;

/// Piecewise-linear cyclic path through `amplitudes` (in units of `scale`), `perSegment` points
/// per segment, starting after 0. Partial unloading/reloading comes from the amplitude list.
inline std::vector<double> cyclicPath(double scale,
                                      std::vector<double> amplitudes = {0.5, 2.0, 1.0, 3.0, -1.0,
                                                                        -3.0, -2.0, 4.0, -4.0, 0.0},
                                      int perSegment = 16) {
  std::vector<double> out;
  double prev = 0.0;
  for (double a : amplitudes) {
    for (int i = 1; i <= perSegment; ++i)
      out.push_back(scale * (prev + (a - prev) * i / perSegment));
    prev = a;
  }
  return out;
}

/// Rate at point k of a path (backward difference over kPathDt).
inline double pathRate(const std::vector<double>& path, std::size_t k) {
  const double before = k == 0 ? 0.0 : path[k - 1];
  return (path[k] - before) / kPathDt;
}

/// Strain, stress, tangent and damping tangent of a trial.
struct Response {
  double strain, stress, tangent, damp;
};
inline Response responseOf(const UniaxialMaterial& m) {
  return Response{m.getStrain(), m.getStress(), m.getTangent(), m.getDampTangent()};
}
inline void expectSame(const Response& a, const Response& b, const char* what, std::size_t k) {
  EXPECT_DOUBLE_EQ(a.strain, b.strain) << what << " at point " << k;
  EXPECT_DOUBLE_EQ(a.stress, b.stress) << what << " at point " << k;
  EXPECT_DOUBLE_EQ(a.tangent, b.tangent) << what << " at point " << k;
  EXPECT_DOUBLE_EQ(a.damp, b.damp) << what << " at point " << k;
}

/// Sets and commits every point of `path` up to (excluding) `end`.
inline void runTo(UniaxialMaterial& m, const std::vector<double>& path, std::size_t end) {
  for (std::size_t k = 0; k < end; ++k) {
    ASSERT_TRUE(ok(m.setTrialStrain(path[k], pathRate(path, k)))) << "point " << k;
    m.commitState();
  }
}

template <class Case>
class MaterialContract : public ::testing::Test {};
TYPED_TEST_SUITE_P(MaterialContract);

TYPED_TEST_P(MaterialContract, TrialIsIdempotent) {
  auto m = TypeParam::make();
  const auto path = TypeParam::path();
  const double far = 3.0 * TypeParam::strainScale();
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    auto fresh = m->clone();  // same committed state, no detour
    ASSERT_TRUE(ok(fresh->setTrialStrain(path[k], rate)));
    // detours in both directions, then the real trial
    ASSERT_TRUE(ok(m->setTrialStrain(path[k] + far, -rate)));
    ASSERT_TRUE(ok(m->setTrialStrain(path[k] - far, rate)));
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], rate)));
    expectSame(responseOf(*m), responseOf(*fresh), "e1 then e2 vs e2", k);
    m->commitState();
  }
}

TYPED_TEST_P(MaterialContract, CommitAndRevertRoundTrip) {
  auto m = TypeParam::make();
  auto reference = TypeParam::make();
  const auto path = TypeParam::path();
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    ASSERT_TRUE(ok(reference->setTrialStrain(path[k], rate)));
    reference->commitState();
    // an excursion that is reverted must leave no trace
    ASSERT_TRUE(ok(m->setTrialStrain(path[k] + 2.5 * TypeParam::strainScale(), rate)));
    m->revertToLastCommit();
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], rate)));
    m->commitState();
    expectSame(responseOf(*m), responseOf(*reference), "after revert + retrial", k);
  }
  // revertToLastCommit restores the committed getters
  const Response committed = responseOf(*m);
  ASSERT_TRUE(ok(m->setTrialStrain(-path.back() - 2.0 * TypeParam::strainScale(), 1.0)));
  m->revertToLastCommit();
  expectSame(responseOf(*m), committed, "revertToLastCommit", path.size());
}

TYPED_TEST_P(MaterialContract, RevertToStartReplaysTheSameHistory) {
  auto m = TypeParam::make();
  const auto virgin = responseOf(*m);
  const auto path = TypeParam::path();
  std::vector<Response> first;
  for (std::size_t k = 0; k < path.size(); ++k) {
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], pathRate(path, k))));
    m->commitState();
    first.push_back(responseOf(*m));
  }
  m->revertToStart();
  expectSame(responseOf(*m), virgin, "revertToStart", 0);
  for (std::size_t k = 0; k < path.size(); ++k) {
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], pathRate(path, k))));
    m->commitState();
    expectSame(responseOf(*m), first[k], "replay after revertToStart", k);
  }
}

TYPED_TEST_P(MaterialContract, CloneIsIndependent) {
  auto m = TypeParam::make();
  const auto path = TypeParam::path();
  const std::size_t half = path.size() / 2;
  runTo(*m, path, half);
  ASSERT_TRUE(ok(m->setTrialStrain(path[half], pathRate(path, half))));
  auto copy = m->clone();
  EXPECT_EQ(copy->tag(), m->tag());
  expectSame(responseOf(*copy), responseOf(*m), "clone of a trial state", half);
  // the original runs on; the copy must not move
  const Response atClone = responseOf(*copy);
  std::vector<Response> original;
  for (std::size_t k = half; k < path.size(); ++k) {
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], pathRate(path, k))));
    m->commitState();
    original.push_back(responseOf(*m));
  }
  expectSame(responseOf(*copy), atClone, "clone after the original moved", half);
  // the copy continues exactly as the original did
  for (std::size_t k = half; k < path.size(); ++k) {
    ASSERT_TRUE(ok(copy->setTrialStrain(path[k], pathRate(path, k))));
    copy->commitState();
    expectSame(responseOf(*copy), original[k - half], "clone continuing the path", k);
  }
}

TYPED_TEST_P(MaterialContract, GettersReportTheLastTrial) {
  auto m = TypeParam::make();
  const auto path = TypeParam::path();
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], rate)));
    EXPECT_EQ(m->getStrain(), path[k]) << "point " << k;
    if (TypeParam::kRateDependent) {
      EXPECT_EQ(m->getStrainRate(), rate) << "point " << k;
    }
    const Response once = responseOf(*m);
    expectSame(responseOf(*m), once, "repeated getters", k);  // getters compute nothing
    m->commitState();
    expectSame(responseOf(*m), once, "commit keeps the trial values", k);
  }
}

TYPED_TEST_P(MaterialContract, TangentMatchesCentralDifference) {
  auto m = TypeParam::make();
  const auto path = TypeParam::path();
  const double epsY = TypeParam::strainScale();
  const double modulus = std::max(std::fabs(m->getInitialTangent()), 1e-300);
  std::size_t checked = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    const double e = path[k];
    const double h = kFdStepFraction * std::max(std::fabs(e), epsY);
    auto stressAt = [&](double x) {
      EXPECT_TRUE(ok(m->setTrialStrain(x, rate)));
      return m->getStress();
    };
    const double sm2 = stressAt(e - 2 * h), sm1 = stressAt(e - h);
    const double sp1 = stressAt(e + h), sp2 = stressAt(e + 2 * h);
    ASSERT_TRUE(ok(m->setTrialStrain(e, rate)));
    const double tangent = m->getTangent();
    const double left = (sm1 - sm2) / h, right = (sp2 - sp1) / h;
    const double slopeScale = std::max({std::fabs(left), std::fabs(right), modulus * 1e-6});
    const bool kink = std::fabs(left - right) > kKinkRelTol * slopeScale;
    if (!kink) {
      const double fd = (sp1 - sm1) / (2 * h);
      const double tol =
          kFdRelTol * std::max(std::fabs(fd), std::fabs(tangent)) + kFdAbsTolFraction * modulus;
      EXPECT_NEAR(tangent, fd, tol) << "point " << k << " strain " << e;
      ++checked;
    }
    m->commitState();
  }
  EXPECT_GE(static_cast<double>(checked), kMinCheckedFraction * static_cast<double>(path.size()))
      << "too few points away from branch switches";
}

TYPED_TEST_P(MaterialContract, DampTangentMatchesCentralDifference) {
  if (!TypeParam::kRateDependent) GTEST_SKIP() << "rate-independent material";
  auto m = TypeParam::make();
  const auto path = TypeParam::path();
  const double rateScale = TypeParam::strainScale() / kPathDt;
  std::size_t checked = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    const double h = kFdStepFraction * std::max(std::fabs(rate), rateScale);
    auto stressAt = [&](double r) {
      EXPECT_TRUE(ok(m->setTrialStrain(path[k], r)));
      return m->getStress();
    };
    const double sm2 = stressAt(rate - 2 * h), sm1 = stressAt(rate - h);
    const double sp1 = stressAt(rate + h), sp2 = stressAt(rate + 2 * h);
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], rate)));
    const double damp = m->getDampTangent();
    const double left = (sm1 - sm2) / h, right = (sp2 - sp1) / h;
    const double scale = std::max({std::fabs(left), std::fabs(right), 1e-300});
    if (std::fabs(left - right) <= kKinkRelTol * scale) {
      const double fd = (sp1 - sm1) / (2 * h);
      EXPECT_NEAR(damp, fd, kFdRelTol * std::max(std::fabs(fd), std::fabs(damp)) + 1e-300)
          << "point " << k;
      ++checked;
    }
    m->commitState();
  }
  EXPECT_GE(static_cast<double>(checked), kMinCheckedFraction * static_cast<double>(path.size()));
}

// A law that says it keeps its state at the same strain (keepsStateAtSameStrain: an element of
// such materials whose nodes have not moved skips its update, as in a transient predictor, which
// moves the rates) must give, at every point of the path, the response its update formed again
// when updated at that strain with another rate, after the commit, bit for bit; and the history
// must be the same too: the path continued from there gives, point for point, the responses of
// the same law walked without the extra updates.
TYPED_TEST_P(MaterialContract, SameStrainKeepsTheStateWhenTheLawSaysSo) {
  auto m = TypeParam::make();
  if (!m->keepsStateAtSameStrain()) GTEST_SKIP() << "the law does not say it keeps its state";
  auto reference = TypeParam::make();
  const auto path = TypeParam::path();
  for (std::size_t k = 0; k < path.size(); ++k) {
    const double rate = pathRate(path, k);
    ASSERT_TRUE(ok(reference->setTrialStrain(path[k], rate)));
    reference->commitState();
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], rate)));
    const Response formed = responseOf(*m);
    EXPECT_EQ(formed.stress, responseOf(*reference).stress) << "point " << k;
    EXPECT_EQ(formed.tangent, responseOf(*reference).tangent) << "point " << k;
    m->commitState();
    ASSERT_TRUE(ok(m->setTrialStrain(path[k], -2.0 * rate - 1.0)));
    const Response again = responseOf(*m);
    EXPECT_EQ(again.strain, formed.strain) << "point " << k;
    EXPECT_EQ(again.stress, formed.stress) << "point " << k;
    EXPECT_EQ(again.tangent, formed.tangent) << "point " << k;
    m->commitState();
  }
}

REGISTER_TYPED_TEST_SUITE_P(MaterialContract, TrialIsIdempotent, CommitAndRevertRoundTrip,
                            RevertToStartReplaysTheSameHistory, CloneIsIndependent,
                            GettersReportTheLastTrial, TangentMatchesCentralDifference,
                            DampTangentMatchesCentralDifference,
                            SameStrainKeepsTheStateWhenTheLawSaysSo);

}  // namespace dabs::materials::testing
