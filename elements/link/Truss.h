// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "elements/DynamicSizeElement.h"
#include "materials/UniaxialMaterial.h"

namespace dabs::elements {

/// Two-node truss with a uniaxial material (`element truss tag i j A matTag ?-rho rho? ?-cMass 0|1?
/// ?-doRayleigh 0|1?`; a truss on a section's axial response has A = 1 and a
/// SectionAxialMaterial). Small displacements: strain = c . (u_j - u_i) / L, axial force A sigma
/// (OpenSees/OpenSees:SRC/element/truss/Truss.cpp). Corotational (`element corotTruss`, large
/// displacements; Crisfield 1991, Non-linear Finite Element Analysis of Solids and Structures,
/// vol. 1, section 3.3): strain = (l - L) / L with the deformed length l, force N n along the
/// deformed axis n, tangent (A E_t / L) n n^T + (N / l)(I - n n^T)
/// (OpenSees/OpenSees:SRC/element/truss/CorotTruss.cpp). Mass rho L/2 per translation (lumped)
/// or rho L/6 [2 1; 1 2] (consistent).
class Truss final : public DynamicSizeElement {
 public:
  struct Params {
    std::vector<int> nodes;
    int ndm = 3;
    int ndf = 3;
    double area = 0.0;
    double rho = 0.0;  ///< mass per unit length
    bool consistentMass = false;
    bool doRayleigh = false;
    bool corotational = false;  ///< corotTruss: large displacements
    void validate() const;
  };

  Truss(int tag, Params params, std::unique_ptr<materials::UniaxialMaterial> material);

  std::string_view typeName() const override {
    return params_.corotational ? "corotTruss" : "truss";
  }
  void initialize(const NodalCoordinates& x) override;
  Status update(const Kinematics& trial) override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

 private:
  void assemble();
  /// Corotational geometry from the end displacement difference du = u_j - u_i (first ndm
  /// components): deformed axis vector, and b_ = d(strain)/d(u).
  void setDeformedAxis(const Eigen::Vector3d& du);
  Params params_;
  std::unique_ptr<materials::UniaxialMaterial> material_;
  double length_ = 0.0;
  Eigen::Vector3d axis0_ = Eigen::Vector3d::Zero();        ///< x_j - x_i (undeformed)
  Eigen::Vector3d axis_ = Eigen::Vector3d::Zero();         ///< deformed x_j - x_i (corotational)
  Eigen::Vector3d duCommitted_ = Eigen::Vector3d::Zero();  ///< u_j - u_i at the last commit
  Eigen::Vector3d duTrial_ = Eigen::Vector3d::Zero();
  Eigen::VectorXd b_;  ///< d(strain)/d(u)
};

}  // namespace dabs::elements
