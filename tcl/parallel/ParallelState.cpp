// SPDX-License-Identifier: MIT
#include "tcl/parallel/ParallelState.h"

#include "tcl/parallel/SerialCommunicator.h"

namespace dabs::parallel {

namespace {

constexpr const char* kKey = "dabs::parallel";

void deleteState(ClientData data, Tcl_Interp* /*interp*/) {
  delete static_cast<ParallelState*>(data);
}

ParallelState* find(Tcl_Interp* interp) {
  return static_cast<ParallelState*>(Tcl_GetAssocData(interp, kKey, nullptr));
}

}  // namespace

ParallelState& ParallelState::of(Tcl_Interp* interp) {
  if (ParallelState* state = find(interp)) return *state;
  set(interp, std::make_unique<SerialCommunicator>());
  return *find(interp);
}

void ParallelState::set(Tcl_Interp* interp, std::unique_ptr<Communicator> comm) {
  auto state = std::make_unique<ParallelState>();
  state->farm = comm->duplicate();
  state->messages = std::move(comm);
  if (ParallelState* old = find(interp)) delete old;
  Tcl_SetAssocData(interp, kKey, deleteState, state.release());
}

}  // namespace dabs::parallel
