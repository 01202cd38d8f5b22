// SPDX-License-Identifier: MIT
#include "elements/transform/CorotationalTransf2d.h"

#include <cmath>

namespace dabs::elements {

void CorotationalTransf<2>::initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
  CrdTransf2d::initialize(xi, xj);
  update(Global::Zero());
}

void CorotationalTransf<2>::update(const Global& u) {
  const double cos0 = axes_(0, 0), sin0 = axes_(0, 1);  // undeformed chord direction
  const double dx = length0_ * cos0 + u(3) - u(0);
  const double dy = length0_ * sin0 + u(4) - u(1);
  lengthN_ = std::hypot(dx, dy);
  const double c = dx / lengthN_, s = dy / lengthN_;
  // Rigid chord rotation relative to the undeformed chord, in (-pi, pi].
  const double alpha = std::atan2(cos0 * s - sin0 * c, cos0 * c + sin0 * s);
  v_(0) = lengthN_ - length0_;
  v_(1) = u(2) - alpha;
  v_(2) = u(5) - alpha;
  r_ << -c, -s, 0.0, c, s, 0.0;
  z_ << s, -c, 0.0, -s, c, 0.0;
  compat_.row(0) = r_.transpose();
  compat_.row(1) = -z_.transpose() / lengthN_;
  compat_.row(2) = -z_.transpose() / lengthN_;
  compat_(1, 2) += 1.0;
  compat_(2, 5) += 1.0;
}

CorotationalTransf<2>::GlobalMatrix CorotationalTransf<2>::globalStiffness(const BasicMatrix& kb,
                                                                           const Basic& q) const {
  GlobalMatrix k = congruence(compat_, kb);
  k += q(0) / lengthN_ * (z_ * z_.transpose());
  k += (q(1) + q(2)) / (lengthN_ * lengthN_) * (r_ * z_.transpose() + z_ * r_.transpose());
  return k;
}

}  // namespace dabs::elements
