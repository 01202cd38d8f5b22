// SPDX-License-Identifier: MIT
// Over 400 lines: the reference assembler and the elements it is checked on (a gate that opens
// and closes, springs, beams) are written here, beside the cases, so the test needs nothing but
// the elements' public getters.
// AnalysisModel's assembly against a dense reference assembler written here: every element's own
// matrices and force (its public getters) and every node's mass, placed by hand into node-dof
// space and projected onto the equations with a mapping built from the constraints the test
// itself defined (fixes, one equalDOF). The reference forms
//
//   A = T^T [ sum_active L_e^T (cK K*_e + cC (C_e + R_e) + cM M_e) L_e
//             + sum_nodes (cM + cC alphaM) M_n + cK sum_rows alpha c c^T ] T
//   B = T^T [ P - sum_active L_e^T f_e
//             - (dynamic) ( sum_active L_e^T (M_e a_e + R_e v_e) + sum_nodes M_n (a_n + alphaM v_n)
//             )
//             - sum_rows alpha c (c . u) ]
//
// with K* the current or the initial stiffness (StiffnessKind), C_e the element's own dashpots,
// R_e = alphaM M_e + betaK K_e + betaK0 K0_e + betaKc Kc_e its Rayleigh damping (only when the
// element takes Rayleigh damping), T the node-dof -> equation map (zero rows for fixed dofs under
// Transformation, the retained dof's row for an equalDOF-constrained one), and penalty rows c
// (the Penalty handler only: alphaSP on each fixed dof, alphaMP on u_constrained - u_retained).
#include "tcl/analysis/model/AnalysisModel.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <map>
#include <memory>
#include <random>

#include "elements/DynamicSizeElement.h"
#include "elements/beam/ElasticBeam2d.h"
#include "elements/link/Truss.h"
#include "elements/link/ZeroLength.h"
#include "elements/transform/LinearTransf.h"
#include "materials/Elastic.h"
#include "tcl/analysis/tests/CubicSpring.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/LinearSeries.h"
#include "tcl/domain/LoadPattern.h"

namespace dabs::analysis {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

/// A contact-like link that the test opens and closes: a nonlinear spring and dashpot along x
/// between two 3-dof nodes while closed; force, stiffness and damping all zero while open
/// (Element::isActive's contract). It lets the test switch an element off and on at will.
class Gate final : public elements::DynamicSizeElement {
 public:
  Gate(int tag, int i, int j, bool rayleigh = false)
      : DynamicSizeElement(tag, {i, j}, 3, rayleigh) {
    k0_(0, 0) = k0_(3, 3) = kSpring;
    k0_(0, 3) = k0_(3, 0) = -kSpring;
    kc_ = k0_;
  }
  void setClosed(bool closed) { closed_ = closed; }
  std::string_view typeName() const override { return "gate"; }
  void initialize(const elements::NodalCoordinates&) override {}
  Status update(const elements::Kinematics& t) override {
    f_.setZero();
    k_.setZero();
    c_.setZero();
    if (!closed_) return Status::Ok;
    const double du = t.u(3) - t.u(0), dv = t.v(3) - t.v(0);
    const double force = kSpring * du + kCubic * du * du * du + kDashpot * dv;
    const double kt = kSpring + 3.0 * kCubic * du * du;
    f_(0) = -force;
    f_(3) = force;
    k_(0, 0) = k_(3, 3) = kt;
    k_(0, 3) = k_(3, 0) = -kt;
    c_(0, 0) = c_(3, 3) = kDashpot;
    c_(0, 3) = c_(3, 0) = -kDashpot;
    return Status::Ok;
  }
  bool isActive() const override { return closed_; }
  bool mayTurnInactive() const override { return true; }
  void commitState() override { kc_ = k_; }
  void revertToLastCommit() override {}
  void revertToStart() override {}

