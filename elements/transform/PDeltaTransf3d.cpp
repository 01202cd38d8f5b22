// SPDX-License-Identifier: MIT
#include "elements/transform/PDeltaTransf3d.h"

namespace dabs::elements {

void PDeltaTransf3d::update(const Global& u) {
  v_ = compat0_ * u;
  const Global ul = toLocal(u);
  deltaY_ = ul(1) - ul(7);
  deltaZ_ = ul(2) - ul(8);
}

PDeltaTransf3d::Global PDeltaTransf3d::globalForce(const Basic& q) const {
  Global pl = Global::Zero();
  const double n = q(0) / length0_;
  pl(1) = n * deltaY_;
  pl(7) = -n * deltaY_;
  pl(2) = n * deltaZ_;
  pl(8) = -n * deltaZ_;
  Global p = compat0_.transpose() * q;
  for (int b = 0; b < 4; ++b) p.segment<3>(3 * b) += axes_.transpose() * pl.segment<3>(3 * b);
  return p;
}

PDeltaTransf3d::GlobalMatrix PDeltaTransf3d::globalStiffness(const BasicMatrix& kb,
                                                             const Basic& q) const {
  GlobalMatrix k = compat0_.transpose() * kb * compat0_;
  addGeometricStiffness(k, q);
  return k;
}

void PDeltaTransf3d::addGeometricStiffness(GlobalMatrix& k, const Basic& q) const {
  // Local geometric matrix N/L [1 -1; -1 1] on the local y and z translations, rotated to global:
  // the translation blocks get +-N/L (y y^T + z z^T).
  const double n = q(0) / length0_;
  const Eigen::Matrix3d g =
      n * (axes_.row(1).transpose() * axes_.row(1) + axes_.row(2).transpose() * axes_.row(2));
  k.block<3, 3>(0, 0) += g;
  k.block<3, 3>(6, 6) += g;
  k.block<3, 3>(0, 6) -= g;
  k.block<3, 3>(6, 0) -= g;
}

}  // namespace dabs::elements
