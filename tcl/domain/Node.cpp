// SPDX-License-Identifier: MIT
#include "tcl/domain/Node.h"

namespace dabs::domain {

Node::Node(int tag, int ndm, int ndf, const Eigen::Vector3d& coords)
    : disp(Eigen::VectorXd::Zero(ndf)),
      vel(Eigen::VectorXd::Zero(ndf)),
      accel(Eigen::VectorXd::Zero(ndf)),
      committedDisp(Eigen::VectorXd::Zero(ndf)),
      committedVel(Eigen::VectorXd::Zero(ndf)),
      committedAccel(Eigen::VectorXd::Zero(ndf)),
      reaction(Eigen::VectorXd::Zero(ndf)),
      tag_(tag),
      ndm_(ndm),
      ndf_(ndf),
      coords_(coords),
      mass_(Eigen::MatrixXd::Zero(ndf, ndf)) {}

void Node::commitState() {
  committedDisp = disp;
  committedVel = vel;
  committedAccel = accel;
}

void Node::revertToLastCommit() {
  disp = committedDisp;
  vel = committedVel;
  accel = committedAccel;
}

void Node::revertToStart() {
  disp.setZero();
  vel.setZero();
  accel.setZero();
  commitState();
  reaction.setZero();
}

}  // namespace dabs::domain
