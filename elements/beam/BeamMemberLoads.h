// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "elements/BeamLoad.h"
#include "elements/beam/SectionInterpolation.h"
#include "elements/transform/CrdTransfNd.h"
#include "elements/transform/FrameTraits.h"

namespace dabs::elements {

/// The member loads acting on one beam-column, scaled by their patterns' factors, and what the
/// element formulations need from them. Everything refers to the basic system of the
/// transformation: a member simply supported for bending (pins at both ends) and held axially at
/// node I, loaded in its undeformed local axes.
///  - reactions(): support reactions of that system, p0 = [N_I, Vy_I, Vy_J] (2D) or
///    [N_I, Vy_I, Vy_J, Vz_I, Vz_J] (3D), added to the end forces;
///  - sectionForces(): the section forces sp(x) of that system (force-based elements add them to
///    b(x) q; Spacone, Filippou & Taucer 1996, eq. 8 with the particular solution of the loads);
///  - fixedEndForces(): basic forces q0 of the member with both ends clamped, for a prismatic
///    elastic member (elastic and displacement-based elements add them to q). They follow from the
///    compatibility of the simply supported system: the end rotations and the elongation under
///    sp(x) are cancelled by q0, q0 = -kb v0 with v0 = int b(x)^T fs sp(x) dx, whose prismatic
///    form no longer depends on EI and EA (Przemieniecki 1968, section 5.7, fixed-end forces).
///    For a uniform load this gives -/+ w L^2 / 12, for a point load -P a b^2 / L^2 and
///    P a^2 b / L^2.
/// Nb is the number of basic forces: 3 in 2D, 6 in 3D.
template <int Nb>
class BeamMemberLoads {
 public:
  static constexpr int kReactions = Nb == 3 ? 3 : 5;
  using Basic = Eigen::Matrix<double, Nb, 1>;
  using Reactions = Eigen::Matrix<double, kReactions, 1>;
  /// End forces in local axes, node by node: 2D [N V M]_I [N V M]_J, 3D [N Vy Vz T My Mz]_I ..
  using LocalEnd = Eigen::Matrix<double, Nb == 3 ? 6 : 12, 1>;

  /// Removes every load.
  void clear();
  /// Adds factor x load on a member of length L. Throws InputError for a load position outside
  /// the member, an empty loaded part, or (2D) a load along local z.
  void add(const BeamLoad& load, double factor, double length);
  bool empty() const noexcept { return loads_.empty(); }

  /// Basic fixed-end forces q0 of the clamped prismatic member.
  const Basic& fixedEndForces() const noexcept { return q0_; }
  /// Reactions p0 of the basic system.
  const Reactions& reactions() const noexcept { return p0_; }
  /// p0 placed on the local end dofs (zero on the rotations and at J's axial dof).
  LocalEnd localEndForces() const;
  /// Section forces sp of the basic system at xi = x / L for the resultants `codes` (torsion: 0).
  /// At a point load's own position the section takes the side towards node I, as OpenSees does.
  SectionVector sectionForces(std::span<const materials::section::SectionCode> codes,
                              double xi) const;

 private:
  struct Scaled {
    BeamLoad load;  ///< with w already multiplied by the factor
  };
  /// Axial force, shear and moment resultants of the basic system at x (absolute) due to one load.
  struct Statics {
    double n = 0.0, vy = 0.0, mz = 0.0, vz = 0.0, my = 0.0;
  };
  Statics statics(const BeamLoad& load, double x) const;

  std::vector<Scaled> loads_;
  double length_ = 0.0;
  Basic q0_ = Basic::Zero();
  Reactions p0_ = Reactions::Zero();
};

/// Global end forces of the reactions p0 of a member: T^T p0 with the undeformed axes.
template <int Ndm>
typename FrameTraits<Ndm>::Global globalReactions(
    const CrdTransfNd<Ndm>& transf, const BeamMemberLoads<FrameTraits<Ndm>::kBasic>& loads) {
  return transf.globalFromLocal(loads.localEndForces());
}

}  // namespace dabs::elements