 private:
  static constexpr double kSpring = 3.0e4, kCubic = 5.0e6, kDashpot = 40.0;
  bool closed_ = true;
};

class AnalysisModelTest : public ::testing::Test {
 protected:
  // Five 2D frame nodes (3 dofs each): a two-span beam 1-2-3 (consistent and lumped mass), an
  // inclined corotational truss 2-4 with a cubic material (nonlinear), a zeroLength 3-5 with
  // dashpots, the gate 4-5; node 1 fixed, node 5's rotation fixed, node 4's x equal to node 2's.
  void SetUp() override {
    const std::map<int, Eigen::Vector3d> xy = {
        {1, {0, 0, 0}}, {2, {4, 0, 0}}, {3, {8, 0, 0}}, {4, {6, 3, 0}}, {5, {8, 0, 0}}};
    for (const auto& [tag, x] : xy) {
      domain::Node& n = domain.addNode(tag, 2, 3, x);
      // Full 3x3 masses (an off-diagonal term checks the node's local mass layout).
      MatrixXd m = MatrixXd::Zero(3, 3);
      m.diagonal() << 10.0 * tag, 12.0 * tag, 0.5 * tag;
      m(0, 1) = m(1, 0) = 0.3 * tag;
      if (tag > 1) n.setMass(m);
    }
    elements::ElasticBeam2d::Params bp{
        .area = 0.02, .modulus = 2.0e8, .inertiaZ = 3.0e-4, .massPerLength = 150.0};
    bp.consistentMass = true;
    domain.addElement(std::make_unique<elements::ElasticBeam2d>(
        1, 1, 2, bp, std::make_unique<elements::LinearTransf2d>(1)));
    bp.consistentMass = false;
    domain.addElement(std::make_unique<elements::ElasticBeam2d>(
        2, 2, 3, bp, std::make_unique<elements::LinearTransf2d>(2)));
    const elements::Truss::Params tp{.nodes = {2, 4},
                                     .ndm = 2,
                                     .ndf = 3,
                                     .area = 0.01,
                                     .rho = 20.0,
                                     .consistentMass = true,
                                     .doRayleigh = true,
                                     .corotational = true};
    tp.validate();
    domain.addElement(std::make_unique<elements::Truss>(
        3, tp, std::make_unique<testing::CubicSpring>(1.0e8, 5.0e11)));
    elements::ZeroLength::Params zp{.nodes = {3, 5}, .ndm = 2, .ndf = 3, .dirs = {1, 2}};
    zp.doRayleigh = true;
    std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats;
    for (double E : {5.0e5, 8.0e5}) {  // with dashpots: a damping tangent
      materials::Elastic::Params mp;
      mp.E = E;
      mp.eta = 0.01 * E;
      mats.push_back(std::make_unique<materials::Elastic>(1, mp));
    }
    zp.validate(mats.size());
    domain.addElement(std::make_unique<elements::ZeroLength>(4, zp, std::move(mats)));
    gate = static_cast<Gate*>(&domain.addElement(std::make_unique<Gate>(5, 4, 5)));
    for (int d = 0; d < 3; ++d) domain.addFix(1, d);
    domain.addFix(5, 2);
    domain.addMP(domain::MPConstraint{2, 4, {0}, {0}, MatrixXd::Identity(1, 1)});
    auto pattern = std::make_unique<domain::PlainPattern>(
        1, std::make_shared<domain::LinearSeries>(1, 1.0), 1.0);
    pattern->loads.push_back({3, Eigen::Vector3d(10.0, -5.0, 2.0)});
    pattern->loads.push_back({4, Eigen::Vector3d(-3.0, 7.0, 0.0)});
    domain.addPattern(std::move(pattern));
  }

  // Node-dof index of (node, dof): nodes in tag order, 3 dofs each.
  static int g(int node, int dof) { return 3 * (node - 1) + dof; }
  static constexpr int kDofs = 15;
  static bool fixed(int node, int dof) { return node == 1 || (node == 5 && dof == 2); }

  /// T: node dofs -> equations, from the constraints defined in SetUp (not the model's tables;
  /// equationOf names the equation of each free dof only).
  MatrixXd mapping(const AnalysisModel& am, ConstraintKind kind) const {
    MatrixXd T = MatrixXd::Zero(kDofs, am.numEquations());
    for (int n = 1; n <= 5; ++n)
      for (int d = 0; d < 3; ++d) {
        if (kind == ConstraintKind::Penalty) {
          T(g(n, d), am.equationOf(n, d)) = 1.0;
        } else if (n == 4 && d == 0) {
          T(g(4, 0), am.equationOf(2, 0)) = 1.0;  // equalDOF: u4x = u2x
        } else if (!fixed(n, d)) {
          T(g(n, d), am.equationOf(n, d)) = 1.0;
        }
      }
    return T;
  }

