// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <span>
#include <vector>

#include "tcl/analysis/model/ConstraintHandler.h"
#include "tcl/analysis/model/Scatter.h"

namespace dabs::analysis {

/// Which stiffness the tangent uses.
enum class StiffnessKind { Current, Initial };

/// Coefficients of one assembly: A = cK K + cC C + cM M and whether inertia and damping forces
/// enter the residual (transient) or not (static).
struct AssemblyCoefficients {
  double cK = 1.0;
  double cC = 0.0;
  double cM = 0.0;
  StiffnessKind stiffness = StiffnessKind::Current;
  bool dynamic = false;
  /// True when `o` forms the same matrix (the residual flag aside).
  bool sameMatrix(const AssemblyCoefficients& o) const noexcept {
    return cK == o.cK && cC == o.cC && cM == o.cM && stiffness == o.stiffness;
  }
};

/// Forms the tangent A = cK K + cC C + cM M into a fixed sparse pattern's values through the
/// scatter records. What cannot change between assemblies with the same coefficients (linear
/// elements, nodal masses, penalty rows, the mass and initial-stiffness damping of the other
/// elements) is summed once and copied; when an element turned active or inactive since, that
/// constant part is formed anew and the assembly tried again.
///
/// The constant parts of the last few coefficient sets are kept: contact sub-steps change the
/// step, and with it the coefficients, back and forth among a few values (the case study's
/// pound case: 86 sets, 7 of them in 94 % of its 24,441 assemblies), and a part summed again at
/// each change was a third of the assemblies. A kept part is the same sum, so the same bits.
class TangentAssembler {
 public:
  /// Forgets the constant parts (a new pattern).
  void reset() noexcept { kept_.clear(); }
  /// Writes the tangent of the awake elements `elements`, the nodes and the penalty rows into
  /// `values` (nnz of them).
  void form(const AssemblyCoefficients& c, double* values, std::size_t nnz,
            std::span<ElementScatter> elements, std::span<const NodeScatter> nodes,
            std::span<const PenaltyRow> penalties);

  /// Which of an element's matrix terms addElement adds: all, those that never change (mass and
  /// initial-stiffness damping), or the others.
  enum class Terms { All, Constant, Varying };
  /// Adds cK K + cC C + cM M of one element (those of `terms`) to the matrix values.
  static void addElement(double* values, ElementScatter& l, const AssemblyCoefficients& c,
                         Terms terms = Terms::All);

 private:
  /// Tangent values of what never changes, for the coefficients `c`, formed with the elements'
  /// activity of ElementScatter::constantActive (the same for every kept part).
  struct ConstantPart {
    AssemblyCoefficients c;
    std::vector<double> values;
    long lastUse = 0;
  };
  /// The kept part for `c`, formed (replacing the least recently used one when all are taken)
  /// if there is none.
  const ConstantPart& constantPart(const AssemblyCoefficients& c, std::size_t nnz,
                                   std::span<ElementScatter> elements,
                                   std::span<const NodeScatter> nodes,
                                   std::span<const PenaltyRow> penalties);
  /// Parts kept at most: a few, and fewer when the matrix is large (2^23 values in all, 64 MB).
  static std::size_t keptAtMost(std::size_t nnz) noexcept {
    constexpr std::size_t kParts = 8, kValues = std::size_t{1} << 23;
    return std::clamp<std::size_t>(kValues / std::max<std::size_t>(nnz, 1), 1, kParts);
  }
  std::vector<ConstantPart> kept_;
  long uses_ = 0;
};

}  // namespace dabs::analysis
