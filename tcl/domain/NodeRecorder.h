// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <vector>

#include "tcl/domain/ResponseRecorder.h"
#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// `recorder Node|EnvelopeNode`: one column per node and dof (nodes in the order given, dofs in
/// -dof order) of disp, vel, accel, incrDisp, reaction or eigen i.
class NodeRecorder final : public ResponseRecorder {
 public:
  enum class Response { Disp, Vel, Accel, IncrDisp, Reaction, Eigen };
  /// dofs are 0-based; `mode` (1-based) for Eigen; `series` (one per dof or empty) are added to the
  /// values, e.g. ground acceleration for absolute accelerations (-timeSeries).
  NodeRecorder(RecorderOutput output, std::vector<int> nodes, std::vector<int> dofs,
               Response response, int mode, std::vector<std::shared_ptr<const TimeSeries>> series);
  void initialize(const Domain& domain) override;
  bool needsReactions() const override { return response_ == Response::Reaction; }

 protected:
  void values(const Domain& domain, std::vector<double>& out) override;

 private:
  std::vector<int> nodes_;
  std::vector<int> dofs_;
  Response response_;
  int mode_;
  std::vector<std::shared_ptr<const TimeSeries>> series_;
  std::vector<double> lastDisp_;  // for incrDisp: displacement at the previous record
};

}  // namespace dabs::domain
