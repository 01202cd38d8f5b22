// SPDX-License-Identifier: MIT
#include "elements/link/Truss.h"

#include <string>

#include "materials/InputError.h"
#include "materials/ResponseArgs.h"

namespace dabs::elements {

void Truss::Params::validate() const {
  if (nodes.size() != 2) throw InputError("nodes", "needs two nodes");
  if (!(area > 0.0)) throw InputError("A", "must be positive");
  if (rho < 0.0) throw InputError("-rho", "must not be negative");
  if (ndm < 1 || ndm > 3) throw InputError("ndm", "must be 1, 2 or 3");
  if (ndf < ndm)
    throw InputError("nodes", "need at least " + std::to_string(ndm) + " dofs for a truss in " +
                                  std::to_string(ndm) + "D");
}

Truss::Truss(int tag, Params params, std::unique_ptr<materials::UniaxialMaterial> material)
    : DynamicSizeElement(tag, params.nodes, params.ndf, params.doRayleigh),
      params_(std::move(params)),
      material_(std::move(material)) {
  b_ = Eigen::VectorXd::Zero(numDof());
}

void Truss::initialize(const NodalCoordinates& x) {
  const Eigen::Vector3d d = x[1] - x[0];
  length_ = d.norm();
  if (length_ == 0.0) throw InputError("nodes", "coincide: a truss needs a length");
  axis0_ = d;
  duTrial_.setZero();
  duCommitted_.setZero();
  setDeformedAxis(duTrial_);
  const int ndf = params_.ndf;
  const double totalMass = params_.rho * length_;
  m_.setZero();
  for (int i = 0; i < params_.ndm; ++i) {
    if (params_.consistentMass) {
      m_(i, i) = m_(ndf + i, ndf + i) = totalMass / 3.0;
      m_(i, ndf + i) = m_(ndf + i, i) = totalMass / 6.0;
    } else {
      m_(i, i) = m_(ndf + i, ndf + i) = totalMass / 2.0;
    }
  }
  const double ea = params_.area * length_;  // K = A L E b b^T since b carries 1/L
  k0_ = (ea * material_->getInitialTangent()) * b_ * b_.transpose();
  assemble();
  kc_ = k_;
}

void Truss::setDeformedAxis(const Eigen::Vector3d& du) {
  axis_ = axis0_ + du;
  const double l = axis_.norm();
  const Eigen::Vector3d n = axis_ / l;
  const int ndf = params_.ndf;
  b_.setZero();
  for (int i = 0; i < params_.ndm; ++i) {
    b_(i) = -n(i) / length_;
    b_(ndf + i) = n(i) / length_;
  }
}

void Truss::assemble() {
  const double al = params_.area * length_;
  f_ = (al * material_->getStress()) * b_;
  k_ = (al * material_->getTangent()) * b_ * b_.transpose();
  c_ = (al * material_->getDampTangent()) * b_ * b_.transpose();
  if (!params_.corotational) return;
  // Geometric stiffness of the axial force N turning with the axis: (N / l)(I - n n^T) on the
  // end displacement difference (Crisfield 1991, eq. 3.21).
  const double l = axis_.norm();
  const double nForce = params_.area * material_->getStress();
  const Eigen::Vector3d n = axis_ / l;
  const int ndm = params_.ndm, ndf = params_.ndf;
  const Eigen::MatrixXd kg =
      (nForce / l) * (Eigen::MatrixXd::Identity(ndm, ndm) - n.head(ndm) * n.head(ndm).transpose());
  k_.block(0, 0, ndm, ndm) += kg;
  k_.block(ndf, ndf, ndm, ndm) += kg;
  k_.block(0, ndf, ndm, ndm) -= kg;
  k_.block(ndf, 0, ndm, ndm) -= kg;
}

Status Truss::update(const Kinematics& trial) {
  if (!params_.corotational) {
    const Status s = material_->setTrialStrain(b_.dot(trial.u), b_.dot(trial.v));
    if (!ok(s)) return s;
    assemble();
    return Status::Ok;
  }
  const int ndm = params_.ndm, ndf = params_.ndf;
  Eigen::Vector3d du = Eigen::Vector3d::Zero(), dv = Eigen::Vector3d::Zero();
  for (int i = 0; i < ndm; ++i) {
    du(i) = trial.u(ndf + i) - trial.u(i);
    dv(i) = trial.v(ndf + i) - trial.v(i);
  }
  duTrial_ = du;
  setDeformedAxis(du);
  const double l = axis_.norm();
  const double strain = (l - length_) / length_;
  const double rate = axis_.dot(dv) / (l * length_);
  const Status s = material_->setTrialStrain(strain, rate);
  if (!ok(s)) return s;
  assemble();
  return f_.allFinite() ? Status::Ok : Status::NonFinite;
}

void Truss::commitState() {
  material_->commitState();
  duCommitted_ = duTrial_;
  kc_ = k_;
}

void Truss::revertToLastCommit() {
  material_->revertToLastCommit();
  duTrial_ = duCommitted_;
  if (params_.corotational) setDeformedAxis(duTrial_);
  assemble();
}

void Truss::revertToStart() {
  material_->revertToStart();
  duTrial_.setZero();
  duCommitted_.setZero();
  setDeformedAxis(duTrial_);
  assemble();
  kc_ = k_;
}

std::optional<Eigen::VectorXd> Truss::response(std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  const double axial = params_.area * material_->getStress();
  if (name == "material" && args.size() == 2) {
    if (args[1] == "stress") return Eigen::VectorXd::Constant(1, material_->getStress());
    if (args[1] == "strain") return Eigen::VectorXd::Constant(1, material_->getStrain());
    if (args[1] == "stressStrain") {
      Eigen::VectorXd out(2);
      out << material_->getStress(), material_->getStrain();
      return out;
    }
    return std::nullopt;
  }
  if (args.size() != 1) return std::nullopt;
  if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
    return Eigen::VectorXd(f_);
  if (name == "axialForce" || name == "basicForce" || name == "basicForces")
    return Eigen::VectorXd::Constant(1, axial);
  if (name == "localForce" || name == "localForces") {
    Eigen::VectorXd out = Eigen::VectorXd::Zero(numDof());
    out(0) = -axial;
    out(params_.ndf) = axial;
    return out;
  }
  if (name == "deformation" || name == "deformations" || name == "basicDeformation" ||
      name == "basicDeformations")
    return Eigen::VectorXd::Constant(1, length_ * material_->getStrain());
  return std::nullopt;
}

}  // namespace dabs::elements
