// SPDX-License-Identifier: MIT
#include "tcl/commands/BearingFailureReport.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "tcl/analysis/driver/AnalysisBuilder.h"

namespace dabs::tcl {

int BearingFailureReport::afterCommit(const domain::Domain& domain,
                                      analysis::StepContext& context) {
  using elements::YoshidaBearing3d;
  if (bearingsOf_ != domain.modelVersion()) {
    bearings_.clear();
    for (const auto& [tag, e] : domain.elements())
      if (const auto* b = dynamic_cast<const YoshidaBearing3d*>(e.get()))
        bearings_.emplace_back(tag, b);
    bearingsOf_ = domain.modelVersion();
  }
  bool stop = false;
  for (const auto& [tag, b] : bearings_) {
    reportBuckling(tag, *b, domain.committedTime(), context);
    if (!b->committedState().failed) {
      reported_.erase(tag);  // back to start (reset): a new failure is reported again
      continue;
    }
    if (reported_.count(tag) != 0) continue;
    reported_.insert(tag);
    ++context.statistics.failedBearings;
    const auto mode = b->params().afterFailure;
    if (context.log) {
      char text[256];
      std::snprintf(
          text, sizeof text,
          "yoshidaBearing %d reached its failure shear strain %g at time %g; -afterFailure %s: %s",
          tag, b->params().failureLimit, b->committedState().failureTime,
          YoshidaBearing3d::afterFailureName(mode),
          mode == YoshidaBearing3d::AfterFailure::Keep
              ? "it goes on carrying load as if intact (the rubber has ruptured in reality)"
          : mode == YoshidaBearing3d::AfterFailure::Release ? "it carries no shear from now on"
          : mode == YoshidaBearing3d::AfterFailure::Drop
              ? "the rubber carries nothing from now on; the girder end comes down onto its seat"
              : "the analysis stops here with code -5");
      context.log(text);
    }
    stop = stop || mode == YoshidaBearing3d::AfterFailure::Stop;
  }
  return stop ? analysis::kBearingFailureStop : 0;
}

void BearingFailureReport::reportBuckling(int tag, const elements::YoshidaBearing3d& b, double time,
                                          analysis::StepContext& context) {
  constexpr int kBuckledBranch = 3;  // KumarVertical::State::branch
  const elements::KumarVertical* law = b.verticalLaw();
  if (law == nullptr) return;
  if (b.committedState().vertical.branch != kBuckledBranch) {
    buckled_.erase(tag);
    return;
  }
  if (!buckled_.insert(tag).second) return;
  ++context.statistics.buckledBearings;
  if (!context.log) return;
  // The element's local basic deformation: axial first, then the two shear offsets.
  const auto d = b.response(std::vector<std::string>{"basicDeformation"});
  const auto q = b.response(std::vector<std::string>{"basicForce"});
  const double uh = d ? std::hypot((*d)(1), (*d)(2)) : 0.0;
  char text[256];
  std::snprintf(text, sizeof text,
                "yoshidaBearing %d buckled at time %g: axial compression %g reached its critical "
                "load %g at a shear offset of %g",
                tag, time, q ? -(*q)(0) : 0.0, law->criticalLoad(uh), uh);
  context.log(text);
}

}  // namespace dabs::tcl
