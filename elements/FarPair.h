// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>

namespace dabs::elements {

/// What the analysis reads of an element that may sleep while far from contact (Element::farPair;
/// the analysis' SleepingPairs). The glossary of this optimisation: two terms, used with these
/// meanings in the code, the READMEs, the docs and the results files.
/// - far: the pair's distance lower bound ("bound") exceeds its search distance, so it adds no
///   force and no stiffness. A pair "far in both states" has its trial and committed states far,
///   quiet and equal but for the gap, so a step changes its gap alone.
/// - sleeping: a far pair the analysis leaves out of the matrix pattern and the iterations and
///   tests by its bound alone once per converged step. It wakes when found near. When every
///   sleeping pair against a target face is far in both states and read by nobody, the face's
///   test is deferred until the nodes could have moved far enough to bring one of its pairs
///   within its search distance (its horizon); meanwhile the domain keeps their states.
///
/// The pair is a contactor node (element node 1) against a four-node target face (element nodes
/// 2 to 5), the shape the analysis' broad phase groups by face. The analysis holds pointers to
/// this interface only while the element lives in the domain; it never owns one.
class FarPair {
 public:
  /// The data of the far test, copied once per matrix pattern into the analysis' own arrays.
  struct Geometry {
    std::array<Eigen::Vector3d, 5> X{};  ///< reference coordinates (contactor, then face nodes)
    Eigen::Vector3d n = Eigen::Vector3d::Zero();  ///< outward unit normal of the target face
    double distance = std::numeric_limits<double>::infinity();  ///< search distance (length)
  };

  /// The far test's data (reference geometry, normal, search distance).
  virtual Geometry farGeometry() const = 0;
  /// The pair's whole far test with its nodes' translations `u` (contactor, then face nodes,
  /// global frame): true when far, with the distance lower bound written to `bound`; false for
  /// non-finite positions. The same arithmetic as the element's own test, so the bound is the gap
  /// the element reports, to the bit.
  virtual bool isFarAt(const std::array<Eigen::Vector3d, 5>& u, double& bound) const = 0;
  /// True when the pair was far in the last committed state.
  virtual bool committedFar() const = 0;
  /// True when the trial state is farther than `factor` x the search distance.
  virtual bool trialFarBeyond(double factor) const = 0;
  /// True while the pair is far in both states (see the glossary above).
  virtual bool farInBothStates() const = 0;
  /// Sets the trial state of a far pair whose far test the caller made (distance bound `bound`,
  /// step `dt`) and returns true; changes nothing and returns false when the step must be
  /// evaluated by update() (a release step, or no search distance).
  virtual bool setFarTrial(double bound, double dt) = 0;
  /// Sets the gap of a far in both states pair in both states to `bound` (the analysis forms it
  /// anew for a pair it left alone for some steps); false, changing nothing, when not far in both
  /// states.
  virtual bool setGapInBothStates(double bound) = 0;

  /// Top of the slab the bilinear face lies in along the unit vector n: its highest corner,
  /// max_i n.x_i. Pairs that share a target face share it, so a broad phase over many contactors
  /// forms it once per face. Defined here, once, for the element's own test and the analysis'.
  static double slabTop(const std::array<Eigen::Vector3d, 4>& quad,
                        const Eigen::Vector3d& n) noexcept {
    double top = n.dot(quad[0]);
    for (std::size_t i = 1; i < 4; ++i) top = std::max(top, n.dot(quad[i]));
    return top;
  }
  /// Slab bound of a contactor against a face with slabTop `top`: its height n.x - top above the
  /// face's highest corner (only the outward side counts; behind the face is penetration).
  static double slabBound(const Eigen::Vector3d& contactor, const Eigen::Vector3d& n,
                          double top) noexcept {
    return n.dot(contactor) - top;
  }

 protected:
  FarPair() = default;
  FarPair(const FarPair&) = default;
  FarPair& operator=(const FarPair&) = default;
  /// Not deleted through this interface: the domain owns the element.
  ~FarPair() = default;
};

}  // namespace dabs::elements
