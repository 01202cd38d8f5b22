// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>

namespace dabs::domain {

/// A node: coordinates, lumped (or full nodal) mass, and its trial and committed response.
/// Displacements are total values in the global frame, one entry per dof (1..ndf in order).
class Node {
 public:
  /// `coords` is padded to 3D; `ndm` is the model dimension the node was created in.
  Node(int tag, int ndm, int ndf, const Eigen::Vector3d& coords);

  int tag() const noexcept { return tag_; }
  int ndm() const noexcept { return ndm_; }
  int ndf() const noexcept { return ndf_; }
  /// Coordinates, padded to 3D with zeros.
  const Eigen::Vector3d& coords() const noexcept { return coords_; }
  /// Nodal mass matrix (ndf x ndf), diagonal when given by `node -mass` or `mass`.
  const Eigen::MatrixXd& mass() const noexcept { return mass_; }
  void setMass(const Eigen::MatrixXd& m) { mass_ = m; }

  /// Trial response (what Newton iterations change).
  Eigen::VectorXd disp, vel, accel;
  /// Committed response (last converged step).
  Eigen::VectorXd committedDisp, committedVel, committedAccel;
  /// Reaction (support force incl. inertia and damping, as OpenSees' `reactions` computes it).
  Eigen::VectorXd reaction;
  /// Eigenvectors, one column per mode, after `eigen`.
  Eigen::MatrixXd eigenvectors;

  void commitState();
  void revertToLastCommit();
  void revertToStart();

 private:
  int tag_;
  int ndm_;
  int ndf_;
  Eigen::Vector3d coords_;
  Eigen::MatrixXd mass_;
};

}  // namespace dabs::domain
