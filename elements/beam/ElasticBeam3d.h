// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/FixedSizeElement.h"
#include "elements/transform/CrdTransf3d.h"

namespace dabs::elements {

/// Parameters of `element elasticBeamColumn tag i j A E G J Iy Iz transfTag ?-mass m? ?-cMass?`.
struct ElasticBeam3dParams {
  double area = 0.0;            ///< A
  double modulus = 0.0;         ///< E
  double shearModulus = 0.0;    ///< G
  double torsion = 0.0;         ///< J (torsional constant)
  double inertiaY = 0.0;        ///< Iy (bending about local y)
  double inertiaZ = 0.0;        ///< Iz (bending about local z)
  double massPerLength = 0.0;   ///< -mass: mass per unit length
  bool consistentMass = false;  ///< -cMass
  /// Throws InputError unless A, E, G, J, Iy, Iz > 0 and mass >= 0.
  void validate() const;
};

/// Linear-elastic Euler-Bernoulli beam-column in space (OpenSees/OpenSees:SRC/element/
/// elasticBeamColumn/ElasticBeam3d.cpp): kb = diag(EA/L, EIz/L [4 2; 2 4], EIy/L [4 2; 2 4], GJ/L)
/// with the undeformed length L, mapped by any 3D transformation. Mass: lumped m L/2 on each
/// node's translations (no rotational mass), or with -cMass the cubic consistent mass plus a
/// linear torsional (polar) mass with rho J/A per length, as OpenSees ElasticBeam3d.
class ElasticBeam3d final : public FixedSizeElement<2, 6> {
 public:
  using Params = ElasticBeam3dParams;
  ElasticBeam3d(int tag, int nodeI, int nodeJ, const Params& params,
                std::unique_ptr<CrdTransf3d> transf);

  std::string_view typeName() const override { return "elasticBeamColumn"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  bool isLinear() const override { return transf_->isLinear(); }
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::string describe() const override;

  /// Basic forces [N, Mz_i, Mz_j, My_i, My_j, T] at the last update.
  const CrdTransf3d::Basic& basicForce() const noexcept { return q_; }
  const CrdTransf3d& transformation() const noexcept { return *transf_; }

 private:
  void formState(const Vector& u);

  Params params_;
  std::unique_ptr<CrdTransf3d> transf_;
  CrdTransf3d::BasicMatrix kb_ = CrdTransf3d::BasicMatrix::Zero();
  CrdTransf3d::Basic q_ = CrdTransf3d::Basic::Zero();
  bool constantCompat_ = false;  ///< B constant: k_ = k0_ + geometric part
  Vector uTrial_ = Vector::Zero();
  Vector uCommitted_ = Vector::Zero();
};

}  // namespace dabs::elements
