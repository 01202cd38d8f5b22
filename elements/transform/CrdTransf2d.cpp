// SPDX-License-Identifier: MIT
#include "elements/transform/CrdTransf2d.h"

#include <cmath>

#include "materials/InputError.h"

namespace dabs::elements {

void CrdTransf2d::initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
  const Eigen::Vector2d d = (xj - xi).head<2>();
  const double length = d.norm();
  if (!(length > 1e-14 * std::max(1.0, xi.norm())))
    throw InputError("geomTransf " + std::to_string(tag()), "element has zero length");
  length0_ = length;
  cos_ = d(0) / length;
  sin_ = d(1) / length;
  rot_.setZero();
  for (int n = 0; n < 2; ++n) {
    const int o = 3 * n;
    rot_(o, o) = cos_;
    rot_(o, o + 1) = sin_;
    rot_(o + 1, o) = -sin_;
    rot_(o + 1, o + 1) = cos_;
    rot_(o + 2, o + 2) = 1.0;
  }
  // Local compatibility (LinearCrdTransf2d): v0 = ul3 - ul0, v1 = ul2 + (ul1 - ul4)/L,
  // v2 = ul5 + (ul1 - ul4)/L.
  Compat local = Compat::Zero();
  const double r = 1.0 / length;
  local(0, 0) = -1.0;
  local(0, 3) = 1.0;
  local(1, 1) = r;
  local(1, 2) = 1.0;
  local(1, 4) = -r;
  local(2, 1) = r;
  local(2, 4) = -r;
  local(2, 5) = 1.0;
  compat0_ = local * rot_;
  compat_ = compat0_;
  v_.setZero();
}

CrdTransf2d::Global CrdTransf2d::globalForce(const Basic& q) const {
  return compat_.transpose() * q;
}

CrdTransf2d::GlobalMatrix CrdTransf2d::globalStiffness(const BasicMatrix& kb, const Basic&) const {
  return compat_.transpose() * kb * compat_;
}

CrdTransf2d::GlobalMatrix CrdTransf2d::initialGlobalStiffness(const BasicMatrix& kb) const {
  return compat0_.transpose() * kb * compat0_;
}

CrdTransf2d::GlobalMatrix CrdTransf2d::globalFromLocal(const GlobalMatrix& local) const {
  return rot_.transpose() * local * rot_;
}

CrdTransf2d::Global CrdTransf2d::localForce(const Basic& q) const {
  Global p;
  const double v = (q(1) + q(2)) / length0_;
  p << -q(0), v, q(1), q(0), -v, q(2);
  return p;
}

CrdTransf2d::Global CrdTransf2d::toLocal(const Global& u) const { return rot_ * u; }

}  // namespace dabs::elements
