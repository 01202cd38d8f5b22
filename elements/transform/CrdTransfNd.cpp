// SPDX-License-Identifier: MIT
#include "elements/transform/CrdTransfNd.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "materials/InputError.h"

namespace dabs::elements {

template <int Ndm>
void CrdTransfNd<Ndm>::initialize(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj) {
  const std::string who = "geomTransf " + std::to_string(tag());
  const Eigen::Matrix<double, Ndm, 1> d = (xj - xi).template head<Ndm>();
  const double length = d.norm();
  if (!(length > 1e-14 * std::max(1.0, xi.norm())))
    throw InputError(who, "element has zero length");
  length0_ = length;
  Compat local = Compat::Zero();
  const double r = 1.0 / length;
  // Local compatibility (LinearCrdTransf2d/3d), with n the dofs per node:
  // v0 = ul(n) - ul(0); v1 = ul(rz_i) + (ul1 - ul(n+1))/L; v2 = ul(rz_j) + (ul1 - ul(n+1))/L.
  constexpr int n = kDofPerNode;
  constexpr int rz = Ndm == 2 ? 2 : 5;
  local(0, 0) = -1.0;
  local(0, n) = 1.0;
  local(1, 1) = r;
  local(1, rz) = 1.0;
  local(1, n + 1) = -r;
  local(2, 1) = r;
  local(2, n + 1) = -r;
  local(2, n + rz) = 1.0;
  if constexpr (Ndm == 2) {
    axes_ << d(0) / length, d(1) / length, -d(1) / length, d(0) / length;
  } else {
    const Eigen::Vector3d x = d / length;
    Eigen::Vector3d y = vecxz_.cross(x);
    const double ny = y.norm();
    // Same test as OpenSees (|vecxz x x| == 0), with a relative tolerance for round-off.
    if (!(ny > 1e-10 * vecxz_.norm()))
      throw InputError(who, "vecxz is parallel to the element axis");
    y /= ny;
    axes_.row(0) = x.transpose();
    axes_.row(1) = y.transpose();
    axes_.row(2) = x.cross(y).transpose();
    // Bending about local y and twist: v3 = ul4 - (ul2 - ul8)/L; v4 = ul10 - (ul2 - ul8)/L;
    // v5 = ul9 - ul3.
    local(3, 2) = -r;
    local(3, 4) = 1.0;
    local(3, 8) = r;
    local(4, 2) = -r;
    local(4, 8) = r;
    local(4, 10) = 1.0;
    local(5, 3) = -1.0;
    local(5, 9) = 1.0;
  }
  // T = diag over the nodes of (axes on the translations; axes (3D) or 1 (2D) on the rotations).
  GlobalMatrix t = GlobalMatrix::Zero();
  for (int o : {0, n}) {
    t.template block<Ndm, Ndm>(o, o) = axes_;
    if constexpr (Ndm == 2)
      t(o + 2, o + 2) = 1.0;
    else
      t.template block<3, 3>(o + 3, o + 3) = axes_;
  }
  compat0_ = local * t;
  compat_ = compat0_;
  v_.setZero();
}

template <int Ndm>
typename CrdTransfNd<Ndm>::Global CrdTransfNd<Ndm>::globalForce(const Basic& q) const {
  return compat_.transpose() * q;
}

template <int Ndm>
typename CrdTransfNd<Ndm>::GlobalMatrix CrdTransfNd<Ndm>::globalStiffness(const BasicMatrix& kb,
                                                                          const Basic&) const {
  return congruence(compat_, kb);
}

template <int Ndm>
typename CrdTransfNd<Ndm>::GlobalMatrix CrdTransfNd<Ndm>::initialGlobalStiffness(
    const BasicMatrix& kb) const {
  return congruence(compat0_, kb);
}

template <int Ndm>
typename CrdTransfNd<Ndm>::GlobalMatrix CrdTransfNd<Ndm>::globalFromLocal(
    const GlobalMatrix& local) const {
  GlobalMatrix g;
  if constexpr (Ndm == 2) {
    GlobalMatrix t = GlobalMatrix::Zero();
    for (int o : {0, 3}) {
      t.template block<2, 2>(o, o) = axes_;
      t(o + 2, o + 2) = 1.0;
    }
    g = t.transpose() * local * t;
  } else {
    // Block by block: T = diag(R, R, R, R).
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        g.template block<3, 3>(3 * a, 3 * b) =
            axes_.transpose() * local.template block<3, 3>(3 * a, 3 * b) * axes_;
  }
  return g;
}

template <int Ndm>
typename CrdTransfNd<Ndm>::Global CrdTransfNd<Ndm>::globalFromLocal(const Global& local) const {
  Global p = local;  // 2D: the rotations rz are the same in both frames
  for (int o = 0; o < 2 * kDofPerNode; o += (Ndm == 2 ? 3 : Ndm))
    p.template segment<Ndm>(o) = axes_.transpose() * local.template segment<Ndm>(o);
  return p;
}

template <int Ndm>
typename CrdTransfNd<Ndm>::Global CrdTransfNd<Ndm>::toLocal(const Global& u) const {
  Global ul = u;
  for (int o = 0; o < 2 * kDofPerNode; o += (Ndm == 2 ? 3 : Ndm))
    ul.template segment<Ndm>(o) = axes_ * u.template segment<Ndm>(o);
  return ul;
}

template <int Ndm>
typename CrdTransfNd<Ndm>::Global CrdTransfNd<Ndm>::localForce(const Basic& q) const {
  Global p;
  const double vy = (q(1) + q(2)) / length0_;
  if constexpr (Ndm == 2) {
    p << -q(0), vy, q(1), q(0), -vy, q(2);
  } else {
    const double vz = (q(3) + q(4)) / length0_;
    p << -q(0), vy, -vz, -q(5), q(3), q(1), q(0), -vy, vz, q(5), q(4), q(2);
  }
  return p;
}

template class CrdTransfNd<2>;
template class CrdTransfNd<3>;

}  // namespace dabs::elements
