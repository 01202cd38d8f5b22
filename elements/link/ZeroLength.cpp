// SPDX-License-Identifier: MIT
#include "elements/link/ZeroLength.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>

#include "materials/InputError.h"
#include "materials/ResponseArgs.h"

namespace dabs::elements {

namespace {
constexpr double kParallelTolerance = 1e-12;  // |x cross yp| below this: axes undefined
}

void ZeroLength::Params::validate(std::size_t numMaterials) const {
  if (nodes.size() != 2) throw InputError("nodes", "needs two nodes");
  if (dirs.empty()) throw InputError("-dir", "needs at least one direction");
  if (dirs.size() != numMaterials)
    throw InputError("-dir", "needs one direction per material (" + std::to_string(numMaterials) +
                                 " materials, " + std::to_string(dirs.size()) + " directions)");
  // Directions a (ndm, ndf) model can carry (OpenSees ZeroLength::setUp).
  int maxDir = 0;
  if (ndm == 1 && ndf == 1)
    maxDir = 1;
  else if (ndm == 2 && ndf == 2)
    maxDir = 2;
  else if (ndm == 2 && ndf == 3)
    maxDir = 3;
  else if (ndm == 3 && ndf == 3)
    maxDir = 3;
  else if (ndm == 3 && ndf == 6)
    maxDir = 6;
  else
    throw InputError(
        "nodes", "have " + std::to_string(ndf) + " dofs, which zeroLength does not support in " +
                     std::to_string(ndm) + "D (use ndf 1 in 1D, 2 or 3 in 2D, 3 or 6 in 3D)");
  for (int d : dirs)
    if (d < 1 || d > maxDir)
      throw InputError("-dir", std::to_string(d) + " is outside 1.." + std::to_string(maxDir) +
                                   " for a " + std::to_string(ndm) + "D model with " +
                                   std::to_string(ndf) + " dofs per node");
  if (x.norm() == 0.0) throw InputError("-orient", "x axis has zero length");
  if (x.cross(yp).norm() <= kParallelTolerance * x.norm() * yp.norm())
    throw InputError("-orient", "yp is parallel to x");
}

ZeroLength::ZeroLength(int tag, Params params,
                       std::vector<std::unique_ptr<materials::UniaxialMaterial>> mats)
    : DynamicSizeElement(tag, params.nodes, params.ndf, params.doRayleigh),
      params_(std::move(params)),
      materials_(std::move(mats)) {
  t_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(materials_.size()), numDof());
  keepsState_ = std::all_of(materials_.begin(), materials_.end(),
                            [](const auto& m) { return m->keepsStateAtSameStrain(); });
}

void ZeroLength::initialize(const NodalCoordinates& /*x*/) {
  // Local axes: rows x, y, z with z = x cross yp and y = z cross x.
  const Eigen::Vector3d ex = params_.x.normalized();
  const Eigen::Vector3d ez = params_.x.cross(params_.yp).normalized();
  const Eigen::Vector3d ey = ez.cross(ex);
  const Eigen::Vector3d axes[3] = {ex, ey, ez};
  const int ndf = params_.ndf, ndm = params_.ndm;
  t_.setZero();
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    int dir = params_.dirs[k] - 1;
    if (ndm == 2 && ndf == 3 && dir == 2) dir = 5;  // 2D: dir 3 is the rotation about z
    const Eigen::Vector3d& a = axes[dir % 3];
    if (dir < 3) {
      for (int c = 0; c < ndm; ++c) {
        t_(row, c) = -a(c);
        t_(row, ndf + c) = a(c);
      }
    } else if (ndf == 6) {
      for (int c = 0; c < 3; ++c) {
        t_(row, 3 + c) = -a(c);
        t_(row, ndf + 3 + c) = a(c);
      }
    } else {  // 2D rotation dof
      t_(row, 2) = -a(2);
      t_(row, ndf + 2) = a(2);
    }
  }
  nonzero_.assign(materials_.size(), {});
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    for (int i = 0; i < numDof(); ++i)
      if (t_(row, i) != 0.0) nonzero_[k].push_back(i);
    k0_.noalias() += materials_[k]->getInitialTangent() * t_.row(row).transpose() * t_.row(row);
  }
  touchedForce_.clear();
  touchedMatrix_.clear();
  for (const auto& dofs : nonzero_)
    for (int i : dofs) {
      touchedForce_.push_back(i);
      for (int j : dofs) touchedMatrix_.push_back(i + j * numDof());
    }
  for (auto* list : {&touchedForce_, &touchedMatrix_}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  f_.setZero();
  k_.setZero();
  c_.setZero();
  assemble();
  kc_ = k_;
}

