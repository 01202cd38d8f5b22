// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "elements/beam/ElasticBeamColumn.h"
#include "elements/transform/CrdTransf2d.h"

namespace dabs::elements {

/// Parameters of `element elasticBeamColumn tag i j A E Iz transfTag ?-mass m? ?-cMass?` (2D).
struct ElasticBeam2dParams {
  double area = 0.0;            ///< A
  double modulus = 0.0;         ///< E
  double inertiaZ = 0.0;        ///< Iz
  double massPerLength = 0.0;   ///< -mass: mass per unit length
  bool consistentMass = false;  ///< -cMass: consistent instead of lumped mass
  /// Throws InputError unless A, E, Iz > 0 and mass >= 0.
  void validate() const;
};

/// Linear-elastic Euler-Bernoulli beam-column in a plane (OpenSees/OpenSees:SRC/element/
/// elasticBeamColumn/ElasticBeam2d.cpp): basic stiffness kb = diag(EA/L, EI/L [4 2; 2 4]) with the
/// undeformed length L, mapped by any 2D transformation (Linear, PDelta, Corotational).
/// Mass: lumped m L/2 on each node's translations (no rotational mass), or with -cMass the cubic
/// consistent mass (Przemieniecki 1968, Theory of Matrix Structural Analysis, eq. 11.23).
class ElasticBeam2d final : public ElasticBeamColumn<2> {
 public:
  using Params = ElasticBeam2dParams;
  ElasticBeam2d(int tag, int nodeI, int nodeJ, const Params& params,
                std::unique_ptr<CrdTransf2d> transf);

  void initialize(const NodalCoordinates& x) override;
  std::string describe() const override;

 private:
  Params params_;
};

}  // namespace dabs::elements
