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
  GlobalMatrix kg = GlobalMatrix::Zero();
  const double n = q(0) / length0_;
  for (int d : {1, 2}) {
    kg(d, d) = kg(d + 6, d + 6) = n;
    kg(d, d + 6) = kg(d + 6, d) = -n;
  }
  return compat0_.transpose() * kb * compat0_ + globalFromLocal(kg);
}

}  // namespace dabs::elements
