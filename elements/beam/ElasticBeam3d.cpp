// SPDX-License-Identifier: MIT
#include "elements/beam/ElasticBeam3d.h"

#include <sstream>

#include "elements/beam/ConsistentMass.h"
#include "materials/InputError.h"

namespace dabs::elements {

void ElasticBeam3dParams::validate() const {
  if (!(area > 0.0)) throw InputError("A", "must be positive");
  if (!(modulus > 0.0)) throw InputError("E", "must be positive");
  if (!(shearModulus > 0.0)) throw InputError("G", "must be positive");
  if (!(torsion > 0.0)) throw InputError("J", "must be positive");
  if (!(inertiaY > 0.0)) throw InputError("Iy", "must be positive");
  if (!(inertiaZ > 0.0)) throw InputError("Iz", "must be positive");
  if (!(massPerLength >= 0.0)) throw InputError("-mass", "must be zero or positive");
}

ElasticBeam3d::ElasticBeam3d(int tag, int nodeI, int nodeJ, const Params& params,
                             std::unique_ptr<CrdTransf3d> transf)
    : ElasticBeamColumn(tag, nodeI, nodeJ, std::move(transf)), params_(params) {}

void ElasticBeam3d::initialize(const NodalCoordinates& x) {
  if (x.size() != 2) throw InputError("element", "elasticBeamColumn needs 2 nodes");
  transf_->initialize(x[0], x[1]);
  const double length = transf_->initialLength();
  const double e = params_.modulus / length;
  kb_.setZero();
  kb_(0, 0) = e * params_.area;
  kb_(1, 1) = kb_(2, 2) = 4.0 * e * params_.inertiaZ;
  kb_(1, 2) = kb_(2, 1) = 2.0 * e * params_.inertiaZ;
  kb_(3, 3) = kb_(4, 4) = 4.0 * e * params_.inertiaY;
  kb_(3, 4) = kb_(4, 3) = 2.0 * e * params_.inertiaY;
  kb_(5, 5) = params_.shearModulus * params_.torsion / length;
  initializeStiffness();

  m_.setZero();
  const double mass = params_.massPerLength * length;
  if (mass > 0.0 && !params_.consistentMass) {
    for (int d : {0, 1, 2, 6, 7, 8}) m_(d, d) = 0.5 * mass;
  } else if (mass > 0.0) {
    m_ = transf_->globalFromLocal(consistentMass<3>(mass, length, params_.torsion / params_.area));
  }
  resetState();
}

std::string ElasticBeam3d::describe() const {
  std::ostringstream s;
  s << "ElasticBeam3d " << tag() << ": nodes " << nodes_[0] << " " << nodes_[1] << ", A "
    << params_.area << ", E " << params_.modulus << ", G " << params_.shearModulus << ", J "
    << params_.torsion << ", Iy " << params_.inertiaY << ", Iz " << params_.inertiaZ
    << ", geomTransf " << transf_->typeName() << " " << transf_->tag() << ", mass/length "
    << params_.massPerLength << (params_.consistentMass ? " (consistent)" : "") << ", basic forces "
    << basicForce().transpose();
  return s.str();
}

}  // namespace dabs::elements