  /// Penalty rows (node-dof space) with their factors.
  std::vector<std::pair<VectorXd, double>> penaltyRows(ConstraintKind kind) const {
    std::vector<std::pair<VectorXd, double>> rows;
    if (kind != ConstraintKind::Penalty) return rows;
    for (int n = 1; n <= 5; ++n)
      for (int d = 0; d < 3; ++d)
        if (fixed(n, d)) rows.emplace_back(VectorXd::Unit(kDofs, g(n, d)), alphaSP);
    VectorXd c = VectorXd::Zero(kDofs);
    c(g(4, 0)) = 1.0;
    c(g(2, 0)) = -1.0;
    rows.emplace_back(c, alphaMP);
    return rows;
  }

  struct Reference {
    MatrixXd A;
    VectorXd B;
  };
  /// The dense reference (formula at the top of the file) at the nodes' current trial state.
  Reference reference(const AnalysisModel& am, ConstraintKind kind, const AssemblyCoefficients& c,
                      double t) const {
    MatrixXd A = MatrixXd::Zero(kDofs, kDofs);
    VectorXd F = VectorXd::Zero(kDofs), u(kDofs), v(kDofs), a(kDofs);
    for (const auto& [tag, n] : domain.nodes()) {
      u.segment<3>(g(tag, 0)) = n.disp;
      v.segment<3>(g(tag, 0)) = n.vel;
      a.segment<3>(g(tag, 0)) = n.accel;
      if (n.mass().size() == 0) continue;
      A.block<3, 3>(g(tag, 0), g(tag, 0)) += (c.cM + c.cC * rayleigh.alphaM) * n.mass();
      if (c.dynamic) F.segment<3>(g(tag, 0)) += n.mass() * (n.accel + rayleigh.alphaM * n.vel);
    }
    for (const auto& [tag, e] : domain.elements()) {
      if (!e->isActive()) continue;
      MatrixXd L = MatrixXd::Zero(e->numDof(), kDofs);
      int k = 0;
      for (int nt : e->nodeTags())
        for (int d = 0; d < 3; ++d) L(k++, g(nt, d)) = 1.0;
      const domain::RayleighFactors r =
          e->rayleighByDefault() ? rayleigh : domain::RayleighFactors{};
      const MatrixXd M = e->mass();
      const MatrixXd R = r.alphaM * M + r.betaK * e->tangentStiff() + r.betaK0 * e->initialStiff() +
                         r.betaKc * e->committedStiff();
      const MatrixXd Kstar =
          c.stiffness == StiffnessKind::Current ? e->tangentStiff() : e->initialStiff();
      A += L.transpose() * (c.cK * Kstar + c.cC * (e->dampingTangent() + R) + c.cM * M) * L;
      // Through the domain: an elastic beam the analysis left to its stiffness product is formed
      // at its nodes' displacements here (Domain::setStateDeferred).
      VectorXd f = domain.elementForce(tag);
      if (c.dynamic) f += M * (L * a) + R * (L * v);
      F += L.transpose() * f;
    }
    VectorXd P = VectorXd::Zero(kDofs);
    for (const auto& [ptag, p] : domain.patterns())
      for (const domain::NodalLoad& load : p->nodalLoads())
        P.segment<3>(g(load.node, 0)) += p->factor(t) * load.values;
    VectorXd B = P - F;
    for (const auto& [row, alpha] : penaltyRows(kind)) {
      A += c.cK * alpha * row * row.transpose();
      B -= alpha * row * row.dot(u);  // support values are zero
    }
    const MatrixXd T = mapping(am, kind);
    return {T.transpose() * A * T, T.transpose() * B};
  }

  /// A random trial state in equation space, written to the nodes and the elements updated.
  void randomState(AnalysisModel& am, std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const int n = am.numEquations();
    VectorXd U(n), V(n), A(n);
    for (int i = 0; i < n; ++i) {
      U(i) = 0.01 * unit(rng);
      V(i) = 0.5 * unit(rng);
      A(i) = 3.0 * unit(rng);
    }
    am.setResponse(U, V, A);
    ASSERT_TRUE(ok(am.updateElements()));
  }

  /// Random coefficients: zeros now and then (static, undamped, massless assemblies).
  static AssemblyCoefficients randomCoefficients(std::mt19937& rng) {
    std::uniform_real_distribution<double> coef(0.1, 3.0);
    std::bernoulli_distribution zero(0.25), initial(0.3), dynamic(0.5);
    AssemblyCoefficients c;
    c.cK = coef(rng);
    c.cC = zero(rng) ? 0.0 : coef(rng) * 1e-2;
    c.cM = zero(rng) ? 0.0 : coef(rng) * 1e2;
    c.stiffness = initial(rng) ? StiffnessKind::Initial : StiffnessKind::Current;
    c.dynamic = dynamic(rng);
    return c;
  }

