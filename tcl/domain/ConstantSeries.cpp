// SPDX-License-Identifier: MIT
#include "tcl/domain/ConstantSeries.h"

namespace dabs::domain {

std::string ConstantSeries::describe() const {
  return "Constant factor " + std::to_string(factor_);
}

}  // namespace dabs::domain
