// SPDX-License-Identifier: MIT
#include "elements/transform/PDeltaTransf.h"

namespace dabs::elements {

template <int Ndm>
void PDeltaTransf<Ndm>::update(const Global& u) {
  constexpr int n = Base::kDofPerNode;
  this->v_ = this->compat0_ * u;
  const Global ul = this->toLocal(u);
  for (int a = 1; a < Ndm; ++a) delta_(a - 1) = ul(a) - ul(n + a);
}

template <int Ndm>
typename PDeltaTransf<Ndm>::Global PDeltaTransf<Ndm>::globalForce(const Basic& q) const {
  constexpr int n = Base::kDofPerNode;
  Global pl = Global::Zero();
  const double axial = q(0) / this->length0_;
  for (int a = 1; a < Ndm; ++a) {
    pl(a) = axial * delta_(a - 1);
    pl(n + a) = -axial * delta_(a - 1);
  }
  Global p = this->compat0_.transpose() * q;
  p += this->globalFromLocal(pl);
  return p;
}

template <int Ndm>
typename PDeltaTransf<Ndm>::GlobalMatrix PDeltaTransf<Ndm>::globalStiffness(const BasicMatrix& kb,
                                                                            const Basic& q) const {
  GlobalMatrix k = Base::congruence(this->compat0_, kb);
  addGeometricStiffness(k, q);
  return k;
}

template <int Ndm>
void PDeltaTransf<Ndm>::addGeometricStiffness(GlobalMatrix& k, const Basic& q) const {
  // Local geometric matrix N/L [1 -1; -1 1] on the local transverse translations, rotated to
  // global: the translation blocks get +-N/L sum_a t_a t_a^T over the transverse axes t_a.
  constexpr int n = Base::kDofPerNode;
  const double axial = q(0) / this->length0_;
  const auto transverse = this->axes_.template bottomRows<Ndm - 1>();
  const Eigen::Matrix<double, Ndm, Ndm> g = axial * (transverse.transpose() * transverse);
  k.template block<Ndm, Ndm>(0, 0) += g;
  k.template block<Ndm, Ndm>(n, n) += g;
  k.template block<Ndm, Ndm>(0, n) -= g;
  k.template block<Ndm, Ndm>(n, 0) -= g;
}

template class PDeltaTransf<2>;
template class PDeltaTransf<3>;

}  // namespace dabs::elements
