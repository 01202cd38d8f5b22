// SPDX-License-Identifier: MIT
// The dabs commands as a loadable Tcl package: `lappend auto_path <dir>; package require dabs`.
#include <tcl.h>

#include "tcl/commands/CommandTable.h"
#include "tcl/parallel/ParallelCommands.h"

extern "C" {

/// Package entry point called by Tcl's `load` (the name follows the library name libdabs).
int Dabs_Init(Tcl_Interp* interp) {
  if (Tcl_InitStubs(interp, "8.6", 0) == nullptr) return TCL_ERROR;
  const std::span<const dabs::tcl::CommandEntry> parallel[] = {dabs::parallel::parallelCommands()};
  if (dabs::tcl::registerCommands(interp, parallel) != TCL_OK) return TCL_ERROR;
  return Tcl_PkgProvide(interp, "dabs", "0.1.0");
}

}  // extern "C"
