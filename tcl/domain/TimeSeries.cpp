// SPDX-License-Identifier: MIT
#include "tcl/domain/TimeSeries.h"

#include <limits>

namespace dabs::domain {

double TimeSeries::duration() const { return std::numeric_limits<double>::infinity(); }
double TimeSeries::samplingInterval() const { return 0.01; }

}  // namespace dabs::domain
