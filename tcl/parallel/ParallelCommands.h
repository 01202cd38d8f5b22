// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <memory>
#include <span>

#include "tcl/commands/Registry.h"
#include "tcl/parallel/Communicator.h"

namespace dabs::parallel {

/// The commands of OpenSeesMP (getPID, getNP, barrier, send, recv, Bcast) and the job farm
/// (`ensemble run`). In the serial program they act for one process (getPID 0, getNP 1); in the
/// MPI program (dabs-mp) for the processes started by mpirun or srun.
std::span<const tcl::CommandEntry> parallelCommands();

/// Gives `interp` the communicator its parallel commands use (the MPI program calls it once at
/// start-up; without it the commands act for one process). Collective in the MPI program.
void setCommunicator(Tcl_Interp* interp, std::unique_ptr<Communicator> comm);

}  // namespace dabs::parallel
