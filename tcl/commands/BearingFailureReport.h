// SPDX-License-Identifier: MIT
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "elements/link/YoshidaBearing3d.h"
#include "tcl/analysis/driver/StepObserver.h"

namespace dabs::tcl {

/// The rupture report of `yoshidaBearing` elements, a step observer the `element yoshidaBearing`
/// command registers once per interpreter: after each committed step, each bearing that reached
/// its failure shear strain in it is counted in analysisStatistics' failedBearings and said once
/// on the analysis' log (stderr), and a bearing with `-afterFailure stop` stops `analyze` with
/// kBearingFailureStop. A bearing back at its start (reset) that fails again is reported again.
/// Likewise a bearing with the Kumar vertical law (`-vertical kumar`, buckling on) whose axial
/// compression reached its critical load Pcr(u) in the step (its law's buckled branch) is counted
/// in buckledBearings and said once, with the load, Pcr and the shear offset; once more only
/// after it has left the buckled branch and reached it again.
class BearingFailureReport final : public analysis::StepObserver {
 public:
  int afterCommit(const domain::Domain& domain, analysis::StepContext& context) override;

 private:
  void reportBuckling(int tag, const elements::YoshidaBearing3d& b, double time,
                      analysis::StepContext& context);
  std::set<int> reported_;  ///< tags of the failed bearings already reported
  std::set<int> buckled_;   ///< tags of the bearings reported buckled, still on that branch
  /// The domain's bearings in tag order, found once per model version (a test per element per
  /// step costs as much as a far contact pair's check).
  std::vector<std::pair<int, const elements::YoshidaBearing3d*>> bearings_;
  long bearingsOf_ = -1;  ///< the domain's modelVersion bearings_ is of
};

}  // namespace dabs::tcl
