// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <vector>

#include "elements/Element.h"

namespace dabs::elements {

/// Base for elements whose size depends on the model's dofs per node (zeroLength, truss): owns the
/// force vector and the stiffness, damping and mass matrices, sized once at construction, and the
/// stiffness at the last commit for Rayleigh's betaKcomm. Counterpart of FixedSizeElement.
class DynamicSizeElement : public Element {
 public:
  DynamicSizeElement(int tag, std::vector<int> nodes, int dofPerNode, bool doRayleigh)
      : Element(tag), nodes_(std::move(nodes)), ndf_(dofPerNode), doRayleigh_(doRayleigh) {
    const int n = numDof();
    f_ = Eigen::VectorXd::Zero(n);
    k_ = k0_ = kc_ = c_ = m_ = Eigen::MatrixXd::Zero(n, n);
  }

  const std::vector<int>& nodeTags() const final { return nodes_; }
  int numDof() const final { return static_cast<int>(nodes_.size()) * ndf_; }
  int dofPerNode() const final { return ndf_; }
  Eigen::Ref<const Eigen::VectorXd> resistingForce() const final { return f_; }
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const final { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> initialStiff() const final { return k0_; }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const final { return kc_; }
  Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const final { return c_; }
  Eigen::Ref<const Eigen::MatrixXd> mass() const final { return m_; }
  /// OpenSees' -doRayleigh flag of zeroLength and truss (off by default).
  bool rayleighByDefault() const final { return doRayleigh_; }

 protected:
  std::vector<int> nodes_;
  int ndf_;
  bool doRayleigh_;
  Eigen::VectorXd f_;   ///< resisting force (global)
  Eigen::MatrixXd k_;   ///< tangent stiffness (global)
  Eigen::MatrixXd k0_;  ///< initial stiffness (global)
  Eigen::MatrixXd kc_;  ///< stiffness at the last commit
  Eigen::MatrixXd c_;   ///< material dashpots (global)
  Eigen::MatrixXd m_;   ///< mass (global)
};

}  // namespace dabs::elements
