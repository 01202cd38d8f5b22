// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/TangentAssembler.h"

#include <Eigen/Core>
#include <algorithm>

namespace dabs::analysis {

namespace {

/// addElement for an element that names its matrices' support: each entry the scatter holds is
/// formed alone, by the operations the whole-matrix path does on it and in the same order, so
/// the values are the same to the bit (and 0 + x is x: the constant terms' zero start).
void addElementEntries(double* values, const ElementScatter& l, const AssemblyCoefficients& c,
                       bool varying, bool constant) {
  const elements::Element& e = *l.element;
  const auto& r = l.rayleigh;
  const bool damped = c.cC != 0.0 && l.rayleighOn && (r.alphaM != 0.0 || r.betaK0 != 0.0);
  if (!varying && !damped && c.cM == 0.0) return;
  // The matrices are an element's own n x n arrays (column-major, no gaps), read by entry.
  const double* k =
      (c.stiffness == StiffnessKind::Current ? e.tangentStiff() : e.initialStiff()).data();
  const double* tangent = e.tangentStiff().data();
  const double* committed = e.committedStiff().data();
  const double* damping = e.dampingTangent().data();
  const double* mass = e.mass().data();
  const double* initial = e.initialStiff().data();
  const bool rayleighTerms = c.cC != 0.0 && l.rayleighOn;
  auto entry = [&](int i) {
    double x = 0.0;
    if (varying) {
      x = c.cK * k[i];
      if (c.cC != 0.0) {
        x += c.cC * damping[i];
        if (rayleighTerms && r.betaK != 0.0) x += (c.cC * r.betaK) * tangent[i];
        if (rayleighTerms && r.betaKc != 0.0) x += (c.cC * r.betaKc) * committed[i];
      }
    }
    if (constant) {
      if (rayleighTerms && r.alphaM != 0.0) x += (c.cC * r.alphaM) * mass[i];
      if (rayleighTerms && r.betaK0 != 0.0) x += (c.cC * r.betaK0) * initial[i];
      if (c.cM != 0.0) x += c.cM * mass[i];
    }
    return x;
  };
  if (l.matSlots.empty()) {
    l.addEntries(values, entry);
    return;
  }
  for (const auto& [offset, value] : l.matSlots) values[value] += entry(offset);
}

}  // namespace

void TangentAssembler::addElement(double* values, ElementScatter& l, const AssemblyCoefficients& c,
                                  Terms terms) {
  if (l.sparse) {
    addElementEntries(values, l, c, terms != Terms::Constant, terms != Terms::Varying);
    return;
  }
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

const TangentAssembler::ConstantPart& TangentAssembler::constantPart(
    const AssemblyCoefficients& c, std::size_t nnz, std::span<ElementScatter> elements,
    std::span<const NodeScatter> nodes, std::span<const PenaltyRow> penalties) {
  ++uses_;
  for (ConstantPart& part : kept_)
    if (part.c.sameMatrix(c)) {
      part.lastUse = uses_;
      return part;
    }
  // The kept parts hold the nonlinear elements' constant terms of the activity they were formed
  // with; a new part takes the present one, so the others go when it differs.
  for (const ElementScatter& l : elements)
    if (!l.element->isLinear() && l.element->isActive() != l.constantActive) {
      kept_.clear();
      break;
    }
  ConstantPart* part = nullptr;
  if (kept_.size() < keptAtMost(nnz)) {
    part = &kept_.emplace_back();
  } else {
    part = &*std::min_element(kept_.begin(), kept_.end(),
                              [](const auto& a, const auto& b) { return a.lastUse < b.lastUse; });
  }
  part->c = c;
  part->lastUse = uses_;
  std::vector<double>& values = part->values;
  values.assign(nnz, 0.0);
  for (ElementScatter& l : elements) {
    const bool active = l.element->isActive();
    if (l.element->isLinear()) {
      if (active) addElement(values.data(), l, c);
    } else {
      l.constantActive = active;
      if (active) addElement(values.data(), l, c, Terms::Constant);
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
  return *part;
}

void TangentAssembler::form(const AssemblyCoefficients& c, double* values, std::size_t nnz,
                            std::span<ElementScatter> elements, std::span<const NodeScatter> nodes,
                            std::span<const PenaltyRow> penalties) {
  // The nonlinear elements' varying terms are formed at every assembly; an element that turns
  // active or inactive (a contact pair) makes the constant parts anew.
  for (;;) {
    const ConstantPart& part = constantPart(c, nnz, elements, nodes, penalties);
    // An Eigen (vector-register) copy, not std::copy: glibc 2.36 copies a block this size (57 KB
    // on the 10-span benchmark bridge) with `rep movsb`, which on the project's AMD EPYC
    // machines ran several times slower in the step than in isolation, 6.6 % of that bridge's
    // time (perf) against under 1 % now.
    Eigen::Map<Eigen::VectorXd>(values, static_cast<Eigen::Index>(nnz)) =
        Eigen::Map<const Eigen::VectorXd>(part.values.data(), static_cast<Eigen::Index>(nnz));
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
    kept_.clear();
  }
}

}  // namespace dabs::analysis
