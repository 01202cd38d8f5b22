// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "elements/Element.h"
#include "materials/UniaxialMaterial.h"

namespace dabs::elements {

/// Two-node truss with a uniaxial material, small displacements (`element truss tag i j A matTag
/// ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?`): strain = c . (u_j - u_i) / L, axial force A sigma,
/// mass rho L/2 per translation (lumped) or rho L/6 [2 1; 1 2] (consistent)
/// (OpenSees/OpenSees:SRC/element/truss/Truss.cpp).
class Truss final : public Element {
 public:
  struct Params {
    std::vector<int> nodes;
    int ndm = 3;
    int ndf = 3;
    double area = 0.0;
    double rho = 0.0;        ///< mass per unit length
    bool consistentMass = false;
    bool doRayleigh = false;
    void validate() const;
  };

  Truss(int tag, Params params, std::unique_ptr<materials::UniaxialMaterial> material);

  std::string_view typeName() const override { return "truss"; }
  const std::vector<int>& nodeTags() const override { return params_.nodes; }
  int numDof() const override { return 2 * params_.ndf; }
  int dofPerNode() const override { return params_.ndf; }
  void initialize(const NodalCoordinates& x) override;
  Status update(const Kinematics& trial) override;
  Eigen::Ref<const Eigen::VectorXd> resistingForce() const override { return f_; }
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const override { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> initialStiff() const override { return k0_; }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return kc_; }
  Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const override { return c_; }
  Eigen::Ref<const Eigen::MatrixXd> mass() const override { return m_; }
  bool rayleighByDefault() const override { return params_.doRayleigh; }
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

 private:
  void assemble();
  Params params_;
  std::unique_ptr<materials::UniaxialMaterial> material_;
  double length_ = 0.0;
  Eigen::VectorXd b_;  ///< d(strain)/d(u)
  Eigen::VectorXd f_;
  Eigen::MatrixXd k_, k0_, kc_, c_, m_;
};

}  // namespace dabs::elements
