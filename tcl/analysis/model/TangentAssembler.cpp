// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/TangentAssembler.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>

namespace dabs::analysis {

void TangentAssembler::addElement(double* values, ElementScatter& l, const AssemblyCoefficients& c,
                                  Terms terms) {
  const elements::Element& e = *l.element;
  const bool varying = terms != Terms::Constant;
  const bool constant = terms != Terms::Varying;
  const auto& r = l.rayleigh;
  const bool rayleighTerms = c.cC != 0.0 && l.rayleighOn;
  // The terms of cK K + cC C + cM M asked for, in the order they are added. The element's
  // matrices are its own n x n arrays (column-major, no gaps).
  struct Term {
    double coef;
    const double* matrix;
  };
  std::array<Term, 7> list{};
  int count = 0;
  auto add = [&](double coef, const Eigen::Ref<const Eigen::MatrixXd>& m) {
    list[static_cast<std::size_t>(count++)] = {coef, m.data()};
  };
  if (varying) {
    add(c.cK, c.stiffness == StiffnessKind::Current ? e.tangentStiff() : e.initialStiff());
    if (c.cC != 0.0) {
      add(c.cC, e.dampingTangent());
      if (rayleighTerms && r.betaK != 0.0) add(c.cC * r.betaK, e.tangentStiff());
      if (rayleighTerms && r.betaKc != 0.0) add(c.cC * r.betaKc, e.committedStiff());
    }
  }
  if (constant) {
    if (rayleighTerms && r.alphaM != 0.0) add(c.cC * r.alphaM, e.mass());
    if (rayleighTerms && r.betaK0 != 0.0) add(c.cC * r.betaK0, e.initialStiff());
    if (c.cM != 0.0) add(c.cM, e.mass());
  }
  if (count == 0) return;
  // Term by term over the entries: everywhere, or only where the element's matrices can be
  // nonzero (Element::matrixSupport; the scatter holds those entries alone). The constant terms
  // alone start from zero.
  double* local = l.work.data();
  auto form = [&](auto overEntries) {
    const Term* t = list.data();
    const Term* const end = t + count;
    if (varying) {
      overEntries([&](int i) { local[i] = t->coef * t->matrix[i]; });
      ++t;
    } else {
      overEntries([&](int i) { local[i] = 0.0; });
    }
    for (; t != end; ++t) overEntries([&](int i) { local[i] += t->coef * t->matrix[i]; });
  };
  const std::span<const int> support = e.matrixSupport();
  if (support.empty()) {
    const auto size = static_cast<int>(l.work.size());
    form([&](auto f) {
      for (int i = 0; i < size; ++i) f(i);
    });
  } else {
    form([&](auto f) {
      for (const int i : support) f(i);
    });
  }
  l.addMatrix(values, l.work);
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
    if (!l.linear && l.element->isActive() != l.constantActive) {
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
    if (l.linear) {
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
      if (l.linear) continue;
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
