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
  GlobalMatrix kg = GlobalMatrix::Zero();
  const double n = q(0) / length0_;
  kg(1, 1) = kg(4, 4) = n;
  kg(1, 4) = kg(4, 1) = -n;
  return compat0_.transpose() * kb * compat0_ + rot_.transpose() * kg * rot_;
}

}  // namespace dabs::elements
