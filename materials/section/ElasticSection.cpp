// SPDX-License-Identifier: MIT
#include "materials/section/ElasticSection.h"

#include "materials/InputError.h"

namespace dabs::materials::section {

void ElasticSectionParams::validate() const {
  if (ndm != 2 && ndm != 3) throw InputError("section Elastic", "needs a 2D or 3D model");
  if (!(modulus > 0.0)) throw InputError("E", "must be positive");
  if (!(area > 0.0)) throw InputError("A", "must be positive");
  if (!(inertiaZ > 0.0)) throw InputError("Iz", "must be positive");
  if (ndm == 3) {
    if (!(inertiaY > 0.0)) throw InputError("Iy", "must be positive");
    if (!(shearModulus > 0.0)) throw InputError("G", "must be positive");
    if (!(torsion > 0.0)) throw InputError("J", "must be positive");
  }
  if (!(alphaY >= 0.0)) throw InputError("alphaY", "must be zero or positive");
  if (!(alphaZ >= 0.0)) throw InputError("alphaZ", "must be zero or positive");
  if (ndm == 2 && alphaZ > 0.0) throw InputError("alphaZ", "is not available in 2D");
  if ((alphaY > 0.0 || alphaZ > 0.0) && !(shearModulus > 0.0))
    throw InputError("G", "must be positive when a shear factor is given");
}

ElasticSection::ElasticSection(int tag, const Params& p) : SectionForceDeformation(tag) {
  p.validate();
  std::vector<double> stiffness;
  auto add = [&](SectionCode c, double k) {
    codes_.push_back(c);
    stiffness.push_back(k);
  };
  add(SectionCode::P, p.modulus * p.area);
  add(SectionCode::Mz, p.modulus * p.inertiaZ);
  if (p.alphaY > 0.0) add(SectionCode::Vy, p.alphaY * p.shearModulus * p.area);
  if (p.ndm == 3) {
    add(SectionCode::My, p.modulus * p.inertiaY);
    if (p.alphaZ > 0.0) add(SectionCode::Vz, p.alphaZ * p.shearModulus * p.area);
    add(SectionCode::T, p.shearModulus * p.torsion);
  }
  const int n = static_cast<int>(codes_.size());
  k_ = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) k_(i, i) = stiffness[static_cast<std::size_t>(i)];
  e_ = eCommitted_ = s_ = Eigen::VectorXd::Zero(n);
}

Status ElasticSection::setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) {
  e_ = e;
  s_.noalias() = k_.diagonal().cwiseProduct(e_);
  return s_.allFinite() ? Status::Ok : Status::NonFinite;
}

void ElasticSection::revertToLastCommit() {
  e_ = eCommitted_;
  s_.noalias() = k_.diagonal().cwiseProduct(e_);
}

void ElasticSection::revertToStart() {
  e_.setZero();
  eCommitted_.setZero();
  s_.setZero();
}

std::optional<Eigen::VectorXd> ElasticSection::response(std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  if (args.size() == 1 && (args[0] == "force" || args[0] == "forces")) return s_;
  if (args.size() == 1 && (args[0] == "deformation" || args[0] == "deformations")) return e_;
  return std::nullopt;
}

}  // namespace dabs::materials::section
