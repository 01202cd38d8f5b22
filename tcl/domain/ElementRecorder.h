// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "tcl/domain/ResponseRecorder.h"

namespace dabs::domain {

/// `recorder Element|EnvelopeElement`: the concatenated response vectors of the elements, in the
/// order given. Unlike OpenSees, which writes nothing for an element that lacks the response,
/// an unknown response is an input error when the recorder is created.
class ElementRecorder final : public ResponseRecorder {
 public:
  ElementRecorder(RecorderOutput output, std::vector<int> elements, std::vector<std::string> response);
  void initialize(const Domain& domain) override;

 protected:
  void values(const Domain& domain, std::vector<double>& out) override;

 private:
  std::vector<int> elements_;
  std::vector<std::string> response_;
  std::vector<Eigen::Index> sizes_;
};

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
