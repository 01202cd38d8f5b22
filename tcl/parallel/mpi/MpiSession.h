// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

namespace dabs::parallel {

/// Starts MPI for the dabs-mp program (first thing in main; MPI may take its own arguments out of
/// argc/argv). Asks for MPI_THREAD_SERIALIZED, which the job farm's dispatcher thread needs.
void startMpi(int* argc, char*** argv);

/// Gives `interp` MPI's world for the parallel commands and ends MPI with the program: Tcl's exit
/// runs the exit handlers (recorders are closed), then MPI_Finalize on a zero status, or
/// MPI_Abort on a non-zero status when there are other processes (a script error on one process
/// ends the whole run instead of leaving the others waiting for it). Collective.
int attachMpi(Tcl_Interp* interp);

}  // namespace dabs::parallel
