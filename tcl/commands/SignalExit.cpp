// SPDX-License-Identifier: MIT
#include "tcl/commands/SignalExit.h"

#include <tcl.h>
#include <unistd.h>

#include <csignal>

#include "tcl/analysis/driver/StopRequest.h"
#include "tcl/commands/Runtime.h"

namespace dabs::tcl {

namespace {

constexpr int kExitBySignal = 128;

// Async-signal-safe: only sig_atomic_t stores and _exit.
void onSignal(int signal) {
  using analysis::StopRequest;
  if (StopRequest::stepLoopRunning != 0 && StopRequest::signal == 0) {
    StopRequest::signal = signal;
    return;
  }
  _exit(kExitBySignal + signal);
}

}  // namespace

void installSignalExit() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int signal : {SIGTERM, SIGINT, SIGHUP}) sigaction(signal, &action, nullptr);
}

void exitOnSignal(Runtime& rt, int signal) {
  try {
    rt.domain.removeAllRecorders();
  } catch (...) {
    // The rows of every committed step are already written; a last failure changes nothing.
  }
  Tcl_Exit(kExitBySignal + signal);
  _exit(kExitBySignal + signal);
}

}  // namespace dabs::tcl
