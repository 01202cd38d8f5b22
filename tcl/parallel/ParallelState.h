// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <memory>

#include "tcl/parallel/Communicator.h"

namespace dabs::parallel {

/// What the parallel commands of one interpreter share, kept with the interpreter (Tcl's
/// associated data, deleted with it): the channel of the script's own messages, the job farm's
/// separate channel, and whether an ensemble job is running.
struct ParallelState {
  std::unique_ptr<Communicator> messages;  ///< send, recv, barrier, Bcast
  std::unique_ptr<Communicator> farm;      ///< the job farm's messages only
  bool inJob = false;                      ///< an ensemble job is running on this process

  /// The state of `interp`; created for one process on first use.
  static ParallelState& of(Tcl_Interp* interp);
  /// Replaces the communicators of `interp` (collective in the MPI program).
  static void set(Tcl_Interp* interp, std::unique_ptr<Communicator> comm);
};

}  // namespace dabs::parallel
