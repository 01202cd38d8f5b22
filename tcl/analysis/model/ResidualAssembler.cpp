// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/ResidualAssembler.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace dabs::analysis {

namespace {
constexpr std::size_t kPrefetchAhead = 4;
}  // namespace

void ResidualAssembler::build(std::span<ElementScatter> elements,
                              std::span<const NodeScatter> nodes,
                              const Eigen::SparseMatrix<double>& pattern) {
  const auto nnz = static_cast<std::size_t>(pattern.nonZeros());
  std::vector<double> mass(nnz, 0.0), damping(nnz, 0.0), stiffness(nnz, 0.0);
  rayleighLeft_.assign(elements.size(), 0);
  anyDeferred_ = false;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    ElementScatter& l = elements[k];
    const elements::Element& e = *l.element;
    if (l.deferred) {
      l.addMatrix(stiffness.data(), e.initialStiff());
      anyDeferred_ = true;
    }
    const Eigen::MatrixXd m = e.mass();
    l.ownDynamics = e.mayTurnInactive() && (l.rayleighOn || !m.isZero(0.0));
    if (l.ownDynamics) continue;
    l.addMatrix(mass.data(), m);
    if (!l.rayleighOn) continue;
    const auto& r = l.rayleigh;
    Eigen::MatrixXd c = r.alphaM * m + r.betaK0 * e.initialStiff();
    if (e.isLinear()) {
      c += (r.betaK + r.betaKc) * e.initialStiff();
    } else if (r.betaK != 0.0 || r.betaKc != 0.0) {
      rayleighLeft_[k] = 1;
    }
    l.addMatrix(damping.data(), c);
  }
  for (const NodeScatter& nl : nodes) {
    const double* m = nl.node->mass().data();
    for (const MatEntry& me : nl.mass) {
      const double v = me.coef * m[me.local];
      mass[static_cast<std::size_t>(me.value)] += v;
      damping[static_cast<std::size_t>(me.value)] += nl.alphaM * v;
    }
  }
  auto onPattern = [&pattern](Eigen::SparseMatrix<double>& m, const std::vector<double>& values) {
    m = pattern;
    std::copy(values.begin(), values.end(), m.valuePtr());
    m.prune(0.0);
  };
  onPattern(massGlobal_, mass);
  onPattern(dampingGlobal_, damping);
  Eigen::SparseMatrix<double> deferred;
  onPattern(deferred, stiffness);
  deferredStiffness_ = deferred;
  eqDisp_ = eqVel_ = eqAcc_ = deferredForce_ = Eigen::VectorXd::Zero(pattern.rows());
  deferredAt_ = Eigen::VectorXd::Constant(pattern.rows(), std::numeric_limits<double>::quiet_NaN());
}

