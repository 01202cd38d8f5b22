// SPDX-License-Identifier: MIT
// The dabs program: `dabs script.tcl ?args...?` runs a script; `dabs` alone, or with a pipe on
// standard input, is an interactive Tcl shell with the dabs commands (Tcl's own main loop, with
// line editing when Debian's tcl-tclreadline is installed).
#include <tcl.h>

#include "tcl/commands/CommandTable.h"

namespace {

int appInit(Tcl_Interp* interp) {
  if (Tcl_Init(interp) != TCL_OK) return TCL_ERROR;
  if (dabs::tcl::registerCommands(interp) != TCL_OK) return TCL_ERROR;
  Tcl_PkgProvide(interp, "dabs", "0.1.0");
  // A terminal session gets line editing and history from Debian's tcl-tclreadline when it is
  // installed; its loop exits the program at end of input. Otherwise Tcl's own loop runs.
  const char* interactive =
      "if {$tcl_interactive && ![catch {package require tclreadline}]} {"
      "  proc ::tclreadline::prompt1 {} {return \"dabs> \"};"
      "  ::tclreadline::Loop"
      "}";
  if (Tcl_Eval(interp, interactive) != TCL_OK) Tcl_ResetResult(interp);
  return TCL_OK;
}

}  // namespace

int main(int argc, char** argv) {
  Tcl_Main(argc, argv, appInit);
  return 0;
}