  /// New random Rayleigh factors (some zero) on every element and node; the model rebuilds.
  void randomRayleigh(AnalysisModel& am, std::mt19937& rng) {
    std::uniform_real_distribution<double> f(0.0, 1.0);
    std::bernoulli_distribution zero(0.3);
    rayleigh.alphaM = zero(rng) ? 0.0 : 0.5 * f(rng);
    rayleigh.betaK = zero(rng) ? 0.0 : 1e-3 * f(rng);
    rayleigh.betaK0 = zero(rng) ? 0.0 : 1e-3 * f(rng);
    rayleigh.betaKc = zero(rng) ? 0.0 : 1e-3 * f(rng);
    domain.setRayleigh(rayleigh);
    ASSERT_TRUE(am.stale());
    am.build();
  }

  /// Commits the elements so that the committed stiffness (betaKc) differs from the initial.
  void commitElements() {
    for (auto& [tag, e] : domain.elements()) e->commitState();
  }

  static void expectClose(const MatrixXd& got, const MatrixXd& ref, const char* what) {
    const double scale = ref.cwiseAbs().maxCoeff();
    EXPECT_LE((got - ref).cwiseAbs().maxCoeff(), 1e-12 * scale) << what;
  }
  void expectMatches(AnalysisModel& am, ConstraintKind kind, const AssemblyCoefficients& c,
                     double t) {
    const Reference ref = reference(am, kind, c, t);
    expectClose(MatrixXd(am.formTangent(c)), ref.A, "tangent");
    VectorXd B;
    am.formResidual(c, B);
    expectClose(B, ref.B, "residual");
  }

