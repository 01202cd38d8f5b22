// SPDX-License-Identifier: MIT
#include "elements/transform/PDeltaTransf2d.h"

namespace dabs::elements {

void PDeltaTransf2d::update(const Global& u) {
  v_ = compat0_ * u;
  const Global ul = toLocal(u);
  delta_ = ul(1) - ul(4);
}

PDeltaTransf2d::Global PDeltaTransf2d::globalForce(const Basic& q) const {
  Global pl = Global::Zero();
  const double shear = q(0) / length0_ * delta_;
  pl(1) = shear;
  pl(4) = -shear;
  return compat0_.transpose() * q + rot_.transpose() * pl;
}

PDeltaTransf2d::GlobalMatrix PDeltaTransf2d::globalStiffness(const BasicMatrix& kb,
                                                             const Basic& q) const {
  GlobalMatrix k = compat0_.transpose() * kb * compat0_;
  addGeometricStiffness(k, q);
  return k;
}

void PDeltaTransf2d::addGeometricStiffness(GlobalMatrix& k, const Basic& q) const {
  // Local geometric matrix N/L [1 -1; -1 1] on the local y translations, rotated to global with
  // the local y axis (-sin, cos): blocks +-N/L y y^T on (ux, uy) of both nodes.
  const double n = q(0) / length0_;
  const double gxx = n * sin_ * sin_, gxy = -n * sin_ * cos_, gyy = n * cos_ * cos_;
  for (int a : {0, 3})
    for (int b : {0, 3}) {
      const double s = a == b ? 1.0 : -1.0;
      k(a, b) += s * gxx;
      k(a, b + 1) += s * gxy;
      k(a + 1, b) += s * gxy;
      k(a + 1, b + 1) += s * gyy;
    }
}

}  // namespace dabs::elements
