// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/algorithms/SolutionAlgorithm.h"

namespace dabs::analysis {

/// One solve per step, no convergence test (`algorithm Linear ?-initial? ?-factorOnce?`). The
/// matrix is factorised once and reused while the step size and the (linear) model do not change,
/// or always after the first step with -factorOnce.
class LinearAlgorithm final : public SolutionAlgorithm {
 public:
  LinearAlgorithm(bool initial, bool factorOnce) : initial_(initial), factorOnce_(factorOnce) {}
  Status solveCurrentStep(LinearSystem& system, Integrator& integrator,
                          ConvergenceTest* test) override;
  bool needsTest() const override { return false; }

 private:
  bool initial_;
  bool factorOnce_;
  bool factoredOnce_ = false;
};

}  // namespace dabs::analysis
