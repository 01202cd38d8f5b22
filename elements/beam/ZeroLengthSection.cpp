// SPDX-License-Identifier: MIT
#include "elements/beam/ZeroLengthSection.h"

#include <Eigen/Geometry>
#include <cassert>
#include <cmath>
#include <sstream>
#include <string>

#include "materials/InputError.h"

namespace dabs::elements {

using materials::section::SectionCode;

template <int Ndm>
ZeroLengthSection<Ndm>::ZeroLengthSection(
    int tag, int nodeI, int nodeJ,
    std::unique_ptr<materials::section::SectionForceDeformation> section, const Eigen::Vector3d& x,
    const Eigen::Vector3d& yp)
    : Base(tag, {nodeI, nodeJ}), section_(std::move(section)) {
  assert(section_);
  const std::string who = "zeroLengthSection " + std::to_string(tag);
  if (!(x.norm() > 0.0)) throw InputError("-orient", "x vector must be nonzero");
  if (!(yp.norm() > 0.0)) throw InputError("-orient", "yp vector must be nonzero");
  const Eigen::Vector3d ex = x.normalized();
  Eigen::Vector3d ez = ex.cross(yp);
  if (!(ez.norm() > 1e-10 * yp.norm()))
    throw InputError("-orient", "x and yp vectors are parallel");
  ez.normalize();
  const Eigen::Vector3d ey = ez.cross(ex);
  axes_.row(0) = ex.transpose();
  axes_.row(1) = ey.transpose();
  axes_.row(2) = ez.transpose();
  if (Ndm == 2 && (std::abs(ex.z()) > 1e-12 || std::abs(ey.z()) > 1e-12))
    throw InputError("-orient", "x and yp must lie in the X-Y plane of a 2D model");

  // One row per resultant: relative motion of node j with respect to node i along/about a local
  // axis (ZeroLengthSection::setTransformation).
  const auto codes = section_->type();
  const int order = static_cast<int>(codes.size());
  if (order > kMaxSectionOrder) throw InputError(who, "section has too many resultants");
  a_ = Compat::Zero(order, kNumDof);
  ka_ = Compat::Zero(order, kNumDof);
  e_ = SectionVector::Zero(order);
  constexpr int ndf = FrameTraits<Ndm>::kDofPerNode;
  for (int r = 0; r < order; ++r) {
    const SectionCode c = codes[static_cast<std::size_t>(r)];
    const bool translation = c == SectionCode::P || c == SectionCode::Vy || c == SectionCode::Vz;
    const int axis = (c == SectionCode::P || c == SectionCode::T)     ? 0
                     : (c == SectionCode::Vy || c == SectionCode::My) ? 1
                                                                      : 2;
    if constexpr (Ndm == 2) {
      if (c == SectionCode::My || c == SectionCode::Vz || c == SectionCode::T)
        throw InputError(who, "section resultant code " + std::to_string(int(c)) +
                                  " (My, Vz or T) is not available in a 2D model");
      for (int n = 0; n < 2; ++n) {
        const double s = n == 0 ? -1.0 : 1.0;
        if (translation) {
          a_(r, n * ndf) = s * axes_(axis, 0);
          a_(r, n * ndf + 1) = s * axes_(axis, 1);
        } else {
          a_(r, n * ndf + 2) = s * axes_(2, 2);  // rotation about global Z, seen from local z
        }
      }
    } else {
      for (int n = 0; n < 2; ++n) {
        const double s = n == 0 ? -1.0 : 1.0;
        const int o = n * ndf + (translation ? 0 : 3);
        for (int d = 0; d < 3; ++d) a_(r, o + d) = s * axes_(axis, d);
      }
    }
  }
}

template <int Ndm>
void ZeroLengthSection<Ndm>::initialize(const NodalCoordinates& x) {
  if (x.size() != 2) throw InputError("element", "zeroLengthSection needs 2 nodes");
  // Like OpenSees, the nodes need not coincide; the element has no length either way.
  ka_.noalias() = section_->getInitialTangent() * a_;
  this->k0_.noalias() = a_.transpose() * ka_;
  formState();
  this->kc_ = this->k_;
}

template <int Ndm>
void ZeroLengthSection<Ndm>::formState() {
  ka_.noalias() = section_->getSectionTangent().lazyProduct(a_);
  this->k_.noalias() = a_.transpose().lazyProduct(ka_);
  this->f_.noalias() = a_.transpose() * section_->getStressResultant();
}

template <int Ndm>
Status ZeroLengthSection<Ndm>::update(const Kinematics& trial) {
  e_.noalias() = a_ * trial.u;
  const Status s = section_->setTrialDeformation(e_);
  formState();
  return s;
}

template <int Ndm>
void ZeroLengthSection<Ndm>::revertToLastCommit() {
  section_->revertToLastCommit();
  formState();
}

template <int Ndm>
void ZeroLengthSection<Ndm>::revertToStart() {
  section_->revertToStart();
  formState();
  this->kc_ = this->k_;
}

template <int Ndm>
std::optional<Eigen::VectorXd> ZeroLengthSection<Ndm>::response(
    std::span<const std::string> args) const {
  if (args.empty()) return std::nullopt;
  const std::string& name = args[0];
  if (name == "section") return section_->response(args.subspan(1));
  if (args.size() != 1) return std::nullopt;
  if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
    return Eigen::VectorXd(this->f_);
  if (name == "basicForce" || name == "basicForces" || name == "localForce" ||
      name == "localForces")
    return Eigen::VectorXd(section_->getStressResultant());
  if (name == "deformation" || name == "deformations" || name == "basicDeformation" ||
      name == "basicDeformations")
    return Eigen::VectorXd(section_->getDeformation());
  return std::nullopt;
}

template <int Ndm>
std::string ZeroLengthSection<Ndm>::describe() const {
  std::ostringstream s;
  s << "ZeroLengthSection " << this->tag() << ": nodes " << this->nodes_[0] << " "
    << this->nodes_[1] << ", section " << section_->tag() << ", x " << axes_.row(0) << ", y "
    << axes_.row(1) << ", resultants " << section_->getStressResultant().transpose();
  return s.str();
}

template class ZeroLengthSection<2>;
template class ZeroLengthSection<3>;

}  // namespace dabs::elements
