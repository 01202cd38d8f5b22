// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "tcl/analysis/model/ConstraintHandler.h"

namespace dabs::analysis {

/// Bounds how far the nodes of a group moved since the group's snapshot, from the equations and
/// support slots their translations are formed from (the deferred faces of SleepingPairs:
/// sleeping contact pairs: a group is a face's nodes and its contactors). A translation formed as
/// sum c_i x_i over equations and slots moved by at most sum |c_i| times the largest change of
/// its x_i, and a node (three translations) by sqrt(3) times the largest of those.
class MotionBound {
 public:
  /// Forgets every group.
  void clear();
  /// Starts a group (its index is the number of groups before it).
  void beginGroup();
  /// Adds a translation of the last group: one equation (coefficient 1) ...
  void addEquation(int eq);
  /// ... or a combination of equations (index >= 0) and slots (index -slot - 1).
  void addTranslation(std::span<const DofTerm> terms);
  /// Ends the last group (its equations and slots sorted, each once).
  void endGroup();
  std::size_t groups() const noexcept { return groups_.size(); }

  /// The group's equations' and slots' values now: what moved() measures from.
  void snapshot(std::size_t g, const Eigen::VectorXd& U, std::span<const SupportSlot> slots);
  /// Bound on how far a node of the group moved since its snapshot (m); infinity when a change is
  /// not finite.
  double moved(std::size_t g, const Eigen::VectorXd& U, std::span<const SupportSlot> slots) const;

  /// A group's terms and snapshot, to carry over a rebuild that numbers the same equations.
  struct Saved {
    std::vector<int> eqs, slots;
    double gainEq = 0.0, gainSlot = 0.0;
    std::vector<double> eqValues, slotValues;
  };
  Saved save(std::size_t g) const;
  /// Takes the snapshot back when group g has the same terms; false (nothing changed) otherwise.
  bool restore(std::size_t g, const Saved& saved);

 private:
  struct Group {
    std::uint32_t eqBegin = 0, eqEnd = 0, slotBegin = 0, slotEnd = 0;
    double gainEq = 0.0, gainSlot = 0.0;  // largest sum of |coefficients| of a translation
  };
  std::vector<Group> groups_;
  std::vector<int> eqs_, slots_;               // the groups' terms, group by group
  std::vector<double> eqValues_, slotValues_;  // at each group's snapshot
};

}  // namespace dabs::analysis
