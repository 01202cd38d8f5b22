// SPDX-License-Identifier: MIT
#include "contact/ContactSearch.h"

#include <algorithm>

namespace dabs::contact {

double ContactSearch::distanceLowerBound(const Eigen::Vector3d& contactor,
                                         const std::array<Eigen::Vector3d, 4>& quad) noexcept {
  const BoundingSphere s = boundingSphere(quad);
  return (contactor - s.center).norm() - s.radius;
}

namespace {
double slabDistance(const Eigen::Vector3d& contactor, const std::array<Eigen::Vector3d, 4>& quad,
                    const Eigen::Vector3d& n) noexcept {
  return ContactSearch::slabBound(contactor, n, ContactSearch::slabTop(quad, n));
}
}  // namespace

double ContactSearch::distanceLowerBound(const Eigen::Vector3d& contactor,
                                         const std::array<Eigen::Vector3d, 4>& quad,
                                         const Eigen::Vector3d& n) noexcept {
  const double slab = slabDistance(contactor, quad, n);
  const double sphere = distanceLowerBound(contactor, quad);
  return slab > sphere ? slab : sphere;
}

bool ContactSearch::isFar(const Eigen::Vector3d& contactor,
                          const std::array<Eigen::Vector3d, 4>& quad, const Eigen::Vector3d& n,
                          double& bound) const noexcept {
  if (!enabled()) return false;
  // The slab alone first: it settles most far pairs (faces across a gap) without the sphere.
  const double slab = slabDistance(contactor, quad, n);
  if (slab > distance_) {
    bound = slab;
    return true;
  }
  const double sphere = distanceLowerBound(contactor, quad);
  bound = slab > sphere ? slab : sphere;
  return bound > distance_;
}

}  // namespace dabs::contact
