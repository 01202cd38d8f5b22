// SPDX-License-Identifier: MIT
#include "tcl/domain/RectangularSeries.h"

namespace dabs::domain {

std::string RectangularSeries::describe() const {
  return "Rectangular tStart " + std::to_string(tStart_) + " tEnd " + std::to_string(tEnd_) +
         " factor " + std::to_string(factor_);
}

}  // namespace dabs::domain
