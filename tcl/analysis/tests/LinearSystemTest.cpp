// SPDX-License-Identifier: MIT
// The linear system of one iteration on a two-spring chain whose stiffness is known in closed
// form: K^-1 P by hand, factorisation only when the matrix may have changed, and modal damping
// kept out of the sparse matrix (Woodbury) giving the solution of the dense K + cC U D U^T.
#include "tcl/analysis/system/LinearSystem.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <memory>

#include "elements/link/ZeroLength.h"
#include "materials/Elastic.h"
#include "tcl/domain/ConstantSeries.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {
namespace {

constexpr double kK1 = 40.0, kK2 = 10.0, kP1 = 1.0, kP2 = 3.0;
constexpr double kTol = 1e-12;

/// Node 0 fixed; node 1 joined to it by k1, node 2 to node 1 by k2; loads P1, P2 on nodes 1, 2.
void buildChain(domain::Domain& domain) {
  for (int i = 0; i < 3; ++i) domain.addNode(i, 1, 1, Eigen::Vector3d::Zero());
  domain.addFix(0, 0);
  const double k[2] = {kK1, kK2};
  for (int e = 0; e < 2; ++e) {
    elements::ZeroLength::Params p;
    p.nodes = {e, e + 1};
    p.ndm = 1;
    p.ndf = 1;
    p.dirs = {1};
    materials::Elastic::Params mp;
    mp.E = k[e];
    std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
    mats.push_back(std::make_unique<materials::Elastic>(e + 1, mp));
    p.validate(mats.size());
    domain.addElement(std::make_unique<elements::ZeroLength>(e + 1, p, std::move(mats)));
  }
  auto pattern = std::make_unique<domain::PlainPattern>(
      1, std::make_shared<domain::ConstantSeries>(1, 1.0), 1.0);
  pattern->loads.push_back({1, Eigen::VectorXd::Constant(1, kP1)});
  pattern->loads.push_back({2, Eigen::VectorXd::Constant(1, kP2)});
  domain.addPattern(std::move(pattern));
}

struct Chain : ::testing::Test {
  domain::Domain domain;
  std::unique_ptr<AnalysisModel> model;
  void SetUp() override {
    buildChain(domain);
    model = std::make_unique<AnalysisModel>(domain, ConstraintKind::Plain, NumbererKind::Plain);
    model->build();
    model->applyLoad(0.0);
  }
  /// K in equation order (equation of node 1 first under the Plain numberer).
  static Eigen::Matrix2d stiffness() {
    Eigen::Matrix2d K;
    K << kK1 + kK2, -kK2, -kK2, kK2;
    return K;
  }
};

TEST_F(Chain, SolvesTheStaticDisplacementsOfTheChain) {
  for (SolverKind kind : {SolverKind::SparseLDLT, SolverKind::SparseLU, SolverKind::DenseLU}) {
    LinearSystem system(*model, kind);
    system.patternChanged();
    ASSERT_TRUE(ok(system.formTangent(AssemblyCoefficients{})));
    system.formResidual(AssemblyCoefficients{});
    ASSERT_TRUE(ok(system.solve()));
    // u1 = (P1 + P2) / k1, u2 = u1 + P2 / k2.
    const double u1 = (kP1 + kP2) / kK1;
    EXPECT_NEAR(system.X(model->equationOf(1, 0)), u1, kTol);
    EXPECT_NEAR(system.X(model->equationOf(2, 0)), u1 + kP2 / kK2, kTol);
  }
}

TEST_F(Chain, FactorisesOnlyWhenTheCoefficientsChangeOrReuseIsOff) {
  LinearSystem system(*model, SolverKind::SparseLDLT);
  system.patternChanged();
  AssemblyCoefficients c;
  ASSERT_TRUE(ok(system.formTangent(c, true)));
  ASSERT_TRUE(ok(system.formTangent(c, true)));
  EXPECT_EQ(system.factorizations(), 1);
  ASSERT_TRUE(ok(system.formTangent(c, false)));
  EXPECT_EQ(system.factorizations(), 2);
  c.cK = 2.0;
  ASSERT_TRUE(ok(system.formTangent(c, true)));
  EXPECT_EQ(system.factorizations(), 3);
  system.invalidate();
  ASSERT_TRUE(ok(system.formTangent(c, true)));
  EXPECT_EQ(system.factorizations(), 4);
}

TEST_F(Chain, ModalDampingSolvesTheDenseSystemWithoutEnteringTheSparseMatrix) {
  // A = K + cC U diag(d) U^T with one column U = (1, 2) and d = 3, cC = 0.5.
  Eigen::MatrixXd U(2, 1);
  U << 1.0, 2.0;
  const Eigen::VectorXd d = Eigen::VectorXd::Constant(1, 3.0);
  model->setModalDamping(U, d);
  AssemblyCoefficients c;
  c.cC = 0.5;
  LinearSystem system(*model, SolverKind::SparseLDLT);
  system.patternChanged();
  ASSERT_TRUE(ok(system.formTangent(c)));
  const Eigen::Vector2d b(1.0, -2.0);
  Eigen::VectorXd x;
  ASSERT_TRUE(ok(system.solve(b, x)));
  const Eigen::Matrix2d A = stiffness() + c.cC * (U * d.asDiagonal() * U.transpose());
  const Eigen::Vector2d expected = A.inverse() * b;
  EXPECT_NEAR(x(0), expected(0), kTol);
  EXPECT_NEAR(x(1), expected(1), kTol);
  // The sparse matrix is the stiffness alone.
  EXPECT_NEAR(model->pattern().coeff(0, 1), -kK2, kTol);
}

}  // namespace
}  // namespace dabs::analysis
