// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "materials/Status.h"

namespace dabs::analysis {

/// Lowest eigenpairs of K phi = lambda M phi with K symmetric positive definite and M symmetric
/// positive semi-definite (massless dofs allowed). Eigenvectors are mass-orthonormal
/// (phi^T M phi = I), as ARPACK's in OpenSees, with the sign fixed so that the largest component
/// is positive.
struct EigenResult {
  Status status = Status::Ok;
  Eigen::VectorXd values;   ///< ascending eigenvalues (omega^2)
  Eigen::MatrixXd vectors;  ///< one column per mode
};

/// Dense solution through the Cholesky factor of K (small systems, or `eigen -fullGenLapack`).
/// With `largest`, the numModes largest finite eigenvalues in ascending order (`eigen
/// -findLargest`; the finite ones are as many as the dofs with mass).
EigenResult solveEigenDense(const Eigen::SparseMatrix<double>& K,
                            const Eigen::SparseMatrix<double>& M, int numModes,
                            bool largest = false);
/// Subspace iteration with a sparse LDL^T of K (Bathe, Finite Element Procedures, sec. 11.6).
EigenResult solveEigenSubspace(const Eigen::SparseMatrix<double>& K,
                               const Eigen::SparseMatrix<double>& M, int numModes);

}  // namespace dabs::analysis
