// SPDX-License-Identifier: MIT
#pragma once

#include <optional>
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
class TangentAssembler {
 public:
  /// Forgets the constant part (a new pattern).
  void reset() noexcept { constantFor_.reset(); }
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
  // Tangent values of what never changes for the coefficients constantFor_.
  std::vector<double> constantValues_;
  std::optional<AssemblyCoefficients> constantFor_;
};

}  // namespace dabs::analysis
