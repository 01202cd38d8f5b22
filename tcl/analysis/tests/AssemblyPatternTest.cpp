// SPDX-License-Identifier: MIT
// The assembly's slot index: each coupling's place in the value array of the compressed matrix,
// checked against Eigen's own look-up, on patterns of more than 46,340 equations, where a
// row * n + column index would overflow a 32-bit int; and through the whole assembly of a chain
// of springs of that size, whose stiffness matrix is known in closed form.
#include "tcl/analysis/model/AssemblyPattern.h"

#include <gtest/gtest.h>

#include <memory>

#include "elements/link/ZeroLength.h"
#include "materials/Elastic.h"
#include "tcl/analysis/model/AnalysisModel.h"
#include "tcl/domain/Domain.h"

namespace dabs::analysis {
namespace {

constexpr int kBeyondIntIndex = 46341;  // 46,341^2 > 2^31 - 1

TEST(AssemblyPatternTest, SlotOfEveryEntryOfALargeTridiagonalPattern) {
  const int n = kBeyondIntIndex + 1000;
  AssemblyPattern pattern;
  for (int i = 0; i + 1 < n; ++i) {
    pattern.couple(i, i + 1);
    pattern.couple(i + 1, i);
  }
  Eigen::SparseMatrix<double> A = pattern.build(n);
  ASSERT_EQ(A.nonZeros(), 3 * n - 2);
  // Each value holds its own index; the slot of (row, col) must hold the value Eigen finds there.
  for (int k = 0; k < A.nonZeros(); ++k) A.valuePtr()[k] = k;
  for (int i : {0, 1, n / 2, kBeyondIntIndex - 1, kBeyondIntIndex, n - 2, n - 1}) {
    EXPECT_EQ(AssemblyPattern::valueIndex(A, i, i), static_cast<int>(A.coeff(i, i)));
    if (i + 1 < n) {
      EXPECT_EQ(AssemblyPattern::valueIndex(A, i, i + 1), static_cast<int>(A.coeff(i, i + 1)));
      EXPECT_EQ(AssemblyPattern::valueIndex(A, i + 1, i), static_cast<int>(A.coeff(i + 1, i)));
    }
  }
  EXPECT_EQ(AssemblyPattern::valueIndex(A, n - 1, n - 1), 3 * n - 3);  // the last value
}

TEST(AssemblyPatternTest, RepeatedCouplingsAreOneEntryAndTheDiagonalIsAlwaysThere) {
  AssemblyPattern pattern;
  pattern.couple(0, 2);
  pattern.couple(0, 2);
  pattern.couple(2, 0);
  const Eigen::SparseMatrix<double> A = pattern.build(3);
  EXPECT_EQ(A.nonZeros(), 5);                          // (0,0) (1,1) (2,2) (0,2) (2,0)
  EXPECT_EQ(AssemblyPattern::valueIndex(A, 2, 0), 1);  // column 0 holds rows 0 and 2
}

TEST(AssemblyPatternTest, ChainOfSpringsPastTheIntIndexAssemblesItsStiffness) {
  // Node 0 fixed, nodes 1..n joined in a chain by springs of stiffness k: K is tridiagonal with
  // 2k on the diagonal (k at the free end) and -k beside it, in equation space of n equations.
  const int n = kBeyondIntIndex + 100;
  const double k = 3.0;
  domain::Domain domain;
  for (int i = 0; i <= n; ++i) domain.addNode(i, 1, 1, Eigen::Vector3d::Zero());
  domain.addFix(0, 0);
  materials::Elastic::Params mp;
  mp.E = k;
  for (int i = 0; i < n; ++i) {
    elements::ZeroLength::Params p;
    p.nodes = {i, i + 1};
    p.ndm = 1;
    p.ndf = 1;
    p.dirs = {1};
    std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
    mats.push_back(std::make_unique<materials::Elastic>(i + 1, mp));
    p.validate(mats.size());
    domain.addElement(std::make_unique<elements::ZeroLength>(i + 1, p, std::move(mats)));
  }
  AnalysisModel model(domain, ConstraintKind::Plain, NumbererKind::Plain);
  model.build();
  ASSERT_EQ(model.numEquations(), n);
  const Eigen::SparseMatrix<double>& K = model.formTangent(AssemblyCoefficients{});
  for (int node : {1, n / 2, kBeyondIntIndex - 1, kBeyondIntIndex, kBeyondIntIndex + 1, n - 1}) {
    const int eq = model.equationOf(node, 0);
    const int next = model.equationOf(node + 1, 0);
    ASSERT_GE(eq, 0);
    EXPECT_DOUBLE_EQ(K.coeff(eq, eq), 2.0 * k);
    EXPECT_DOUBLE_EQ(K.coeff(eq, next), -k);
    EXPECT_DOUBLE_EQ(K.coeff(next, eq), -k);
  }
  const int last = model.equationOf(n, 0);
  EXPECT_DOUBLE_EQ(K.coeff(last, last), k);
  EXPECT_DOUBLE_EQ(K.sum(), k);  // rows sum to zero except the first, tied to the support
}

}  // namespace
}  // namespace dabs::analysis
