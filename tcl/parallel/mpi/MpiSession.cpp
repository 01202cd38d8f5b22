// SPDX-License-Identifier: MIT
#include "tcl/parallel/mpi/MpiSession.h"

#include <mpi.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "tcl/parallel/ParallelCommands.h"
#include "tcl/parallel/mpi/MpiCommunicator.h"

namespace dabs::parallel {

namespace {

// Replaces exit() for Tcl_Exit: Tcl calls it with the status instead of running its exit handlers.
[[noreturn]] void exitMpi(ClientData data) {
  const int status = static_cast<int>(reinterpret_cast<std::intptr_t>(data));
  Tcl_Finalize();  // exit handlers: recorders written and closed
  std::fflush(nullptr);
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (status != 0 && size > 1) MPI_Abort(MPI_COMM_WORLD, status);
  MPI_Finalize();
  std::exit(status);
}

}  // namespace

void startMpi(int* argc, char*** argv) {
  int provided = MPI_THREAD_SINGLE;
  MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
}

int attachMpi(Tcl_Interp* interp) {
  int provided = MPI_THREAD_SINGLE;
  MPI_Query_thread(&provided);
  setCommunicator(interp, std::make_unique<MpiCommunicator>(MPI_COMM_WORLD, false,
                                                            provided >= MPI_THREAD_SERIALIZED));
  Tcl_SetExitProc(exitMpi);
  return TCL_OK;
}

}  // namespace dabs::parallel
