// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "elements/DynamicSizeElement.h"
#include "materials/UniaxialMaterial.h"

namespace dabs::elements {

/// Two-node truss with a uniaxial material, small displacements (`element truss tag i j A matTag
/// ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?`): strain = c . (u_j - u_i) / L, axial force A sigma,
/// mass rho L/2 per translation (lumped) or rho L/6 [2 1; 1 2] (consistent)
/// (OpenSees/OpenSees:SRC/element/truss/Truss.cpp).
class Truss final : public DynamicSizeElement {
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
  void initialize(const NodalCoordinates& x) override;
  Status update(const Kinematics& trial) override;
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
};

}  // namespace dabs::elements
