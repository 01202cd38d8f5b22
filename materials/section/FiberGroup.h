// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"

namespace dabs::materials::section {

/// Running sums of fiber contributions under plane-section kinematics, strain
/// eps = e0 - y kz + z ky with the row a = [1, -y, z]: s = sum(sigma A a) and the symmetric
/// k = sum(Et A a a^T), kept as plain numbers so the fiber loop needs no matrix objects.
struct FiberSums {
  double p = 0.0, mz = 0.0, my = 0.0;                                       ///< s
  double kPP = 0.0, kPz = 0.0, kPy = 0.0, kzz = 0.0, kzy = 0.0, kyy = 0.0;  ///< k, upper half

  /// Adds one fiber with force sigma*A = `force` and stiffness Et*A = `stiffness` at (y, z).
  void add(double y, double z, double force, double stiffness) noexcept {
    p += force;
    mz -= force * y;
    my += force * z;
    kPP += stiffness;
    kPz -= stiffness * y;
    kPy += stiffness * z;
    kzz += stiffness * y * y;
    kzy -= stiffness * y * z;
    kyy += stiffness * z * z;
  }
  /// The same for a plane section (z and ky absent): the five sums a 2D section uses.
  void addPlanar(double y, double force, double stiffness) noexcept {
    p += force;
    mz -= force * y;
    kPP += stiffness;
    kPz -= stiffness * y;
    kzz += stiffness * y * y;
  }
};

/// The fibers of one section that share a material type: coordinates, areas and material states
/// side by side in arrays, updated in one loop. Fiber sections hold one group per material type,
/// so the per-fiber work is a direct (often inlined) call instead of three virtual calls and a
/// small dynamic matrix update (the arrangement style.md sections 8 and 10 ask for).
class FiberGroup {
 public:
  virtual ~FiberGroup() = default;

  int size() const noexcept { return static_cast<int>(geometry_->area.size()); }
  double y(int i) const { return geometry_->y[static_cast<std::size_t>(i)]; }
  double z(int i) const { return geometry_->z[static_cast<std::size_t>(i)]; }
  double area(int i) const { return geometry_->area[static_cast<std::size_t>(i)]; }
  /// Fiber i's trial stress and strain, and the tag of the group's material.
  virtual double stress(int i) const = 0;
  virtual double strain(int i) const = 0;
  virtual int materialTag() const = 0;
  /// Adds a fiber with a clone of `prototype`.
  virtual void add(double y, double z, double area, const UniaxialMaterial& prototype) = 0;
  /// Adds `area` to fiber i: a fiber of the same material at the same strain point (in a plane
  /// section, the same y) has the same strain history, so the two are one fiber of their summed
  /// area (OpenSees evaluates both).
  void addArea(int i, double area) { ownGeometry().area[static_cast<std::size_t>(i)] += area; }

  /// Sets every fiber's trial strain e0 - y kz + z ky and adds the fibers' trial forces and
  /// tangents to `sums`. Returns the last failed status, or Ok; a non-finite fiber stress or
  /// tangent may instead show only as non-finite sums, which the caller checks.
  [[nodiscard]] virtual Status setTrial(double e0, double kz, double ky, FiberSums& sums) = 0;
  /// The same for a 2D section: strains e0 - y kz, and only the sums addPlanar forms.
  [[nodiscard]] virtual Status setTrialPlanar(double e0, double kz, FiberSums& sums) = 0;
  /// Adds the current trial forces and tangents (`initial`: the initial tangents, no forces).
  virtual void addTo(FiberSums& sums, bool initial) const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;
  [[nodiscard]] virtual std::unique_ptr<FiberGroup> clone() const = 0;
  /// True when every fiber's material keeps its state at the same strain
  /// (UniaxialMaterial::keepsStateAtSameStrain).
  virtual bool keepsStateAtSameStrains() const = 0;

  /// A group for `prototype`: for Concrete01/02 and Steel02 one parameter set and arrays of fiber
  /// states (the update is the material's computeTrial, and a fiber costs its two states, not a
  /// whole material object: what bounds large models is memory traffic); for Steel01, Elastic
  /// and ElasticPP an array of material objects; otherwise materials held by pointer.
  static std::unique_ptr<FiberGroup> forMaterial(const UniaxialMaterial& prototype);
  /// True when `material` belongs in this group.
  virtual bool accepts(const UniaxialMaterial& material) const = 0;

 protected:
  /// Coordinates and areas of the fibers. They never change once the section is built, so the
  /// copies of a section (one per integration point and element) share one block: on a model
  /// whose fiber states do not fit in the cache, each pass then streams only the states.
  struct Geometry {
    std::vector<double> y, z, area;
  };
  /// Appends a fiber's geometry.
  void addGeometry(double y, double z, double area) {
    Geometry& g = ownGeometry();
    g.y.push_back(y);
    g.z.push_back(z);
    g.area.push_back(area);
  }
  const Geometry& geometry() const noexcept { return *geometry_; }

 private:
  /// The geometry to change, copied first if another group shares it.
  Geometry& ownGeometry() {
    if (geometry_.use_count() > 1) geometry_ = std::make_shared<Geometry>(*geometry_);
    return *geometry_;
  }
  std::shared_ptr<Geometry> geometry_ = std::make_shared<Geometry>();
};

}  // namespace dabs::materials::section
