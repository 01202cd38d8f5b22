// SPDX-License-Identifier: MIT
#include "tcl/domain/LinearSeries.h"

namespace dabs::domain {

std::string LinearSeries::describe() const { return "Linear factor " + std::to_string(factor_); }

}  // namespace dabs::domain
