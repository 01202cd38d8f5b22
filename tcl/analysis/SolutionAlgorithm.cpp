// SPDX-License-Identifier: MIT
#include "tcl/analysis/SolutionAlgorithm.h"

namespace dabs::analysis {

bool SolutionAlgorithm::holdStatusesIfDue(LinearSystem& system) {
  if (iterations_ != kHoldAfter) return false;
  return system.model().holdStatuses();
}

SolutionAlgorithm::Settled SolutionAlgorithm::settleStatuses(LinearSystem& system,
                                                             const AssemblyCoefficients& c) {
  switch (system.model().checkHeldStatuses()) {
    case elements::Element::HeldStatus::Agrees: return Settled::Converged;
    case elements::Element::HeldStatus::Conflict: return Settled::Failed;
    case elements::Element::HeldStatus::Switched: break;
  }
  if (!ok(system.model().updateElements())) return Settled::Failed;
  system.formResidual(c);
  return Settled::IterateOn;
}

}  // namespace dabs::analysis
