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
  ElementRecorder(RecorderOutput output, std::vector<int> elements,
                  std::vector<std::string> response);
  void initialize(const Domain& domain) override;
  void elementsRead(std::vector<int>& tags) const override {
    tags.insert(tags.end(), elements_.begin(), elements_.end());
  }

 protected:
  void values(const Domain& domain, std::vector<double>& out) override;

 private:
  std::vector<int> elements_;
  std::vector<std::string> response_;
  std::vector<Eigen::Index> sizes_;
};
}  // namespace dabs::domain
