// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/SolutionAlgorithm.h"

namespace dabs::analysis {

SolutionAlgorithm::Next SolutionAlgorithm::afterTest(ConvergenceTest::Result result,
                                                     LinearSystem& system,
                                                     const AssemblyCoefficients& c) {
  heldNow_ = iterations_ == kHoldAfter && system.model().holdStatuses();
  if (result == ConvergenceTest::Result::Failed) return Next::Failed;
  if (result == ConvergenceTest::Result::Continue) return Next::IterateOn;
  switch (system.model().checkHeldStatuses()) {
    case elements::Element::HeldStatus::Agrees: return Next::Converged;
    case elements::Element::HeldStatus::Conflict: return Next::Failed;
    case elements::Element::HeldStatus::Switched: break;
  }
  if (!ok(system.model().updateElements())) return Next::Failed;
  system.formResidual(c);
  return Next::Switched;
}

}  // namespace dabs::analysis
