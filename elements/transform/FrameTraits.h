// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

namespace dabs::elements {

// How planar and spatial frames share code (one scheme for elements/transform and
// elements/beam): a class that exists in 2D and 3D is ONE class template on the model dimension
// Ndm (2 or 3). Its sizes and matrix types come from FrameTraits<Ndm> below; what is the same in
// both dimensions is written once in the template; a difference of a few lines is an
// `if constexpr (Ndm == 3)` branch; a formulation that differs as a whole (the corotational
// kinematics) is an explicit specialisation of the same template. The 2D and 3D names
// (CrdTransf2d, LinearTransf3d, ...) are aliases of the instantiations, never copies.

template <int Ndm>
class CrdTransfNd;

/// Sizes and fixed-size matrix types of a two-node beam-column in an Ndm-dimensional model:
/// ndf 3 (ux uy rz) in 2D, 6 (ux uy uz rx ry rz) in 3D; as many basic forces as dofs per node
/// (2D: N M_i M_j; 3D: N Mz_i Mz_j My_i My_j T).
template <int Ndm>
struct FrameTraits {
  static_assert(Ndm == 2 || Ndm == 3, "beam-columns are planar (2) or spatial (3)");
  static constexpr int kDofPerNode = Ndm == 2 ? 3 : 6;
  static constexpr int kBasic = kDofPerNode;
  static constexpr int kGlobal = 2 * kDofPerNode;
  using Basic = Eigen::Matrix<double, kBasic, 1>;
  using BasicMatrix = Eigen::Matrix<double, kBasic, kBasic>;
  using Global = Eigen::Matrix<double, kGlobal, 1>;
  using GlobalMatrix = Eigen::Matrix<double, kGlobal, kGlobal>;
  using Compat = Eigen::Matrix<double, kBasic, kGlobal>;
  /// Local axes as the rows of a rotation matrix (global components).
  using Axes = Eigen::Matrix<double, Ndm, Ndm>;
  using Transf = CrdTransfNd<Ndm>;
};

}  // namespace dabs::elements
