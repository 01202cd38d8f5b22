// SPDX-License-Identifier: MIT
// section Elastic and section Aggregator: closed-form stiffness, resultant order (OpenSees:
// base section first), FD tangent of an aggregated nonlinear section, commit/revert, bad input.
#include <gtest/gtest.h>

#include "materials/Elastic.h"
#include "materials/InputError.h"
#include "materials/Steel02.h"
#include "materials/section/ElasticSection.h"
#include "materials/section/SectionAggregator.h"

namespace dabs::materials::section {
namespace {

constexpr double kTol = 1e-12;   // round-off, relative
constexpr double kFdTol = 1e-6;  // finite-difference tangent, relative
constexpr double kFdStep = 1e-9;

ElasticSectionParams params3d() {
  ElasticSectionParams p;
  p.ndm = 3;
  p.modulus = 2.0e8;
  p.area = 0.02;
  p.inertiaZ = 3.0e-4;
  p.inertiaY = 2.0e-4;
  p.shearModulus = 8.0e7;
  p.torsion = 5.0e-4;
  return p;
}

Steel02 steel() {
  Steel02::Params p;
  p.Fy = 300.0;
  p.E = 1.0e5;
  p.b = 0.02;
  p.validate();
  return Steel02(7, p);
}

TEST(ElasticSectionTest, StiffnessIsDiagonalEaEiGj) {
  const ElasticSection s(1, params3d());
  ASSERT_EQ(s.order(), 4);
  EXPECT_EQ(s.type()[0], SectionCode::P);
  EXPECT_EQ(s.type()[1], SectionCode::Mz);
  EXPECT_EQ(s.type()[2], SectionCode::My);
  EXPECT_EQ(s.type()[3], SectionCode::T);
  const Eigen::Vector4d expected(2.0e8 * 0.02, 2.0e8 * 3.0e-4, 2.0e8 * 2.0e-4, 8.0e7 * 5.0e-4);
  EXPECT_LT((s.getSectionTangent().diagonal() - expected).norm(), kTol * expected.norm());
  EXPECT_EQ((s.getSectionTangent() - Eigen::MatrixXd(expected.asDiagonal())).norm(), 0.0);
}

TEST(ElasticSectionTest, ShearFactorsAddVyVzInOpenSeesOrder) {
  ElasticSectionParams p = params3d();
  p.alphaY = 5.0 / 6.0;
  p.alphaZ = 0.9;
  ElasticSection s(1, p);
  ASSERT_EQ(s.order(), 6);
  const SectionCode expected[] = {SectionCode::P,  SectionCode::Mz, SectionCode::Vy,
                                  SectionCode::My, SectionCode::Vz, SectionCode::T};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(s.type()[static_cast<std::size_t>(i)], expected[i]);
  Eigen::VectorXd e(6);
  e << 1e-4, 2e-3, 3e-4, -1e-3, 5e-4, 2e-3;
  ASSERT_TRUE(ok(s.setTrialDeformation(e)));
  EXPECT_NEAR(s.getStressResultant()(2), 5.0 / 6.0 * 8.0e7 * 0.02 * 3e-4, kTol * 1e3);
  EXPECT_NEAR(s.getStressResultant()(4), 0.9 * 8.0e7 * 0.02 * 5e-4, kTol * 1e3);
  // 2D: E A Iz G alphaY gives P, Mz, Vy.
  ElasticSectionParams q;
  q.modulus = 2.0e8;
  q.area = 0.02;
  q.inertiaZ = 3.0e-4;
  q.shearModulus = 8.0e7;
  q.alphaY = 1.0;
  EXPECT_EQ(ElasticSection(2, q).order(), 3);
}

TEST(ElasticSectionTest, RejectsBadInput) {
  ElasticSectionParams p = params3d();
  p.torsion = 0.0;
  EXPECT_THROW(p.validate(), InputError);
  p = params3d();
  p.alphaY = -1.0;
  EXPECT_THROW(p.validate(), InputError);
  ElasticSectionParams q;  // 2D with shear factor but no G
  q.modulus = 1.0;
  q.area = 1.0;
  q.inertiaZ = 1.0;
  q.alphaY = 1.0;
  EXPECT_THROW(q.validate(), InputError);
  q.ndm = 4;
  EXPECT_THROW(q.validate(), InputError);
}

TEST(SectionAggregatorTest, BaseResultantsFirstThenMaterials) {
  const Steel02 s = steel();
  Elastic::Params ep;
  ep.E = 5.0e4;
  ep.validate();
  const Elastic el(8, ep);
  const ElasticSection base(1, params3d());
  SectionAggregator agg(2, {{&s, SectionCode::Vy}, {&el, SectionCode::Vz}}, &base);
  ASSERT_EQ(agg.order(), 6);
  EXPECT_EQ(agg.type()[4], SectionCode::Vy);
  EXPECT_EQ(agg.type()[5], SectionCode::Vz);
  Eigen::VectorXd e(6);
  e << 1e-4, 2e-3, -1e-3, 2e-3, 1e-3, -2e-3;
  ASSERT_TRUE(ok(agg.setTrialDeformation(e)));
  // The elastic Vz part and the base are linear: closed form; the steel is elastic below Fy/E.
  EXPECT_NEAR(agg.getStressResultant()(5), 5.0e4 * -2e-3, kTol * 1e2);
  EXPECT_NEAR(agg.getStressResultant()(4), 1.0e5 * 1e-3 * 1.0, 1e-2 * 100.0);
  EXPECT_NEAR(agg.getStressResultant()(0), 2.0e8 * 0.02 * 1e-4, kTol * 1e4);
  // Block diagonal: no coupling between the base and the added parts.
  EXPECT_EQ(agg.getSectionTangent().block(0, 4, 4, 2).norm(), 0.0);
}

TEST(SectionAggregatorTest, TangentMatchesFiniteDifferencesAndRevertRestores) {
  const Steel02 s = steel();
  SectionAggregator agg(2, {{&s, SectionCode::P}, {&s, SectionCode::Mz}}, nullptr);
  Eigen::VectorXd e(2);
  e << 0.0045, -0.004;  // both beyond yield (0.003)
  ASSERT_TRUE(ok(agg.setTrialDeformation(e)));
  const Eigen::MatrixXd k = agg.getSectionTangent();
  Eigen::MatrixXd kNum(2, 2);
  for (int j = 0; j < 2; ++j) {
    Eigen::VectorXd ep = e, em = e;
    ep(j) += kFdStep;
    em(j) -= kFdStep;
    ASSERT_TRUE(ok(agg.setTrialDeformation(ep)));
    const Eigen::VectorXd sp = agg.getStressResultant();
    ASSERT_TRUE(ok(agg.setTrialDeformation(em)));
    kNum.col(j) = (sp - agg.getStressResultant()) / (2 * kFdStep);
  }
  EXPECT_LT((k - kNum).norm() / k.norm(), kFdTol);
  EXPECT_LT(k(0, 0), 0.5 * 1.0e5);  // yielded: the check is not on the elastic branch
  // Commit at e, then a trial elsewhere, then revert: resultants of e come back.
  ASSERT_TRUE(ok(agg.setTrialDeformation(e)));
  const Eigen::VectorXd sAtE = agg.getStressResultant();
  agg.commitState();
  Eigen::VectorXd e2(2);
  e2 << -0.01, 0.01;
  ASSERT_TRUE(ok(agg.setTrialDeformation(e2)));
  agg.revertToLastCommit();
  EXPECT_EQ((agg.getStressResultant() - sAtE).norm(), 0.0);
  EXPECT_EQ((agg.getDeformation() - e).norm(), 0.0);
  // Clones are independent.
  auto c = agg.clone();
  ASSERT_TRUE(ok(c->setTrialDeformation(e2)));
  EXPECT_EQ((agg.getStressResultant() - sAtE).norm(), 0.0);
}

TEST(SectionAggregatorTest, RejectsBadInput) {
  const Steel02 s = steel();
  const ElasticSection base(1, params3d());
  EXPECT_THROW(SectionAggregator(2, {}, nullptr), InputError);
  EXPECT_THROW(SectionAggregator(2, {{&s, SectionCode::P}, {&s, SectionCode::P}}, nullptr),
               InputError);                                                        // repeated code
  EXPECT_THROW(SectionAggregator(2, {{&s, SectionCode::Mz}}, &base), InputError);  // in base
  EXPECT_THROW(SectionAggregator(2, {{nullptr, SectionCode::Vy}}, nullptr), InputError);
}

}  // namespace
}  // namespace dabs::materials::section