  domain::Domain domain;
  Gate* gate = nullptr;
  domain::RayleighFactors rayleigh;
  double alphaSP = 1.0e10, alphaMP = 3.0e9;
};

TEST_F(AnalysisModelTest, NumbersOneEquationPerFreeDofUnderEachHandler) {
  AnalysisModel transformation(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  transformation.build();
  EXPECT_EQ(transformation.numEquations(), kDofs - 4 - 1);  // four fixes, one equalDOF
  EXPECT_EQ(transformation.equationOf(1, 0), -1);
  EXPECT_EQ(transformation.equationOf(4, 0), transformation.equationOf(2, 0));
  AnalysisModel penalty(domain, ConstraintKind::Penalty, NumbererKind::RCM, alphaSP, alphaMP);
  penalty.build();
  EXPECT_EQ(penalty.numEquations(), kDofs);  // penalty rows keep every dof an equation
}

// Random coefficients, stiffness kinds, states, load times and Rayleigh factors: the sparse
// tangent and the residual (static and dynamic) equal the dense reference.
TEST_F(AnalysisModelTest, TangentAndResidualMatchDenseReferenceUnderTransformation) {
  std::mt19937 rng(20240611);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  for (int trial = 0; trial < 40; ++trial) {
    if (trial % 8 == 0) randomRayleigh(am, rng);
    const double t = 0.1 * trial;
    am.applyLoad(t);
    randomState(am, rng);
    if (trial % 3 == 0) commitElements();
    expectMatches(am, ConstraintKind::Transformation, randomCoefficients(rng), t);
  }
}

// The Penalty handler: every dof an equation, cK alpha c c^T in the tangent and -alpha c (c.u) in
// the residual for each fix (alphaSP) and the equalDOF (alphaMP).
TEST_F(AnalysisModelTest, PenaltyRowsMatchDenseReference) {
  std::mt19937 rng(7);
  AnalysisModel am(domain, ConstraintKind::Penalty, NumbererKind::Plain, alphaSP, alphaMP);
  am.build();
  for (int trial = 0; trial < 30; ++trial) {
    if (trial % 10 == 0) randomRayleigh(am, rng);
    const double t = 0.05 * trial;
    am.applyLoad(t);
    randomState(am, rng);
    expectMatches(am, ConstraintKind::Penalty, randomCoefficients(rng), t);
  }
}

// The gate opening and closing in a random sequence, often with unchanged coefficients (the
// cache's constant part must be formed again when an element's activity changes): an open gate
// leaves the tangent and the residual, a closed one comes back.
TEST_F(AnalysisModelTest, InactiveElementLeavesAndReentersTheAssembly) {
  std::mt19937 rng(99);
  std::bernoulli_distribution flip(0.5), newCoefficients(0.3);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  randomRayleigh(am, rng);
  am.applyLoad(1.0);
  AssemblyCoefficients c = randomCoefficients(rng);
  bool wasOpen = false, wasClosed = false;
  for (int trial = 0; trial < 40; ++trial) {
    const bool closed = flip(rng);
    (closed ? wasClosed : wasOpen) = true;
    gate->setClosed(closed);
    if (newCoefficients(rng)) c = randomCoefficients(rng);
    randomState(am, rng);
    ASSERT_EQ(gate->isActive(), closed);
    expectMatches(am, ConstraintKind::Transformation, c, 1.0);
  }
  EXPECT_TRUE(wasOpen && wasClosed);
}

// The tangent's cache: the same request twice gives the same matrix, bit for bit; a change of
// coefficients, of stiffness kind or of state gives the reference's new matrix, not the old one.
TEST_F(AnalysisModelTest, TangentCacheServesNoStaleMatrix) {
  std::mt19937 rng(1234);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  randomRayleigh(am, rng);
  am.applyLoad(0.5);
  randomState(am, rng);
  commitElements();
  AssemblyCoefficients c1{2.0, 0.03, 400.0, StiffnessKind::Current, true};
  AssemblyCoefficients c2{1.0, 0.0, 0.0, StiffnessKind::Current, false};
  const MatrixXd first = MatrixXd(am.formTangent(c1));
  const MatrixXd again = MatrixXd(am.formTangent(c1));
  EXPECT_EQ((first - again).cwiseAbs().maxCoeff(), 0.0);
  expectClose(first, reference(am, ConstraintKind::Transformation, c1, 0.5).A, "first");
  // New coefficients: a new constant part.
  expectClose(MatrixXd(am.formTangent(c2)),
              reference(am, ConstraintKind::Transformation, c2, 0.5).A, "new coefficients");
  // Same coefficients, initial stiffness: differs from the current tangent of the nonlinear
  // elements, which the cache must notice.
  AssemblyCoefficients c3 = c1;
  c3.stiffness = StiffnessKind::Initial;
  expectClose(MatrixXd(am.formTangent(c3)),
              reference(am, ConstraintKind::Transformation, c3, 0.5).A, "initial stiffness");
  // Back to c1 after a new state: the nonlinear elements' tangents changed.
  for (int k = 0; k < 5; ++k) {
    randomState(am, rng);
    const MatrixXd now = MatrixXd(am.formTangent(c1));
    expectClose(now, reference(am, ConstraintKind::Transformation, c1, 0.5).A, "new state");
    EXPECT_GT((now - first).cwiseAbs().maxCoeff(), 0.0);  // the state did change the matrix
  }
  // Only the residual flag differs: the same matrix.
  AssemblyCoefficients c4 = c1;
  c4.dynamic = false;
  EXPECT_EQ((MatrixXd(am.formTangent(c4)) - MatrixXd(am.formTangent(c1))).cwiseAbs().maxCoeff(),
            0.0);
}

// The constant parts kept for several coefficient sets (contact sub-steps change the step back
// and forth): ten sets, more than are kept, taken at random with the gate opening and closing
// between them, match the reference every time; a part formed while a gate with initial-stiffness
// Rayleigh damping (a constant term) was closed never serves once it is open. A set taken again
// in the same state gives the same matrix to the bit.
TEST_F(AnalysisModelTest, KeptConstantPartsFollowCoefficientsAndActivity) {
  std::mt19937 rng(321);
  std::bernoulli_distribution flip(0.2);
  auto* dampedGate =
      static_cast<Gate*>(&domain.addElement(std::make_unique<Gate>(6, 2, 3, /*rayleigh=*/true)));
  rayleigh = {0.2, 0.0, 1e-3, 0.0};
  domain.setRayleigh(rayleigh);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  am.applyLoad(1.0);
  // The first two damped, so that the gate's Rayleigh term is in their constant parts.
  std::vector<AssemblyCoefficients> sets = {{1.0, 0.02, 300.0, StiffnessKind::Current, true},
                                            {1.5, 0.01, 200.0, StiffnessKind::Current, true}};
  for (int k = 0; k < 8; ++k) sets.push_back(randomCoefficients(rng));
  std::uniform_int_distribution<std::size_t> pick(0, sets.size() - 1);
  // The case that needs the kept parts dropped: a part formed with the gates closed, the gates
  // open, a new set's part formed, then the first set again.
  for (bool closedFirst : {true, false}) {
    gate->setClosed(closedFirst);
    dampedGate->setClosed(closedFirst);
    randomState(am, rng);
    expectMatches(am, ConstraintKind::Transformation, sets[0], 1.0);
    gate->setClosed(!closedFirst);
    dampedGate->setClosed(!closedFirst);
    randomState(am, rng);
    expectMatches(am, ConstraintKind::Transformation, sets[1], 1.0);
    expectMatches(am, ConstraintKind::Transformation, sets[0], 1.0);
  }
  bool closed = true, closedAgain = false;
  for (int trial = 0; trial < 120; ++trial) {
    if (flip(rng)) {
      closed = !closed;
      closedAgain = closedAgain || closed;
      gate->setClosed(closed);
      dampedGate->setClosed(closed);
    }
    randomState(am, rng);
    ASSERT_EQ(gate->isActive(), closed);
    expectMatches(am, ConstraintKind::Transformation, sets[pick(rng)], 1.0);
  }
  EXPECT_TRUE(closedAgain);
  const MatrixXd first = MatrixXd(am.formTangent(sets[0]));
  for (std::size_t k = 1; k < sets.size(); ++k) am.formTangent(sets[k]);
  EXPECT_EQ((MatrixXd(am.formTangent(sets[0])) - first).cwiseAbs().maxCoeff(), 0.0);
}

// A support moving with an imposed velocity (MultipleSupport, node 1's x) sends the dynamic
// residual through the elements' own inertia and damping forces instead of the constant global
// matrices: the same reference (which reads the prescribed dof's motion from the node) holds.
TEST_F(AnalysisModelTest, ImposedSupportMotionBranchMatchesDenseReference) {
  domain.removeFix(1, 0);
  auto pattern = std::make_unique<domain::MultipleSupportPattern>(2);
  pattern->groundMotions[1] =
      std::make_unique<domain::GroundMotion>(std::make_shared<domain::LinearSeries>(2, 3.0),
                                             std::make_shared<domain::LinearSeries>(3, 0.2),
                                             std::make_shared<domain::LinearSeries>(4, 0.01), 1.0);
  pattern->imposed.push_back({1, 0, 1, true});
  domain.addPattern(std::move(pattern));
  std::mt19937 rng(4242);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  for (int trial = 0; trial < 30; ++trial) {
    if (trial % 6 == 0) randomRayleigh(am, rng);
    const double t = 0.2 + 0.1 * trial;
    am.applyLoad(t);
    randomState(am, rng);
    ASSERT_NE(domain.node(1).vel(0), 0.0);  // the support moves
    if (trial % 4 == 0) commitElements();
    gate->setClosed(trial % 5 != 0);
    ASSERT_TRUE(ok(am.updateElements()));
    AssemblyCoefficients c = randomCoefficients(rng);
    c.dynamic = true;
    expectMatches(am, ConstraintKind::Transformation, c, t);
  }
}

// An inactive element that takes Rayleigh damping with betaK0 (a nonzero initial stiffness) must
// add no damping force, as it adds nothing to the tangent and nothing in the imposed-motion
// branch.
TEST_F(AnalysisModelTest, InactiveElementWithRayleighAddsNoDampingForce) {
  // The element may turn inactive (Element::mayTurnInactive), so its Rayleigh damping stays out
  // of the damping matrix formed at build() and the residual adds it only while it is active.
  domain.addElement(std::make_unique<Gate>(6, 2, 3, /*rayleigh=*/true));
  rayleigh = {0.0, 0.0, 1e-3, 0.0};
  domain.setRayleigh(rayleigh);
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  am.applyLoad(1.0);
  std::mt19937 rng(5);
  for (auto* e : {gate, static_cast<Gate*>(domain.findElement(6))}) e->setClosed(false);
  randomState(am, rng);
  expectMatches(am, ConstraintKind::Transformation,
                {1.0, 0.02, 300.0, StiffnessKind::Current, true}, 1.0);
}

// formMass is the tangent with cK = 0, cM = 1: element and nodal masses alone.
TEST_F(AnalysisModelTest, MassMatrixMatchesDenseReference) {
  AnalysisModel am(domain, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  AssemblyCoefficients c{0.0, 0.0, 1.0, StiffnessKind::Current, false};
  expectClose(MatrixXd(am.formMass()), reference(am, ConstraintKind::Transformation, c, 0.0).A,
              "mass");
}

/// A linear spring along x between two 1-dof nodes that counts its updates and says, as told,
/// whether its state may be kept at the same displacements
/// (Element::keepsStateAtSameDisplacements). `nonlinear`: it says it is not linear (so the
/// analysis gathers its rates) and takes Rayleigh damping.
class CountingSpring final : public elements::DynamicSizeElement {
 public:
  CountingSpring(int tag, int i, int j, bool nonlinear = false)
      : DynamicSizeElement(tag, {i, j}, 1, nonlinear), nonlinear_(nonlinear) {
    k0_ << kStiffness, -kStiffness, -kStiffness, kStiffness;
    k_ = kc_ = k0_;
  }
  std::string_view typeName() const override { return "countingSpring"; }
  void initialize(const elements::NodalCoordinates&) override {}
  Status update(const elements::Kinematics& t) override {
    ++updates;
    f_ = k0_ * t.u;
    return Status::Ok;
  }
  bool isLinear() const override { return !nonlinear_; }
  bool keepsStateAtSameDisplacements() const override { return keeps; }
  bool forceIsInitialStiffnessTimesDisplacements() const override { return deferrable; }
  void commitState() override { ++commits; }
  void revertToLastCommit() override {}
  void revertToStart() override {}

  static constexpr double kStiffness = 2.0e3;
  int updates = 0;
  int commits = 0;
  bool keeps = true;
  bool deferrable = false;

 private:
  bool nonlinear_ = false;
};

// An element whose state depends on its displacements alone is not updated again while no node
// moved (a transient predictor moves only the rates); any move of a node, by the model or not,
// or an element that cannot keep its state, updates it.
TEST(AnalysisModelSkipTest, ElementKeepingItsStateIsNotUpdatedWhileNoNodeMoves) {
  domain::Domain d;
  for (int tag : {1, 2}) d.addNode(tag, 1, 1, Eigen::Vector3d(tag, 0, 0));
  d.addFix(1, 0);
  d.addElement(std::make_unique<CountingSpring>(1, 1, 2));
  auto& spring = static_cast<CountingSpring&>(*d.findElement(1));
  AnalysisModel am(d, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  am.applyLoad(0.0);  // no pattern: P = 0
  ASSERT_EQ(am.numEquations(), 1);
  const VectorXd u = VectorXd::Constant(1, 0.004), rates = VectorXd::Constant(1, 0.3);
  auto pass = [&](const VectorXd& U, const VectorXd& V) {
    am.setResponse(U, V, V);
    ASSERT_TRUE(ok(am.updateElements()));
  };
  pass(u, rates);
  EXPECT_EQ(spring.updates, 1);
  pass(u, 2.0 * rates);  // the rates alone moved
  EXPECT_EQ(spring.updates, 1);
  VectorXd B;
  am.formResidual({1.0, 0.0, 0.0, StiffnessKind::Current, false}, B);
  EXPECT_DOUBLE_EQ(B(0), -CountingSpring::kStiffness * 0.004);  // the kept force
  pass(2.0 * u, rates);
  EXPECT_EQ(spring.updates, 2);
  d.findNode(2)->disp(0) = 0.001;  // moved outside the model
  ASSERT_TRUE(ok(am.updateElements()));
  EXPECT_EQ(spring.updates, 3);
  spring.keeps = false;
  ASSERT_TRUE(ok(am.updateElements()));
  EXPECT_EQ(spring.updates, 4);
  // Non-finite displacements fail the pass before the element sees them; the same ones again
  // must fail again, not be taken as the kept state's.
  spring.keeps = true;
  const VectorXd nan = VectorXd::Constant(1, std::numeric_limits<double>::quiet_NaN());
  for (int attempt = 0; attempt < 2; ++attempt) {
    am.setResponse(nan, rates, rates);
    EXPECT_FALSE(ok(am.updateElements())) << "attempt " << attempt;
  }
}

// A nonlinear element kept at the same displacements still has its rates gathered: the residual's
// Rayleigh term with the current tangent, betaK K v, reads them (the beam of a transient
// predictor, whose velocities moved).
TEST(AnalysisModelSkipTest, KeptNonlinearElementStillGathersItsRates) {
  domain::Domain d;
  for (int tag : {1, 2}) d.addNode(tag, 1, 1, Eigen::Vector3d(tag, 0, 0));
  d.addFix(1, 0);
  d.addElement(std::make_unique<CountingSpring>(1, 1, 2, true));
  auto& spring = static_cast<CountingSpring&>(*d.findElement(1));
  domain::RayleighFactors rayleigh;
  rayleigh.betaK = 0.01;
  d.setRayleigh(rayleigh);
  AnalysisModel am(d, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  am.applyLoad(0.0);
  ASSERT_EQ(am.numEquations(), 1);
  const VectorXd u = VectorXd::Constant(1, 0.004), rates = VectorXd::Constant(1, 0.3);
  am.setResponse(u, rates, rates);
  ASSERT_TRUE(ok(am.updateElements()));
  am.setResponse(u, 2.0 * rates, rates);
  ASSERT_TRUE(ok(am.updateElements()));
  EXPECT_EQ(spring.updates, 1);
  VectorXd B;
  am.formResidual({1.0, 0.0, 0.0, StiffnessKind::Current, true}, B);
  const double k = CountingSpring::kStiffness;
  EXPECT_DOUBLE_EQ(B(0), -k * 0.004 - 0.01 * k * 0.6);
  // A non-finite velocity fails the pass as an update would.
  am.setResponse(u, VectorXd::Constant(1, std::numeric_limits<double>::infinity()), rates);
  EXPECT_FALSE(ok(am.updateElements()));
}

// A spring whose force is its stiffness times its displacements is left to one product with the
// assembled stiffness: the passes and the domain's commit leave it, the residual is the same, and
// the domain forms its state when it is read or when the mark is lifted. Chain 1-2-3 along x,
// node 1 fixed, u2 = 0.004, u3 = 0.010: internal forces k (u2 - (u3 - u2)) = -0.002 k at node 2
// and k (u3 - u2) = 0.006 k at node 3.
TEST(AnalysisModelSkipTest, DeferredElementIsOneProductAndFormedWhenRead) {
  domain::Domain d;
  for (int tag : {1, 2, 3}) d.addNode(tag, 1, 1, Eigen::Vector3d(tag, 0, 0));
  d.addFix(1, 0);
  d.addElement(std::make_unique<CountingSpring>(1, 1, 2));
  d.addElement(std::make_unique<CountingSpring>(2, 2, 3));
  auto& deferred = static_cast<CountingSpring&>(*d.findElement(1));
  auto& updated = static_cast<CountingSpring&>(*d.findElement(2));
  deferred.deferrable = true;
  updated.keeps = false;
  AnalysisModel am(d, ConstraintKind::Transformation, NumbererKind::RCM);
  am.build();
  am.applyLoad(0.0);
  EXPECT_TRUE(d.stateDeferred(1));
  EXPECT_FALSE(d.stateDeferred(2));
  VectorXd U(2);
  U(am.equationOf(2, 0)) = 0.004;
  U(am.equationOf(3, 0)) = 0.010;
  am.setResponse(U, VectorXd::Zero(2), VectorXd::Zero(2));
  ASSERT_TRUE(ok(am.updateElements()));
  EXPECT_EQ(deferred.updates, 0);
  EXPECT_EQ(updated.updates, 1);
  EXPECT_EQ(am.elementUpdates(), 1);
  VectorXd B;
  am.formResidual({1.0, 0.0, 0.0, StiffnessKind::Current, false}, B);
  const double k = CountingSpring::kStiffness;
  EXPECT_NEAR(B(am.equationOf(2, 0)), 0.002 * k, 1e-12 * k);
  EXPECT_NEAR(B(am.equationOf(3, 0)), -0.006 * k, 1e-12 * k);
  d.commit();
  EXPECT_EQ(deferred.commits, 0);
  EXPECT_EQ(updated.commits, 1);
  // Read: formed at the nodes' trial displacements, u2 - u1 = 0.004.
  const VectorXd f = d.elementForce(1);
  EXPECT_EQ(deferred.updates, 1);
  EXPECT_NEAR(f(1), 0.004 * k, 1e-12 * k);
  // Lifting the mark forms the committed state and then the trial one.
  d.setStateDeferred(1, false);
  EXPECT_EQ(deferred.updates, 3);
  EXPECT_EQ(deferred.commits, 1);
  EXPECT_FALSE(d.stateDeferred(1));
  d.commit();  // the domain's lists were current: the lifted mark shows in them at once
  EXPECT_EQ(deferred.commits, 2);
  // Only an element that says its state is its displacements' may be marked.
  EXPECT_THROW(d.setStateDeferred(2, true), InputError);
  EXPECT_THROW(d.setStateDeferred(99, true), InputError);
  EXPECT_FALSE(d.stateDeferred(2));
}

}  // namespace
}  // namespace dabs::analysis
