// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <string>

#include "tcl/domain/Domain.h"

namespace dabs::analysis {

struct AnalysisStatistics;

/// What a step observer may touch after a committed step: the analysis' counters (an observer
/// adds its own, e.g. failedBearings) and the analysis' log (one line per call; null when no one
/// listens).
struct StepContext {
  AnalysisStatistics& statistics;
  const std::function<void(const std::string&)>& log;
};

/// Something outside the solver that watches the analysis step by step (registered with
/// AnalysisBuilder::addStepObserver): a bearing that reports its rupture, say. The engine stays
/// general; an element type's reporting lives with the code that defines the element, not in the
/// step loop.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Called once after each step `analyze` commits (each of contact stepping's steps; a step
  /// recovered by sub-stepping once, after its sub-steps), before the recorders' error check and
  /// the script after each step, with the domain in its committed state; never after a step that
  /// failed. Returns 0 to go on, or the (negative) code with which `analyze` stops after this step.
  virtual int afterCommit(const domain::Domain& domain, StepContext& context) = 0;
};

}  // namespace dabs::analysis
