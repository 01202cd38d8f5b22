// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <limits>

#include "contact/ContactGeometry.h"
#include "elements/FarPair.h"

namespace dabs::contact {

/// Decides whether a contactor is near enough to its target quad to be worth evaluating ("only
/// what the scene needs"). The test is a lower bound of the distance from the contactor to the
/// quad, the larger of two: the bounding sphere, |x_k - c| - r with c and r the centre and radius
/// of the quad's current bounding sphere; and the height above the face along its reference
/// (outward) normal n, z_k - max z_i with z = n.x (the bilinear quad lies in the convex hull of
/// its corners, so below their largest height along any fixed direction; only the outward side
/// counts, since behind the face is penetration). The
/// slab is what tells two parallel faces apart across a narrow gap, where the sphere of a wide
/// face reaches past the other face's corners. A pair is far when the bound exceeds the
/// distance; a far pair adds no force and no stiffness. (The analysis leaves far pairs out of
/// the matrix pattern and out of the iterations, checking them once per step:
/// AnalysisModel's sleeping pairs.)
class ContactSearch {
 public:
  /// `distance` >= 0; infinity (the default) evaluates the pair at every update.
  explicit ContactSearch(double distance = std::numeric_limits<double>::infinity()) noexcept
      : distance_(distance) {}

  double distance() const noexcept { return distance_; }
  bool enabled() const noexcept { return distance_ < std::numeric_limits<double>::infinity(); }

  /// Lower bound of the distance from the contactor to the quad (>= 0 outside its bounding sphere,
  /// negative inside it).
  static double distanceLowerBound(const Eigen::Vector3d& contactor,
                                   const std::array<Eigen::Vector3d, 4>& quad) noexcept;
  /// The same, the larger of the sphere bound and the slab bound along the unit vector n.
  static double distanceLowerBound(const Eigen::Vector3d& contactor,
                                   const std::array<Eigen::Vector3d, 4>& quad,
                                   const Eigen::Vector3d& n) noexcept;

  /// Top of the slab the bilinear quad lies in along the unit vector n: its highest corner,
  /// max_i n.x_i. Pairs that share a target face share it, so a broad phase over many contactors
  /// forms it once per face (AnalysisModel's far test of sleeping pairs). The arithmetic is
  /// elements::FarPair's, so the element's test and the analysis' agree to the bit.
  static double slabTop(const std::array<Eigen::Vector3d, 4>& quad,
                        const Eigen::Vector3d& n) noexcept {
    return elements::FarPair::slabTop(quad, n);
  }
  /// Slab bound of a contactor against a face with slabTop `top`: its height n.x - top above the
  /// face's highest corner. One-sided: only the outward side counts (behind the face is
  /// penetration, never far). Together with slabTop the same arithmetic as isFar's slab bound,
  /// so a caller that forms the top once per face gets the same bound to the bit.
  static double slabBound(const Eigen::Vector3d& contactor, const Eigen::Vector3d& n,
                          double top) noexcept {
    return elements::FarPair::slabBound(contactor, n, top);
  }

  /// True when the pair is farther apart than the search distance (and so may be skipped).
  /// Writes the distance lower bound to `bound` when the test was made: the slab bound when that
  /// alone shows the pair far, else the larger of the slab and sphere bounds.
  bool isFar(const Eigen::Vector3d& contactor, const std::array<Eigen::Vector3d, 4>& quad,
             const Eigen::Vector3d& n, double& bound) const noexcept;

 private:
  double distance_;
};

}  // namespace dabs::contact
