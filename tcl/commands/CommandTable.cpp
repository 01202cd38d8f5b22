// SPDX-License-Identifier: MIT
#include "tcl/commands/CommandTable.h"

#include <array>
#include <string>
#include <vector>

#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"

namespace dabs::tcl {

namespace {

int dispatch(ClientData data, Tcl_Interp* /*interp*/, int objc, Tcl_Obj* const objv[]) {
  auto* binding = static_cast<CommandBinding*>(data);
  return runCommand(*binding->runtime, *binding->entry, objc, objv);
}

// Tcl's own `load` (of shared libraries) under the name our nodal `load` hands its calls to.
// Tcl itself needs it: tclreadline and Tk load their libraries with it.
constexpr const char* kTclLoad = "::dabs::tclLoad";

// Whether a `load` call is a nodal load: its first argument is an integer (a node tag). Anything
// else (a file name, `-global`, `--`) is a call of Tcl's `load`.
bool isNodalLoad(int objc, Tcl_Obj* const objv[]) {
  int tag = 0;
  return objc < 2 || Tcl_GetIntFromObj(nullptr, objv[1], &tag) == TCL_OK;
}

int dispatchLoad(ClientData data, Tcl_Interp* interp, int objc, Tcl_Obj* const objv[]) {
  auto* binding = static_cast<CommandBinding*>(data);
  if (isNodalLoad(objc, objv) ||
      Tcl_FindCommand(interp, kTclLoad, nullptr, TCL_GLOBAL_ONLY) == nullptr)
    return runCommand(*binding->runtime, *binding->entry, objc, objv);
  std::vector<Tcl_Obj*> args(objv, objv + objc);
  args[0] = Tcl_NewStringObj(kTclLoad, -1);
  Tcl_IncrRefCount(args[0]);
  const int code = Tcl_EvalObjv(interp, objc, args.data(), 0);
  Tcl_DecrRefCount(args[0]);
  return code;
}

// Flushes recorders when the program exits without deleting the interpreter.
void flushAtExit(ClientData data) { static_cast<Runtime*>(data)->domain.flushRecorders(); }

void deleteRuntime(ClientData data, Tcl_Interp* /*interp*/) {
  Tcl_DeleteExitHandler(flushAtExit, data);
  delete static_cast<Runtime*>(data);
}

void setError(Tcl_Interp* interp, const std::string& message) {
  Tcl_SetObjResult(interp, Tcl_NewStringObj(message.c_str(), static_cast<int>(message.size())));
}

}  // namespace

// Every family of commands of this library, in registration order (a program's extra families
// follow): the one list both registerCommands and commandEntries read, so another language's
// binding sees exactly the commands Tcl has.
static std::array<std::span<const CommandEntry>, 10> commandFamilies() {
  return {
      modelCommands(),    loadCommands(),         analysisCommands(), queryCommands(),
      recorderCommands(), materialTestCommands(), sectionCommands(),  beamCommands(),
      bearingCommands(),  contactCommands(),
  };
}

std::vector<const CommandEntry*> commandEntries(CommandFamilies extra) {
  std::vector<const CommandEntry*> entries;
  for (const auto& family : commandFamilies())
    for (const CommandEntry& entry : family) entries.push_back(&entry);
  for (const auto& family : extra)
    for (const CommandEntry& entry : family) entries.push_back(&entry);
  return entries;
}

int runCommand(Runtime& rt, const CommandEntry& entry, int objc, Tcl_Obj* const objv[]) {
  ArgReader args(objc, objv, std::string(entry.usage));
  try {
    Tcl_ResetResult(rt.interp);
    entry.fn(rt, args);
    rt.heap.adviseGrowth();
    return TCL_OK;
  } catch (const ArgError& e) {
    setError(rt.interp, e.what());
  } catch (const InputError& e) {
    // A validation error names the field it is about; the reader knows where that field was
    // read, so the message points at the argument without any bookkeeping in the parser.
    try {
      args.failInput(e);
    } catch (const ArgError& located) {
      setError(rt.interp, located.what());
    }
  } catch (const std::bad_alloc&) {
    setError(rt.interp, args.context() + ": out of memory");
  } catch (const std::exception& e) {
    setError(rt.interp, args.context() + ": internal error: " + e.what());
  }
  return TCL_ERROR;
}

int registerCommands(Tcl_Interp* interp, CommandFamilies extra) {
  auto* rt = new Runtime(interp);
  Tcl_CallWhenDeleted(interp, deleteRuntime, rt);
  Tcl_CreateExitHandler(flushAtExit, rt);
  // Keep Tcl's `load` reachable before ours takes its name.
  if (Tcl_FindCommand(interp, "::load", nullptr, TCL_GLOBAL_ONLY) != nullptr &&
      Tcl_FindCommand(interp, kTclLoad, nullptr, TCL_GLOBAL_ONLY) == nullptr &&
      Tcl_Eval(interp,
               (std::string("namespace eval ::dabs {}; rename ::load ") + kTclLoad).c_str()) !=
          TCL_OK)
    return TCL_ERROR;
  for (const CommandEntry* entry : commandEntries(extra)) {
    rt->bindings.push_back(std::make_unique<CommandBinding>(CommandBinding{rt, entry}));
    Tcl_CreateObjCommand(interp, std::string(entry->name).c_str(),
                         entry->name == "load" ? dispatchLoad : dispatch, rt->bindings.back().get(),
                         nullptr);
  }
  return TCL_OK;
}

}  // namespace dabs::tcl
