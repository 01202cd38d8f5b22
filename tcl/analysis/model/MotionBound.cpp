// SPDX-License-Identifier: MIT
#include "tcl/analysis/model/MotionBound.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dabs::analysis {

void MotionBound::clear() {
  groups_.clear();
  eqs_.clear();
  slots_.clear();
  eqValues_.clear();
  slotValues_.clear();
}

void MotionBound::beginGroup() {
  Group g;
  g.eqBegin = g.eqEnd = static_cast<std::uint32_t>(eqs_.size());
  g.slotBegin = g.slotEnd = static_cast<std::uint32_t>(slots_.size());
  groups_.push_back(g);
}

void MotionBound::addEquation(int eq) {
  Group& g = groups_.back();
  eqs_.push_back(eq);
  g.gainEq = std::max(g.gainEq, 1.0);
}

void MotionBound::addTranslation(std::span<const DofTerm> terms) {
  Group& g = groups_.back();
  double eqGain = 0.0, slotGain = 0.0;
  for (const DofTerm& t : terms) {
    if (t.index >= 0) {
      eqGain += std::abs(t.coef);
      eqs_.push_back(t.index);
    } else {
      slotGain += std::abs(t.coef);
      slots_.push_back(-t.index - 1);
    }
  }
  g.gainEq = std::max(g.gainEq, eqGain);
  g.gainSlot = std::max(g.gainSlot, slotGain);
}

void MotionBound::endGroup() {
  Group& g = groups_.back();
  auto unique = [](std::vector<int>& v, std::uint32_t begin) {
    std::sort(v.begin() + begin, v.end());
    v.erase(std::unique(v.begin() + begin, v.end()), v.end());
    return static_cast<std::uint32_t>(v.size());
  };
  g.eqEnd = unique(eqs_, g.eqBegin);
  g.slotEnd = unique(slots_, g.slotBegin);
  eqValues_.resize(eqs_.size(), 0.0);
  slotValues_.resize(slots_.size(), 0.0);
}

void MotionBound::snapshot(std::size_t gi, const Eigen::VectorXd& U,
                           std::span<const SupportSlot> slots) {
  const Group& g = groups_[gi];
  for (std::uint32_t k = g.eqBegin; k < g.eqEnd; ++k) eqValues_[k] = U(eqs_[k]);
  for (std::uint32_t k = g.slotBegin; k < g.slotEnd; ++k)
    slotValues_[k] = slots[static_cast<std::size_t>(slots_[k])].disp;
}

double MotionBound::moved(std::size_t gi, const Eigen::VectorXd& U,
                          std::span<const SupportSlot> slots) const {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const Group& g = groups_[gi];
  // The largest changes since the snapshot (a NaN or infinite one: no bound).
  double eqMax = 0.0, slotMax = 0.0;
  bool finite = true;
  for (std::uint32_t k = g.eqBegin; k < g.eqEnd; ++k) {
    const double change = std::abs(U(eqs_[k]) - eqValues_[k]);
    finite = finite && change < kInfinity;
    eqMax = std::max(eqMax, change);
  }
  for (std::uint32_t k = g.slotBegin; k < g.slotEnd; ++k) {
    const double change =
        std::abs(slots[static_cast<std::size_t>(slots_[k])].disp - slotValues_[k]);
    finite = finite && change < kInfinity;
    slotMax = std::max(slotMax, change);
  }
  // The factor covers the round-off of the sums.
  const double bound = std::sqrt(3.0) * (g.gainEq * eqMax + g.gainSlot * slotMax) * (1.0 + 1e-9);
  return finite ? bound : kInfinity;
}

MotionBound::Saved MotionBound::save(std::size_t gi) const {
  const Group& g = groups_[gi];
  return Saved{{eqs_.begin() + g.eqBegin, eqs_.begin() + g.eqEnd},
               {slots_.begin() + g.slotBegin, slots_.begin() + g.slotEnd},
               g.gainEq,
               g.gainSlot,
               {eqValues_.begin() + g.eqBegin, eqValues_.begin() + g.eqEnd},
               {slotValues_.begin() + g.slotBegin, slotValues_.begin() + g.slotEnd}};
}

bool MotionBound::restore(std::size_t gi, const Saved& saved) {
  const Group& g = groups_[gi];
  if (!std::equal(saved.eqs.begin(), saved.eqs.end(), eqs_.begin() + g.eqBegin,
                  eqs_.begin() + g.eqEnd) ||
      !std::equal(saved.slots.begin(), saved.slots.end(), slots_.begin() + g.slotBegin,
                  slots_.begin() + g.slotEnd) ||
      saved.gainEq != g.gainEq || saved.gainSlot != g.gainSlot)
    return false;
  std::copy(saved.eqValues.begin(), saved.eqValues.end(), eqValues_.begin() + g.eqBegin);
  std::copy(saved.slotValues.begin(), saved.slotValues.end(), slotValues_.begin() + g.slotBegin);
  return true;
}

}  // namespace dabs::analysis
