// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/TangentAssembler.h"

#include <algorithm>

namespace dabs::analysis {

void TangentAssembler::addElement(double* values, ElementScatter& l, const AssemblyCoefficients& c,
                                  Terms terms) {
  const elements::Element& e = *l.element;
  Eigen::MatrixXd& local = l.work;
  const bool varying = terms != Terms::Constant;
  const bool constant = terms != Terms::Varying;
  const auto& r = l.rayleigh;
  if (varying) {
    const auto k = c.stiffness == StiffnessKind::Current ? e.tangentStiff() : e.initialStiff();
    local.noalias() = c.cK * k;
    if (c.cC != 0.0) {
      local.noalias() += c.cC * e.dampingTangent();
      if (l.rayleighOn) {
        if (r.betaK != 0.0) local.noalias() += (c.cC * r.betaK) * e.tangentStiff();
        if (r.betaKc != 0.0) local.noalias() += (c.cC * r.betaKc) * e.committedStiff();
      }
    }
  } else {
    const bool damped = c.cC != 0.0 && l.rayleighOn && (r.alphaM != 0.0 || r.betaK0 != 0.0);
    if (!damped && c.cM == 0.0) return;
    local.setZero(e.numDof(), e.numDof());
  }
  if (constant) {
    if (c.cC != 0.0 && l.rayleighOn) {
      if (r.alphaM != 0.0) local.noalias() += (c.cC * r.alphaM) * e.mass();
      if (r.betaK0 != 0.0) local.noalias() += (c.cC * r.betaK0) * e.initialStiff();
    }
    if (c.cM != 0.0) local.noalias() += c.cM * e.mass();
  }
  l.addMatrix(values, local);
}

void TangentAssembler::form(const AssemblyCoefficients& c, double* values, std::size_t nnz,
                            std::span<ElementScatter> elements, std::span<const NodeScatter> nodes,
                            std::span<const PenaltyRow> penalties) {
  // The nonlinear elements' varying terms are formed at every assembly; an element that turns
  // active or inactive (a contact pair) makes the constant part anew.
  for (;;) {
    if (!constantFor_ || !constantFor_->sameMatrix(c)) {
      std::fill(values, values + nnz, 0.0);
      for (ElementScatter& l : elements) {
        const bool active = l.element->isActive();
        if (l.element->isLinear()) {
          if (active) addElement(values, l, c);
        } else {
          l.constantActive = active;
          if (active) addElement(values, l, c, Terms::Constant);
        }
      }
      if (c.cM != 0.0 || c.cC != 0.0) {
        for (const NodeScatter& nl : nodes) {
          const double f = c.cM + c.cC * nl.alphaM;
          const double* m = nl.node->mass().data();
          for (const MatEntry& me : nl.mass) values[me.value] += f * me.coef * m[me.local];
        }
      }
      for (const PenaltyRow& row : penalties) {
        std::size_t idx = 0;
        for (const auto& a : row.eqs)
          for (const auto& b : row.eqs)
            values[row.valueIndex[idx++]] += c.cK * row.alpha * a.second * b.second;
      }
      constantValues_.assign(values, values + nnz);
      constantFor_ = c;
    } else {
      std::copy(constantValues_.begin(), constantValues_.end(), values);
    }
    bool activityChanged = false;
    for (ElementScatter& l : elements) {
      if (l.element->isLinear()) continue;
      const bool active = l.element->isActive();
      if (active != l.constantActive) {
        activityChanged = true;
        break;
      }
      if (active) addElement(values, l, c, Terms::Varying);
    }
    if (!activityChanged) return;
    constantFor_.reset();
  }
}

}  // namespace dabs::analysis
