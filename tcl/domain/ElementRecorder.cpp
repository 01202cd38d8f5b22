// SPDX-License-Identifier: MIT
#include "tcl/domain/ElementRecorder.h"

#include <cmath>

#include "materials/InputError.h"
#include "tcl/domain/Domain.h"

namespace dabs::domain {

ElementRecorder::ElementRecorder(RecorderOutput output, std::vector<int> elements,
                                 std::vector<std::string> response)
    : ResponseRecorder(std::move(output)),
      elements_(std::move(elements)),
      response_(std::move(response)) {}

void ElementRecorder::initialize(const Domain& domain) {
  if (response_.empty())
    throw InputError("response", "is missing (e.g. force, localForce, deformation)");
  sizes_.clear();
  for (int tag : elements_) {
    const elements::Element* e = domain.findElement(tag);
    if (e == nullptr)
      throw InputError("-ele", "element " + std::to_string(tag) + " does not exist");
    const auto r = domain.elementResponse(tag, response_);
    if (!r) {
      std::string what;
      for (const auto& w : response_) what += (what.empty() ? "" : " ") + w;
      throw InputError("response", "\"" + what + "\" is not a response of element " +
                                       std::to_string(tag) + " (" + std::string(e->typeName()) +
                                       ")");
    }
    sizes_.push_back(r->size());
  }
}

void ElementRecorder::values(const Domain& domain, std::vector<double>& out) {
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    const elements::Element* e = domain.findElement(elements_[k]);
    std::optional<Eigen::VectorXd> r;
    if (e != nullptr) r = domain.elementResponse(elements_[k], response_);
    for (Eigen::Index i = 0; i < sizes_[k]; ++i) out.push_back(r && i < r->size() ? (*r)(i) : 0.0);
  }
}

}  // namespace dabs::domain
