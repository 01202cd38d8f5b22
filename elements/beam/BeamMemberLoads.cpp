// SPDX-License-Identifier: MIT
#include "elements/beam/BeamMemberLoads.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::elements {

using materials::section::SectionCode;

template <int Nb>
void BeamMemberLoads<Nb>::clear() {
  loads_.clear();
  q0_.setZero();
  p0_.setZero();
}

// Statics of the basic system at x for one load (w scaled). With A, B the loaded part, the
// transverse reactions at I and J are the lever-rule shares of the resultant; the section forces
// follow from equilibrium of the part [0, x]: V_y(x) = -R_yI + int_0^x w_y, M_z(x) = -R_yI x +
// int_0^x w_y (x - s) ds (OpenSees' sign convention: an upward load gives a negative moment), and
// with the opposite sign for the x-z plane (M_y = R_zI x - int_0^x w_z (x - s) ds, V_z = dM_y/dx).
// The axial force is the axial load between x and J (the member is held axially at I).
template <int Nb>
typename BeamMemberLoads<Nb>::Statics BeamMemberLoads<Nb>::statics(const BeamLoad& load,
                                                                   double x) const {
  const double length = length_;
  const double a = load.a * length;
  const Eigen::Vector3d& w = load.w;
  Statics s;
  if (load.type == BeamLoad::Type::Point) {
    const double shareJ = load.a;  // reaction share at J: a / L
    const double ryI = w.y() * (1.0 - shareJ), rzI = w.z() * (1.0 - shareJ);
    const bool right = x > a;
    s.n = right ? 0.0 : w.x();
    s.vy = -ryI + (right ? w.y() : 0.0);
    s.mz = -ryI * x + (right ? w.y() * (x - a) : 0.0);
    s.vz = rzI - (right ? w.z() : 0.0);
    s.my = rzI * x - (right ? w.z() * (x - a) : 0.0);
    return s;
  }
  // Loaded part [A, B] with intensity w0 + k (s - A), k = (w1 - w0) / (B - A); with C = c - A
  // and X = x - A for c = clamp(x, A, B): int_A^c w ds = w0 C + k C^2/2 and
  // int_A^c w (x - s) ds = w0 (X C - C^2/2) + k (X C^2/2 - C^3/3).
  const double b = load.b * length;
  const double span = b - a;
  const Eigen::Vector3d w1 = load.wEnd.value_or(w);
  const Eigen::Vector3d k = (w1 - w) / span;
  const Eigen::Vector3d total = 0.5 * (w + w1) * span;
  // First moment about I: int w s ds = w0 (B^2 - A^2)/2 + k ((B^3 - A^3)/3 - A (B^2 - A^2)/2).
  const Eigen::Vector3d moment =
      w * 0.5 * (b * b - a * a) + k * ((b * b * b - a * a * a) / 3.0 - a * 0.5 * (b * b - a * a));
  const Eigen::Vector3d rI = total - moment / length;  // reactions at I (lever rule)
  const double c = std::clamp(x, a, b);
  const double cc = c - a, xx = x - a;
  const Eigen::Vector3d loaded = w * cc + k * (0.5 * cc * cc);
  const Eigen::Vector3d lever =
      w * (xx * cc - 0.5 * cc * cc) + k * (0.5 * xx * cc * cc - cc * cc * cc / 3.0);
  s.n = total.x() - loaded.x();
  s.vy = -rI.y() + loaded.y();
  s.mz = -rI.y() * x + lever.y();
  s.vz = rI.z() - loaded.z();
  s.my = rI.z() * x - lever.z();
  return s;
}

