// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/beam/ElasticBeamColumn.h"
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
class ElasticBeam3d final : public ElasticBeamColumn<3> {
 public:
  using Params = ElasticBeam3dParams;
  ElasticBeam3d(int tag, int nodeI, int nodeJ, const Params& params,
                std::unique_ptr<CrdTransf3d> transf);

  void initialize(const NodalCoordinates& x) override;
  std::string describe() const override;

 private:
  Params params_;
};

}  // namespace dabs::elements
