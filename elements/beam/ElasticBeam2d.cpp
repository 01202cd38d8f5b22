// SPDX-License-Identifier: MIT
#include "elements/beam/ElasticBeam2d.h"

#include <cassert>
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
    : FixedSizeElement(tag, {nodeI, nodeJ}), params_(params), transf_(std::move(transf)) {
  assert(transf_);
}

void ElasticBeam2d::initialize(const NodalCoordinates& x) {
  if (x.size() != 2) throw InputError("element", "elasticBeamColumn needs 2 nodes");
  transf_->initialize(x[0], x[1]);
  const double length = transf_->initialLength();
  const double ei = params_.modulus * params_.inertiaZ / length;
  kb_.setZero();
  kb_(0, 0) = params_.modulus * params_.area / length;
  kb_(1, 1) = kb_(2, 2) = 4.0 * ei;
  kb_(1, 2) = kb_(2, 1) = 2.0 * ei;
  k0_ = transf_->initialGlobalStiffness(kb_);
  // Linear and PDelta transformations have a constant B, so B^T kb B is formed here once and an
  // update only adds the geometric part (nothing for Linear).
  constantCompat_ = transf_->hasConstantCompatibility();
  k_ = k0_;

  m_.setZero();
  const double mass = params_.massPerLength * length;
  if (mass > 0.0 && !params_.consistentMass) {
    for (int d : {0, 1, 3, 4}) m_(d, d) = 0.5 * mass;
  } else if (mass > 0.0) {
    m_ = transf_->globalFromLocal(consistentMass2d(mass, length));
  }
  uTrial_.setZero();
  uCommitted_.setZero();
  formState(uTrial_);
}

void ElasticBeam2d::formState(const Vector& u) {
  transf_->update(u);
  q_ = kb_ * transf_->basicDeformation();
  f_ = transf_->globalForce(q_);
  if (!constantCompat_) {
    k_ = transf_->globalStiffness(kb_, q_);
  } else if (!transf_->isLinear()) {
    k_ = k0_;
    transf_->addGeometricStiffness(k_, q_);
  }
}

Status ElasticBeam2d::update(const Kinematics& trial) {
  uTrial_ = trial.u;
  formState(uTrial_);
  return f_.allFinite() ? Status::Ok : Status::NonFinite;
}

void ElasticBeam2d::commitState() {
  transf_->commitState();
  uCommitted_ = uTrial_;
}

void ElasticBeam2d::revertToLastCommit() {
  transf_->revertToLastCommit();
  uTrial_ = uCommitted_;
  formState(uTrial_);
}

void ElasticBeam2d::revertToStart() {
  transf_->revertToStart();
  uTrial_.setZero();
  uCommitted_.setZero();
  formState(uTrial_);
}

std::optional<Eigen::VectorXd> ElasticBeam2d::response(std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
    return Eigen::VectorXd(f_);
  if (name == "localForce" || name == "localForces") return Eigen::VectorXd(transf_->localForce(q_));
  if (name == "basicForce" || name == "basicForces") return Eigen::VectorXd(q_);
  if (name == "deformations" || name == "basicDeformation" || name == "basicDeformations")
    return Eigen::VectorXd(transf_->basicDeformation());
  return std::nullopt;
}

std::string ElasticBeam2d::describe() const {
  std::ostringstream s;
  s << "ElasticBeam2d " << tag() << ": nodes " << nodes_[0] << " " << nodes_[1]
    << ", A " << params_.area << ", E " << params_.modulus << ", Iz " << params_.inertiaZ
    << ", geomTransf " << transf_->typeName() << " " << transf_->tag()
    << ", mass/length " << params_.massPerLength << (params_.consistentMass ? " (consistent)" : "")
    << ", basic forces " << q_.transpose();
  return s.str();
}

}  // namespace dabs::elements
