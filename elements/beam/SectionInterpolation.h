// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <span>

#include "materials/section/SectionForceDeformation.h"

namespace dabs::elements {

/// Largest section order handled (P, Mz, Vy, My, Vz, T).
inline constexpr int kMaxSectionOrder = 6;
using SectionVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxSectionOrder, 1>;
using SectionMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSectionOrder, kMaxSectionOrder>;
template <int Nb>
using SectionBasicMatrix = Eigen::Matrix<double, Eigen::Dynamic, Nb, 0, kMaxSectionOrder, Nb>;

/// Force interpolation b(xi): section resultants s = b q from basic forces q (equilibrium of the
/// simply supported basic system; Spacone, Filippou & Taucer 1996, eq. 8). Throws InputError for
/// resultants the dimension does not have.
template <int Nb>
SectionBasicMatrix<Nb> forceInterpolation(std::span<const materials::section::SectionCode> codes,
                                          double xi, double length);

/// Displacement interpolation B(xi): section deformations e = B v from basic deformations v
/// (linear axial and twist, cubic Hermitian transverse displacement; curvature
/// ((6xi - 4) v_i + (6xi - 2) v_j) / L). Throws InputError for shear resultants.
template <int Nb>
SectionBasicMatrix<Nb> deformationInterpolation(
    std::span<const materials::section::SectionCode> codes, double xi, double length);

}  // namespace dabs::elements
