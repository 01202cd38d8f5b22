// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "tcl/domain/ResponseRecorder.h"

namespace dabs::domain {

/// `recorder Drift -iNode .. -jNode .. -dof .. -perpDirn ..`: (u_j - u_i) / (x_j - x_i) along the
/// perpendicular direction, one column per node pair.
class DriftRecorder final : public ResponseRecorder {
 public:
  DriftRecorder(RecorderOutput output, std::vector<int> iNodes, std::vector<int> jNodes,
                std::vector<int> dofs, std::vector<int> perpDirns);
  void initialize(const Domain& domain) override;

 protected:
  void values(const Domain& domain, std::vector<double>& out) override;

 private:
  std::vector<int> iNodes_, jNodes_, dofs_, perp_;
  std::vector<double> lengths_;
};

}  // namespace dabs::domain
