// SPDX-License-Identifier: MIT
#include "elements/beam/ElasticBeam2d.h"

#include <sstream>

#include "elements/beam/ConsistentMass.h"
#include "materials/InputError.h"

namespace dabs::elements {

void ElasticBeam2dParams::validate() const {
  if (!(area > 0.0)) throw InputError("A", "must be positive");
  if (!(modulus > 0.0)) throw InputError("E", "must be positive");
  if (!(inertiaZ > 0.0)) throw InputError("Iz", "must be positive");
  if (!(massPerLength >= 0.0)) throw InputError("-mass", "must be zero or positive");
}

ElasticBeam2d::ElasticBeam2d(int tag, int nodeI, int nodeJ, const Params& params,
                             std::unique_ptr<CrdTransf2d> transf)
    : ElasticBeamColumn(tag, nodeI, nodeJ, std::move(transf)), params_(params) {}

void ElasticBeam2d::initialize(const NodalCoordinates& x) {
  if (x.size() != 2) throw InputError("element", "elasticBeamColumn needs 2 nodes");
  transf_->initialize(x[0], x[1]);
  const double length = transf_->initialLength();
  const double ei = params_.modulus * params_.inertiaZ / length;
  kb_.setZero();
  kb_(0, 0) = params_.modulus * params_.area / length;
  kb_(1, 1) = kb_(2, 2) = 4.0 * ei;
  kb_(1, 2) = kb_(2, 1) = 2.0 * ei;
  initializeStiffness();

  m_.setZero();
  const double mass = params_.massPerLength * length;
  if (mass > 0.0 && !params_.consistentMass) {
    for (int d : {0, 1, 3, 4}) m_(d, d) = 0.5 * mass;
  } else if (mass > 0.0) {
    m_ = transf_->globalFromLocal(consistentMass<2>(mass, length));
  }
  resetState();
}

std::string ElasticBeam2d::describe() const {
  std::ostringstream s;
  s << "ElasticBeam2d " << tag() << ": nodes " << nodes_[0] << " " << nodes_[1] << ", A "
    << params_.area << ", E " << params_.modulus << ", Iz " << params_.inertiaZ << ", geomTransf "
    << transf_->typeName() << " " << transf_->tag() << ", mass/length " << params_.massPerLength
    << (params_.consistentMass ? " (consistent)" : "") << ", basic forces "
    << basicForce().transpose();
  return s.str();
}

}  // namespace dabs::elements
