// SPDX-License-Identifier: MIT
// OpenSeesMP's commands for the processes of a run (OpenSees: SRC/tcl/commands.cpp getPID, getNP,
// opsBarrier, opsSend, opsRecv; SRC/interpreter/OpenSeesMiscCommands.cpp OPS_Bcast):
//   getPID                      this process's number, 0 ... getNP - 1
//   getNP                       number of processes
//   barrier                     waits until every process has reached it
//   send -pid p value           sends value to process p (not this one)
//   send value                  process 0 only: to every other process, each taking it with `recv
//   varName` recv -pid p|ANY varName     waits for a value from p (or any process), sets varName to
//   it and
//                               returns the sender's number (OpenSees returns nothing)
//   recv varName                processes other than 0: takes the value process 0 sent with `send
//   value` Bcast ?value ...?           collective: every process returns process 0's value(s)
//   (OpenSees
//                               returns them on the other processes only)
#include "tcl/parallel/ParallelCommands.h"

#include <string>

#include "tcl/parallel/EnsembleCommand.h"
#include "tcl/parallel/ParallelState.h"

namespace dabs::parallel {

namespace {

using tcl::ArgReader;
using tcl::Runtime;

// Tag of the script's own point-to-point messages.
constexpr int kMessageTag = 0;

Communicator& messages(Runtime& rt, ArgReader& a) {
  ParallelState& state = ParallelState::of(rt.interp);
  if (state.inJob)
    a.fail(
        "not available inside an ensemble job (jobs are independent; process 0 collects results)");
  return *state.messages;
}

void setInt(Runtime& rt, int value) { Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(value)); }

// Reads the process number after -pid: another process than this one, or any (-1) when `any`.
int readPid(ArgReader& a, const Communicator& comm, const std::string& token, bool any) {
  if (any && (token == "ANY" || token == "ANY_SOURCE" || token == "MPI_ANY_SOURCE"))
    return Communicator::kAnySource;
  const std::string range = comm.size() == 1 ? " other than this process, the only one (getNP is 1)"
                                             : " from 0 to " + std::to_string(comm.size() - 1) +
                                                   " other than this process (" +
                                                   std::to_string(comm.rank()) + ")";
  std::size_t used = 0;
  int pid = -1;
  try {
    pid = std::stoi(token, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != token.size() || token.empty() || pid < 0 || pid >= comm.size() || pid == comm.rank())
    a.fail(std::string("-pid expected a process number") + (any ? " or ANY" : "") + range +
           ", got \"" + token + "\"");
  return pid;
}

void getPIDCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  setInt(rt, ParallelState::of(rt.interp).messages->rank());
}

void getNPCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  setInt(rt, ParallelState::of(rt.interp).messages->size());
}

void barrierCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  messages(rt, a).barrier();
}

void sendCmd(Runtime& rt, ArgReader& a) {
  Communicator& comm = messages(rt, a);
  const std::optional<std::string> pidWord = a.optionalWordOption("-pid");
  const std::string value = Tcl_GetString(a.object("value"));
  a.finish();
  if (pidWord) {
    comm.send(readPid(a, comm, *pidWord, false), kMessageTag, value);
    return;
  }
  if (comm.rank() != 0)
    a.fail(
        "without -pid only process 0 sends (to every other process, which takes it with "
        "`recv varName`); this is process " +
        std::to_string(comm.rank()));
  comm.broadcast(value, 0);
}

void recvCmd(Runtime& rt, ArgReader& a) {
  Communicator& comm = messages(rt, a);
  const std::optional<std::string> pidWord = a.optionalWordOption("-pid");
  Tcl_Obj* var = a.object("varName");
  a.finish();
  Communicator::Message message;
  if (pidWord) {
    const int source = readPid(a, comm, *pidWord, true);
    if (comm.size() == 1)
      a.fail("-pid " + *pidWord + ": there is no other process to receive from (getNP is 1)");
    message = comm.receive(source, kMessageTag);
  } else {
    if (comm.rank() == 0)
      a.fail(
          "without -pid a process takes what process 0 sent with `send value`; process 0 "
          "cannot receive from itself");
    message.text = comm.broadcast(std::string(), 0);
    message.source = 0;
  }
  Tcl_Obj* value = Tcl_NewStringObj(message.text.data(), static_cast<int>(message.text.size()));
  if (Tcl_ObjSetVar2(rt.interp, var, nullptr, value, TCL_LEAVE_ERR_MSG) == nullptr)
    a.fail(std::string("cannot set variable \"") + Tcl_GetString(var) +
           "\": " + Tcl_GetStringResult(rt.interp));
  setInt(rt, message.source);
}

void bcastCmd(Runtime& rt, ArgReader& a) {
  Communicator& comm = messages(rt, a);
  std::string value;
  if (comm.rank() == 0) {
    if (!a.hasMore()) a.fail(1, "value", "expected a value on process 0, got nothing");
    std::vector<Tcl_Obj*> values;
    while (a.hasMore()) values.push_back(a.object("value"));
    // One value goes as it is; several as a Tcl list (OpenSees sends several numbers).
    Tcl_Obj* list = values.size() == 1
                        ? values[0]
                        : Tcl_NewListObj(static_cast<int>(values.size()), values.data());
    Tcl_IncrRefCount(list);
    value = Tcl_GetString(list);
    Tcl_DecrRefCount(list);
  } else {
    while (a.hasMore()) a.object("value");  // the other processes' arguments are not used
  }
  value = comm.broadcast(std::move(value), 0);
  Tcl_SetObjResult(rt.interp, Tcl_NewStringObj(value.data(), static_cast<int>(value.size())));
}

constexpr tcl::CommandEntry kCommands[] = {
    {"getPID", "getPID", getPIDCmd},
    {"getNP", "getNP", getNPCmd},
    {"barrier", "barrier", barrierCmd},
    {"send", "send ?-pid pid? value", sendCmd},
    {"recv", "recv ?-pid pid|ANY? varName", recvCmd},
    {"Bcast", "Bcast ?value ...? (values on process 0)", bcastCmd},
    {"ensemble", "ensemble run jobList command ?-out dir?", ensembleCmd},
};

}  // namespace

std::span<const tcl::CommandEntry> parallelCommands() { return kCommands; }

void setCommunicator(Tcl_Interp* interp, std::unique_ptr<Communicator> comm) {
  ParallelState::set(interp, std::move(comm));
}

}  // namespace dabs::parallel
