// SPDX-License-Identifier: MIT
#include "elements/transform/CrdTransf3d.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "materials/InputError.h"

namespace dabs::elements {

void CrdTransf3d::initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
  const std::string who = "geomTransf " + std::to_string(tag());
  const Eigen::Vector3d d = xj - xi;
  const double length = d.norm();
  if (!(length > 1e-14 * std::max(1.0, xi.norm())))
    throw InputError(who, "element has zero length");
  const Eigen::Vector3d x = d / length;
  Eigen::Vector3d y = vecxz_.cross(x);
  const double ny = y.norm();
  // Same test as OpenSees (|vecxz x x| == 0), with a relative tolerance for round-off.
  if (!(ny > 1e-10 * vecxz_.norm())) throw InputError(who, "vecxz is parallel to the element axis");
  y /= ny;
  const Eigen::Vector3d z = x.cross(y);
  axes_.row(0) = x.transpose();
  axes_.row(1) = y.transpose();
  axes_.row(2) = z.transpose();
  length0_ = length;

  // Local compatibility (LinearCrdTransf3d): v0 = ul6 - ul0; v1 = ul5 + (ul1 - ul7)/L;
  // v2 = ul11 + (ul1 - ul7)/L; v3 = ul4 - (ul2 - ul8)/L; v4 = ul10 - (ul2 - ul8)/L; v5 = ul9 - ul3.
  Compat local = Compat::Zero();
  const double r = 1.0 / length;
  local(0, 0) = -1.0;
  local(0, 6) = 1.0;
  local(1, 1) = r;
  local(1, 5) = 1.0;
  local(1, 7) = -r;
  local(2, 1) = r;
  local(2, 7) = -r;
  local(2, 11) = 1.0;
  local(3, 2) = -r;
  local(3, 4) = 1.0;
  local(3, 8) = r;
  local(4, 2) = -r;
  local(4, 8) = r;
  local(4, 10) = 1.0;
  local(5, 3) = -1.0;
  local(5, 9) = 1.0;
  GlobalMatrix t = GlobalMatrix::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = axes_;
  compat0_ = local * t;
  compat_ = compat0_;
  v_.setZero();
}

CrdTransf3d::Global CrdTransf3d::globalForce(const Basic& q) const {
  return compat_.transpose() * q;
}

CrdTransf3d::GlobalMatrix CrdTransf3d::globalStiffness(const BasicMatrix& kb, const Basic&) const {
  return compat_.transpose() * kb * compat_;
}

CrdTransf3d::GlobalMatrix CrdTransf3d::initialGlobalStiffness(const BasicMatrix& kb) const {
  return compat0_.transpose() * kb * compat0_;
}

CrdTransf3d::GlobalMatrix CrdTransf3d::globalFromLocal(const GlobalMatrix& local) const {
  GlobalMatrix g;
  // (T^T m T) block by block: T = diag(R, R, R, R).
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      g.block<3, 3>(3 * a, 3 * b) = axes_.transpose() * local.block<3, 3>(3 * a, 3 * b) * axes_;
  return g;
}

CrdTransf3d::Global CrdTransf3d::localForce(const Basic& q) const {
  Global p;
  const double vy = (q(1) + q(2)) / length0_;
  const double vz = (q(3) + q(4)) / length0_;
  p << -q(0), vy, -vz, -q(5), q(3), q(1), q(0), -vy, vz, q(5), q(4), q(2);
  return p;
}

CrdTransf3d::Global CrdTransf3d::toLocal(const Global& u) const {
  Global ul;
  for (int b = 0; b < 4; ++b) ul.segment<3>(3 * b) = axes_ * u.segment<3>(3 * b);
  return ul;
}

}  // namespace dabs::elements
