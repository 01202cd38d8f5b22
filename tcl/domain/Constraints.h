// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <vector>

namespace dabs::domain {

/// Single-point constraint: dof `dof` (0-based) of node `node` is prescribed. A `fix` is
/// homogeneous (value 0); patterns add scaled or imposed-motion constraints of their own.
struct SPConstraint {
  int node = 0;
  int dof = 0;
};

/// Multi-point constraint u_c = Ccr u_r between a constrained and a retained node (equalDOF,
/// rigidLink), with dofs 0-based. Ccr has one row per constrained dof and one column per retained
/// dof. Rigid links are linearised about the initial geometry, as in OpenSees' RigidBeam/RigidRod.
struct MPConstraint {
  int retainedNode = 0;
  int constrainedNode = 0;
  std::vector<int> constrainedDofs;
  std::vector<int> retainedDofs;
  Eigen::MatrixXd Ccr;
};

}  // namespace dabs::domain
