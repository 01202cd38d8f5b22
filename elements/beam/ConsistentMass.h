// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

#include "elements/transform/FrameTraits.h"

namespace dabs::elements {

/// Local consistent mass of a straight beam of mass `mass` and length `length` (Przemieniecki
/// 1968, Theory of Matrix Structural Analysis, eq. 11.42): linear axial, cubic Hermitian
/// transverse in each bending plane; dofs 2D [u v rz]_i [..]_j, 3D [u v w rx ry rz]_i [..]_j.
/// 3D: `polar` = J/A gives a linear torsional (polar) mass (0: none); in the x-z plane
/// ry = -dw/dx flips the sign of the coupling terms.
template <int Ndm>
typename FrameTraits<Ndm>::GlobalMatrix consistentMass(double mass, double length,
                                                       double polar = 0.0) {
  using Matrix = typename FrameTraits<Ndm>::GlobalMatrix;
  constexpr int n = FrameTraits<Ndm>::kDofPerNode;
  Matrix ml = Matrix::Zero();
  const double m = mass / 420.0, l = length;
  ml(0, 0) = ml(n, n) = 140.0 * m;
  ml(0, n) = ml(n, 0) = 70.0 * m;
  if constexpr (Ndm == 3) {
    ml(3, 3) = ml(9, 9) = 140.0 * m * polar;
    ml(3, 9) = ml(9, 3) = 70.0 * m * polar;
  }
  for (int d = 1; d < Ndm; ++d) {
    // translation d and the rotation that bends with it: rz for v; ry for w (3D)
    const int r = Ndm == 2 ? 2 : (d == 1 ? 5 : 4);
    const double s = d == 1 ? 1.0 : -1.0;
    ml(d, d) = ml(d + n, d + n) = 156.0 * m;
    ml(d, d + n) = ml(d + n, d) = 54.0 * m;
    ml(r, r) = ml(r + n, r + n) = 4.0 * l * l * m;
    ml(r, r + n) = ml(r + n, r) = -3.0 * l * l * m;
    ml(d, r) = ml(r, d) = s * 22.0 * l * m;
    ml(d + n, r + n) = ml(r + n, d + n) = -s * 22.0 * l * m;
    ml(d, r + n) = ml(r + n, d) = -s * 13.0 * l * m;
    ml(r, d + n) = ml(d + n, r) = s * 13.0 * l * m;
  }
  return ml;
}

}  // namespace dabs::elements
