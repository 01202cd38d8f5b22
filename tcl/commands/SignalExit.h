// SPDX-License-Identifier: MIT
#pragma once

namespace dabs::tcl {

struct Runtime;

/// Installs the dabs program's handler of SIGTERM, SIGINT and SIGHUP (see analysis::StopRequest).
/// Only the program calls it; the loadable package leaves the host's signals alone.
void installSignalExit();

/// Closes every recorder of `rt` (writing what they still hold) and exits the program with status
/// 128 + `signal`, the shell's convention for a program ended by a signal.
[[noreturn]] void exitOnSignal(Runtime& rt, int signal);

}  // namespace dabs::tcl
