// SPDX-License-Identifier: MIT
#include "contact/ContactSearch.h"

namespace dabs::contact {

double ContactSearch::distanceLowerBound(const Eigen::Vector3d& contactor,
                                         const std::array<Eigen::Vector3d, 4>& quad) noexcept {
  const BoundingSphere s = boundingSphere(quad);
  return (contactor - s.center).norm() - s.radius;
}

bool ContactSearch::isFar(const Eigen::Vector3d& contactor,
                          const std::array<Eigen::Vector3d, 4>& quad, double& bound) const noexcept {
  if (!enabled()) return false;
  bound = distanceLowerBound(contactor, quad);
  return bound > distance_;
}

}  // namespace dabs::contact
