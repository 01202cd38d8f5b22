// SPDX-License-Identifier: MIT
#include "tcl/analysis/driver/StopRequest.h"

namespace dabs::analysis {

volatile std::sig_atomic_t StopRequest::signal = 0;
volatile std::sig_atomic_t StopRequest::stepLoopRunning = 0;

}  // namespace dabs::analysis