template <int Nb>
void BeamMemberLoads<Nb>::add(const BeamLoad& given, double factor, double length) {
  if (!(length > 0.0)) throw InputError("", "member load on an element without length");
  if (given.type == BeamLoad::Type::Point) {
    if (!(given.a >= 0.0 && given.a <= 1.0))
      throw InputError("xL", "must be within [0, 1], got " + std::to_string(given.a));
  } else if (!(given.a >= 0.0 && given.a < given.b && given.b <= 1.0)) {
    throw InputError("aOverL bOverL", "must satisfy 0 <= aOverL < bOverL <= 1");
  }
  if (Nb == 3 && (given.w.z() != 0.0 || (given.wEnd && given.wEnd->z() != 0.0)))
    throw InputError("", "a 2D member load has no component along local z");
  BeamLoad load = given;
  load.w *= factor;
  if (load.wEnd) *load.wEnd *= factor;
  length_ = length;
  loads_.push_back({load});

  // Reactions: a point load shares by the lever rule; for a distributed load the section forces
  // at the ends are the reactions (all the axial load goes to I).
  const double a = load.a * length;
  Reactions p = Reactions::Zero();
  if (load.type == BeamLoad::Type::Point) {
    p(0) = -load.w.x();
    p(1) = -load.w.y() * (1.0 - load.a);
    p(2) = -load.w.y() * load.a;
    if constexpr (Nb == 6) {
      p(3) = -load.w.z() * (1.0 - load.a);
      p(4) = -load.w.z() * load.a;
    }
  } else {
    const Statics atI = statics(load, 0.0);
    const Statics atJ = statics(load, length);
    p(0) = -atI.n;
    p(1) = atI.vy;   // V_y(0) = -R_yI
    p(2) = -atJ.vy;  // V_y(L) = R_yJ
    if constexpr (Nb == 6) {
      p(3) = -atI.vz;  // V_z(0) = R_zI
      p(4) = atJ.vz;   // V_z(L) = -R_zJ
    }
  }
  p0_ += p;

  // Fixed-end forces: v0 = int b^T sp dx / (EI or EA) integrated exactly (Gauss-Legendre with
  // three points per piece is exact for the quartic integrands of a linearly varying load; the
  // pieces end where the load starts and stops), then q0 = -kb v0 for the prismatic member.
  std::array<double, 4> breaks{0.0, a, load.type == BeamLoad::Type::Uniform ? load.b * length : a,
                               length};
  std::sort(breaks.begin(), breaks.end());
  const double g = 0.5 * std::sqrt(0.6);
  constexpr std::array<double, 3> kWeights{5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  double intN = 0.0;
  Eigen::Vector2d rotZ = Eigen::Vector2d::Zero(), rotY = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double x0 = breaks[k], h = breaks[k + 1] - breaks[k];
    if (h <= 0.0) continue;
    const std::array<double, 3> points{0.5 - g, 0.5, 0.5 + g};
    for (std::size_t q = 0; q < 3; ++q) {
      const double x = x0 + points[q] * h;
      const double xi = x / length;
      const Statics s = statics(load, x);
      const double wgt = kWeights[q] * h;
      intN += wgt * s.n;
      rotZ += wgt * s.mz * Eigen::Vector2d(xi - 1.0, xi);
      rotY += wgt * s.my * Eigen::Vector2d(xi - 1.0, xi);
    }
  }
  Eigen::Matrix2d k;
  k << 4.0, 2.0, 2.0, 4.0;
  q0_(0) -= intN / length;
  q0_.template segment<2>(1) -= k * rotZ / length;
  if constexpr (Nb == 6) q0_.template segment<2>(3) -= k * rotY / length;
}

template <int Nb>
typename BeamMemberLoads<Nb>::LocalEnd BeamMemberLoads<Nb>::localEndForces() const {
  LocalEnd p = LocalEnd::Zero();
  if constexpr (Nb == 3) {
    p(0) = p0_(0);
    p(1) = p0_(1);
    p(4) = p0_(2);
  } else {
    p(0) = p0_(0);
    p(1) = p0_(1);
    p(7) = p0_(2);
    p(2) = p0_(3);
    p(8) = p0_(4);
  }
  return p;
}

template <int Nb>
SectionVector BeamMemberLoads<Nb>::sectionForces(std::span<const SectionCode> codes,
                                                 double xi) const {
  SectionVector sp = SectionVector::Zero(static_cast<int>(codes.size()));
  const double x = xi * length_;
  for (const Scaled& l : loads_) {
    const Statics s = statics(l.load, x);
    for (std::size_t r = 0; r < codes.size(); ++r) {
      const auto i = static_cast<Eigen::Index>(r);
      switch (codes[r]) {
        case SectionCode::P: sp(i) += s.n; break;
        case SectionCode::Mz: sp(i) += s.mz; break;
        case SectionCode::Vy: sp(i) += s.vy; break;
        case SectionCode::My: sp(i) += Nb == 6 ? s.my : 0.0; break;
        case SectionCode::Vz: sp(i) += Nb == 6 ? s.vz : 0.0; break;
        case SectionCode::T: break;
      }
    }
  }
  return sp;
}

template class BeamMemberLoads<3>;
template class BeamMemberLoads<6>;

}  // namespace dabs::elements