void ZeroLength::assemble() {
  // Clearing only the entries the rows reach: a gap or bearing spring touches 4 of the 144
  // entries of a 3D link's 12 x 12 matrices, and clearing all of k_ and c_ at every update was
  // 2.4 % of the 100-span benchmark bridge (perf).
  double* stiffness = k_.data();
  double* damping = c_.data();
  for (int i : touchedForce_) f_(i) = 0.0;
  for (int idx : touchedMatrix_) stiffness[idx] = damping[idx] = 0.0;
  // Each row of t touches at most 2 x 3 dofs: add only those entries.
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    const auto row = static_cast<Eigen::Index>(k);
    const auto& m = *materials_[k];
    const double stress = m.getStress(), tangent = m.getTangent(), eta = m.getDampTangent();
    for (int i : nonzero_[k]) {
      const double ti = t_(row, i);
      f_(i) += stress * ti;
      for (int j : nonzero_[k]) {
        k_(i, j) += tangent * ti * t_(row, j);
        if (eta != 0.0) c_(i, j) += eta * ti * t_(row, j);
      }
    }
  }
}

Status ZeroLength::update(const Kinematics& trial) {
  stateCurrent_ = false;
  for (std::size_t k = 0; k < materials_.size(); ++k) {
    const auto row = t_.row(static_cast<Eigen::Index>(k));
    const Status s = materials_[k]->setTrialStrain(row.dot(trial.u), row.dot(trial.v));
    if (!ok(s)) return s;
  }
  assemble();
  stateCurrent_ = true;
  return Status::Ok;
}

void ZeroLength::commitState() {
  for (auto& m : materials_) m->commitState();
  const double* trial = k_.data();
  double* committed = kc_.data();
  for (int idx : touchedMatrix_) committed[idx] = trial[idx];
}

void ZeroLength::revertToLastCommit() {
  for (auto& m : materials_) m->revertToLastCommit();
  assemble();
  stateCurrent_ = false;
}

void ZeroLength::revertToStart() {
  for (auto& m : materials_) m->revertToStart();
  assemble();
  kc_ = k_;
  stateCurrent_ = false;
}

std::optional<Eigen::VectorXd> ZeroLength::response(std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  const auto nm = static_cast<Eigen::Index>(materials_.size());
  if (name == "material") {
    // material i response: exactly three words, i a whole integer.
    const std::optional<int> k = args.size() == 3 ? responseInteger(args[1]) : std::nullopt;
    if (!k || *k < 1 || *k > static_cast<int>(nm)) return std::nullopt;
    const auto& m = *materials_[static_cast<std::size_t>(*k - 1)];
    if (args[2] == "stress") return Eigen::VectorXd::Constant(1, m.getStress());
    if (args[2] == "strain") return Eigen::VectorXd::Constant(1, m.getStrain());
    if (args[2] == "tangent") return Eigen::VectorXd::Constant(1, m.getTangent());
    if (args[2] == "stressStrain") {
      Eigen::VectorXd out(2);
      out << m.getStress(), m.getStrain();
      return out;
    }
    if (const auto r = m.response(args[2])) return Eigen::VectorXd::Constant(1, *r);
    return std::nullopt;
  }
  if (args.size() != 1) return std::nullopt;
  if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
    return Eigen::VectorXd(f_);
  if (name == "basicForce" || name == "basicForces" || name == "localForce" ||
      name == "localForces") {
    Eigen::VectorXd out(nm);
    for (Eigen::Index k = 0; k < nm; ++k)
      out(k) = materials_[static_cast<std::size_t>(k)]->getStress();
    return out;
  }
  if (name == "deformation" || name == "deformations" || name == "basicDeformation" ||
      name == "basicDeformations" || name == "defo") {
    Eigen::VectorXd out(nm);
    for (Eigen::Index k = 0; k < nm; ++k)
      out(k) = materials_[static_cast<std::size_t>(k)]->getStrain();
    return out;
  }
  if (name == "deformationsANDforces") {
    Eigen::VectorXd out(2 * nm);
    for (Eigen::Index k = 0; k < nm; ++k) {
      out(k) = materials_[static_cast<std::size_t>(k)]->getStrain();
      out(nm + k) = materials_[static_cast<std::size_t>(k)]->getStress();
    }
    return out;
  }
  return std::nullopt;
}

}  // namespace dabs::elements
