// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

namespace dabs::elements {

/// Local consistent mass of a straight beam of mass `mass` and length `length` (Przemieniecki
/// 1968, Theory of Matrix Structural Analysis, eq. 11.42): linear axial, cubic Hermitian
/// transverse; dofs [u v rz]_i [u v rz]_j.
inline Eigen::Matrix<double, 6, 6> consistentMass2d(double mass, double length) {
  Eigen::Matrix<double, 6, 6> ml = Eigen::Matrix<double, 6, 6>::Zero();
  const double m = mass / 420.0, l = length;
  ml(0, 0) = ml(3, 3) = 140.0 * m;
  ml(0, 3) = ml(3, 0) = 70.0 * m;
  ml(1, 1) = ml(4, 4) = 156.0 * m;
  ml(1, 4) = ml(4, 1) = 54.0 * m;
  ml(2, 2) = ml(5, 5) = 4.0 * l * l * m;
  ml(2, 5) = ml(5, 2) = -3.0 * l * l * m;
  ml(1, 2) = ml(2, 1) = 22.0 * l * m;
  ml(4, 5) = ml(5, 4) = -22.0 * l * m;
  ml(1, 5) = ml(5, 1) = -13.0 * l * m;
  ml(2, 4) = ml(4, 2) = 13.0 * l * m;
  return ml;
}

/// 3D version, dofs [u v w rx ry rz]_i [..]_j; `polar` = J/A gives a linear torsional (polar)
/// mass (0: none). In the x-z plane ry = -dw/dx flips the sign of the coupling terms.
inline Eigen::Matrix<double, 12, 12> consistentMass3d(double mass, double length, double polar) {
  Eigen::Matrix<double, 12, 12> ml = Eigen::Matrix<double, 12, 12>::Zero();
  const double m = mass / 420.0, l = length;
  ml(0, 0) = ml(6, 6) = 140.0 * m;
  ml(0, 6) = ml(6, 0) = 70.0 * m;
  ml(3, 3) = ml(9, 9) = 140.0 * m * polar;
  ml(3, 9) = ml(9, 3) = 70.0 * m * polar;
  for (int d : {1, 2}) {
    const int r = d == 1 ? 5 : 4;
    const double s = d == 1 ? 1.0 : -1.0;
    ml(d, d) = ml(d + 6, d + 6) = 156.0 * m;
    ml(d, d + 6) = ml(d + 6, d) = 54.0 * m;
    ml(r, r) = ml(r + 6, r + 6) = 4.0 * l * l * m;
    ml(r, r + 6) = ml(r + 6, r) = -3.0 * l * l * m;
    ml(d, r) = ml(r, d) = s * 22.0 * l * m;
    ml(d + 6, r + 6) = ml(r + 6, d + 6) = -s * 22.0 * l * m;
    ml(d, r + 6) = ml(r + 6, d) = -s * 13.0 * l * m;
    ml(r, d + 6) = ml(d + 6, r) = s * 13.0 * l * m;
  }
  return ml;
}

}  // namespace dabs::elements