void ResidualAssembler::form(const AssemblyCoefficients& c, const ResidualInputs& in,
                             Eigen::VectorXd& B) const {
  B = in.P;
  const bool global = c.dynamic && !in.imposedMotion;
  const std::size_t count = in.elements.size();
  for (std::size_t k = 0; k < count; ++k) {
    // The element objects and scatter arrays a few links ahead: a pass over a large model's fiber
    // states has evicted them since the update, and each is a separate allocation the hardware
    // prefetcher cannot guess.
    if (k + kPrefetchAhead < count && !in.elements[k + kPrefetchAhead].deferred) {
      const ElementScatter& ahead = in.elements[k + kPrefetchAhead];
      __builtin_prefetch(ahead.element);
      __builtin_prefetch(reinterpret_cast<const char*>(ahead.element) + 64);
      __builtin_prefetch(reinterpret_cast<const char*>(ahead.element) + 128);
      __builtin_prefetch(ahead.direct.data());
    }
    const ElementScatter& l = in.elements[k];
    if (l.deferred) continue;  // in the product below
    const elements::Element& e = *l.element;
    if (!e.isActive()) continue;
    if (global && !l.ownDynamics) {
      if (rayleighLeft_[k] == 0) {
        l.subtractForce(e.resistingForce(), B);
        continue;
      }
      Eigen::VectorXd& f = l.force;
      f = e.resistingForce();
      const auto& r = l.rayleigh;
      if (r.betaK != 0.0) f.noalias() += r.betaK * (e.tangentStiff() * l.v);
      if (r.betaKc != 0.0) f.noalias() += r.betaKc * (e.committedStiff() * l.v);
      l.subtractForce(f, B);
    } else if (c.dynamic) {
      // (also an element with its own dynamics under the global matrices: its rates are
      // gathered, as for every nonlinear element or one with a damping tangent)
      Eigen::VectorXd& f = l.force;
      f = e.resistingForce();
      const auto m = e.mass();
      f.noalias() += m * l.a;
      if (l.rayleighOn) {
        const auto& r = l.rayleigh;
        if (r.alphaM != 0.0) f.noalias() += r.alphaM * (m * l.v);
        if (r.betaK != 0.0) f.noalias() += r.betaK * (e.tangentStiff() * l.v);
        if (r.betaK0 != 0.0) f.noalias() += r.betaK0 * (e.initialStiff() * l.v);
        if (r.betaKc != 0.0) f.noalias() += r.betaKc * (e.committedStiff() * l.v);
      }
      l.subtractForce(f, B);
    } else {
      l.subtractForce(e.resistingForce(), B);
    }
  }
  const bool rates = c.dynamic && (global || hasModalDamping());
  if (anyDeferred_ || rates) {
    const auto neq = static_cast<int>(in.eqDof.size());
    for (int eq = 0; eq < neq; ++eq) {
      const auto& [node, dof] = in.eqDof[static_cast<std::size_t>(eq)];
      eqDisp_(eq) = node->disp(dof);
      eqVel_(eq) = node->vel(dof);
      eqAcc_(eq) = node->accel(dof);
    }
  }
  // The deferred elements: no support value a pattern drives is among their dofs, so their
  // force is their assembled stiffness times the equations' values.
  if (anyDeferred_) {
    const auto bytes = static_cast<std::size_t>(eqDisp_.size()) * sizeof(double);
    if (std::memcmp(eqDisp_.data(), deferredAt_.data(), bytes) != 0) {
      deferredForce_.noalias() = deferredStiffness_ * eqDisp_;
      deferredAt_ = eqDisp_;
    }
    B -= deferredForce_;
  }
  if (c.dynamic) {
    if (global) {
      B.noalias() -= massGlobal_ * eqAcc_;
      B.noalias() -= dampingGlobal_ * eqVel_;
    } else {
      for (const NodeScatter& nl : in.nodes) {
        if (nl.mass.empty()) continue;
        const domain::Node& n = *nl.node;
        // At most 6 dofs a node: on the stack, no allocation in the iteration.
        const Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> f =
            n.mass() * (n.accel + nl.alphaM * n.vel);
        for (const VecEntry& v : nl.vec) B(v.eq) -= v.coef * f(v.local);
      }
    }
    if (hasModalDamping())
      B.noalias() -=
          modalMphi_ * (modalCoefficients_.asDiagonal() * (modalMphi_.transpose() * eqVel_));
  }
  for (const PenaltyRow& row : in.penalties) {
    // Penalty force alpha c (g - c.u) (OpenSees PenaltySP_FE / PenaltyMP_FE).
    double cu = 0.0;
    for (auto [eq, coef] : row.eqs) {
      const auto& [node, dof] = in.eqDof[static_cast<std::size_t>(eq)];
      cu += coef * node->disp(dof);
    }
    const double g = row.slot >= 0 ? in.slots[static_cast<std::size_t>(row.slot)].disp : 0.0;
    for (auto [eq, coef] : row.eqs) B(eq) += row.alpha * coef * (g - cu);
  }
}

void ResidualAssembler::formDeferredForce(
    std::span<const std::pair<domain::Node*, int>> eqDof) const {
  if (!anyDeferred_) return;
  const auto neq = static_cast<Eigen::Index>(eqDof.size());
  for (Eigen::Index eq = 0; eq < neq; ++eq) {
    const auto& [node, dof] = eqDof[static_cast<std::size_t>(eq)];
    deferredAt_(eq) = node->disp(dof);
  }
  deferredForce_.noalias() = deferredStiffness_ * deferredAt_;
}

void ResidualAssembler::setModalDamping(const Eigen::MatrixXd& Mphi,
                                        const Eigen::VectorXd& coefficients) {
  modalMphi_ = Mphi;
  modalCoefficients_ = coefficients;
}

}  // namespace dabs::analysis
