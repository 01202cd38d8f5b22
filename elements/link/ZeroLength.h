// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "elements/DynamicSizeElement.h"
#include "materials/UniaxialMaterial.h"

namespace dabs::elements {

/// Zero-length element (`element zeroLength tag i j -mat m.. -dir d.. ?-orient x1 x2 x3 yp1 yp2
/// yp3? ?-doRayleigh 0|1?`): uniaxial materials acting on the relative displacement of two nodes
/// along local axes (dirs 1-3) or about them (dirs 4-6). Local x is given by -orient, y lies in
/// the plane of x and yp, z = x cross yp (OpenSees/OpenSees:SRC/element/zeroLength/ZeroLength.cpp).
/// Deformation e_k = t_k . u with t_k = [-a_k, a_k] over the chosen dofs of nodes i and j.
class ZeroLength final : public DynamicSizeElement {
 public:
  struct Params {
    std::vector<int> nodes;  ///< i, j
    int ndm = 3;
    int ndf = 6;
    std::vector<int> dirs;  ///< 1..6 as in the command
    Eigen::Vector3d x{1.0, 0.0, 0.0};
    Eigen::Vector3d yp{0.0, 1.0, 0.0};
    bool doRayleigh = false;
    /// Throws InputError for dirs the model's ndm/ndf cannot carry or a degenerate orientation.
    void validate(std::size_t numMaterials) const;
  };

  ZeroLength(int tag, Params params,
             std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats);

  std::string_view typeName() const override { return "zeroLength"; }
  void initialize(const NodalCoordinates& x) override;
  Status update(const Kinematics& trial) override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::span<const int> matrixSupport() const override { return touchedMatrix_; }
  /// After an update, when every material keeps its state at the same strain
  /// (UniaxialMaterial::keepsStateAtSameStrain: Steel01/02, Concrete01/02, Elastic without
  /// damping): the deformations are then a fixed projection of the displacements, and an update
  /// at the same ones (a transient step's predictor) would leave the state as it is.
  bool keepsStateAtSameDisplacements() const override { return stateCurrent_ && keepsState_; }

 private:
  void assemble();
  Params params_;
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> materials_;
  Eigen::MatrixXd t_;                      ///< one row per material: d(deformation)/d(u)
  std::vector<std::vector<int>> nonzero_;  ///< per material: the dofs its row of t_ touches
  /// The entries of f_ and (column-major) of k_ and c_ that some material's row reaches: the
  /// only ones an update rewrites; the rest stay zero from initialize().
  std::vector<int> touchedForce_, touchedMatrix_;
  bool keepsState_ = false;    ///< every material keeps its state at the same strain
  bool stateCurrent_ = false;  ///< the state is the one the last update formed
};

}  // namespace dabs::elements
