// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>

#include "contact/ContactGeometry.h"

namespace dabs::contact {

/// Decides whether a contactor is near enough to its target quad to be worth evaluating ("only
/// what the scene needs"). The test is one bounding-sphere distance per update: a pair is
/// far when |x_k - c| - r > distance, where c and r are the centre and radius of the quad's
/// current bounding sphere. A far pair adds no force and no stiffness; its element still owns its
/// place in the sparse matrix pattern, so nothing is re-analysed when it closes.
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

  /// True when the pair is farther apart than the search distance (and so may be skipped).
  /// Writes the distance lower bound to `bound` when the test was made.
  bool isFar(const Eigen::Vector3d& contactor, const std::array<Eigen::Vector3d, 4>& quad,
             double& bound) const noexcept;

 private:
  double distance_;
};

}  // namespace dabs::contact
