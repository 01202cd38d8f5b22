// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "materials/section/geometry/Fiber.h"

namespace dabs::materials::section {

/// Quadrilateral patch (`patch quad matTag nIJ nJK yI zI yJ zJ yK zK yL zL`, vertices counter-
/// clockwise) or rectangle (`patch rect matTag nY nZ yI zI yJ zJ`, I bottom-left, J top-right),
/// divided into nIJ x nJK cells by the bilinear map of the corners, one fiber per cell at the
/// cell's centroid with the cell's area (OpenSees/OpenSees:SRC/material/section/repres/patch/
/// QuadPatch.cpp).
struct QuadPatch {
  int materialTag = 0;
  int divIJ = 1, divJK = 1;
  std::array<double, 4> y{}, z{};  ///< vertices I, J, K, L

  /// Rectangle with corners (yI, zI) and (yJ, zJ), nY divisions along y and nZ along z.
  static QuadPatch rect(int mat, int nY, int nZ, double yI, double zI, double yJ, double zJ);
  /// Throws InputError for nonpositive divisions or a degenerate/clockwise quadrilateral.
  void validate() const;
  /// Appends the fibers to `out`.
  void discretize(FiberList& out) const;
};

}  // namespace dabs::materials::section
