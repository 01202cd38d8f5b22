// SPDX-License-Identifier: MIT
#pragma once

#include <csignal>

namespace dabs::analysis {

/// A request to end the program, set by the dabs program's handler of SIGTERM, SIGINT and SIGHUP.
/// Signals belong to the process, not to an interpreter, so this is process-wide state. While a
/// step loop runs (`stepLoopRunning`), the handler only records the signal; the loop stops after
/// the step in progress commits, and the `analyze` command then closes every recorder and exits
/// with status 128 + signal. A second signal, or one outside a step loop, ends the program at once:
/// recorders have already handed every committed step to the operating system.
struct StopRequest {
  static volatile std::sig_atomic_t signal;  ///< the signal received, 0 when none
  static volatile std::sig_atomic_t
      stepLoopRunning;  ///< 1 while AnalysisBuilder::analyze runs steps
};

}  // namespace dabs::analysis
