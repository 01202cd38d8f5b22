// SPDX-License-Identifier: MIT
// The dabs program: `dabs script.tcl ?args...?` runs a script; `dabs` alone in a terminal is an
// interactive Tcl shell with the dabs commands (line editing and history from Debian's
// tcl-tclreadline when it is installed); `dabs` with standard input from a pipe or a file runs the
// commands read there and exits with status 1 when any of them failed. Built with DABS_MPI it is
// dabs-mp: MPI starts first, and getPID, send, ensemble ... act for the processes mpirun started.
#include <tcl.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "tcl/commands/CommandTable.h"
#include "tcl/commands/SignalExit.h"
#include "tcl/parallel/ParallelCommands.h"
#include "tcl/viewer/ViewerPageTemplate.h"
#ifdef DABS_MPI
#include "tcl/parallel/mpi/MpiSession.h"
#endif

namespace {

int appInit(Tcl_Interp* interp) {
  if (Tcl_Init(interp) != TCL_OK) return TCL_ERROR;
  // getPID, getNP, send, recv, barrier, Bcast, ensemble: the program's own commands.
  const std::span<const dabs::tcl::CommandEntry> parallel[] = {dabs::parallel::parallelCommands()};
  if (dabs::tcl::registerCommands(interp, parallel) != TCL_OK) return TCL_ERROR;
#ifdef DABS_MPI
  // dabs-mp: getPID, send, ensemble ... act for the processes mpirun started.
  if (dabs::parallel::attachMpi(interp) != TCL_OK) return TCL_ERROR;
#endif
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

void reportError(Tcl_Interp* interp) {
  std::fprintf(stderr, "%s\n", Tcl_GetStringResult(interp));
  std::fflush(stderr);
}

// Commands from a pipe: Tcl_Main would go on after a failed command and exit with status 0, so a
// pipeline could not see the failure. This loop reads complete commands as Tcl_Main does, reports
// each error on stderr, runs a last command even without its newline, and reports one left
// incomplete at end of input (an unclosed brace) as an error instead of dropping it.
int runPipedInput(const char* argv0) {
  Tcl_FindExecutable(argv0);
  Tcl_Interp* interp = Tcl_CreateInterp();
  Tcl_SetVar2Ex(interp, "argv0", nullptr, Tcl_NewStringObj(argv0, -1), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argc", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "argv", nullptr, Tcl_NewObj(), TCL_GLOBAL_ONLY);
  Tcl_SetVar2Ex(interp, "tcl_interactive", nullptr, Tcl_NewIntObj(0), TCL_GLOBAL_ONLY);
  if (appInit(interp) != TCL_OK) {
    reportError(interp);
    Tcl_Exit(1);
  }
  Tcl_Channel in = Tcl_GetStdChannel(TCL_STDIN);
  if (in == nullptr) Tcl_Exit(0);
  bool failed = false;
  Tcl_Obj* command = Tcl_NewObj();
  Tcl_IncrRefCount(command);
  auto run = [&] {
    if (Tcl_EvalObjEx(interp, command, TCL_EVAL_GLOBAL) != TCL_OK) {
      reportError(interp);
      failed = true;
    }
    Tcl_DecrRefCount(command);
    command = Tcl_NewObj();
    Tcl_IncrRefCount(command);
  };
  for (;;) {
    Tcl_Obj* line = Tcl_NewObj();
    Tcl_IncrRefCount(line);
    const int length = Tcl_GetsObj(in, line);
    if (length < 0) {
      Tcl_DecrRefCount(line);
      break;
    }
    Tcl_AppendObjToObj(command, line);
    Tcl_DecrRefCount(line);
    Tcl_AppendToObj(command, "\n", 1);
    if (Tcl_CommandComplete(Tcl_GetString(command))) run();
  }
  int size = 0;
  const char* rest = Tcl_GetStringFromObj(command, &size);
  if (size > 0 && !Tcl_CommandComplete(rest)) {
    std::fprintf(
        stderr, "incomplete command at end of input (a brace, bracket or quote is not closed):\n%s",
        rest);
    failed = true;
  } else if (size > 0) {
    run();
  }
  Tcl_DecrRefCount(command);
  Tcl_Exit(failed ? 1 : 0);
  return 0;
}

#ifdef DABS_MPI
constexpr const char* kProgram = "dabs-mp";
#else
constexpr const char* kProgram = "dabs";
#endif

int printHelp() {
  // Each way of running the program, then what it does (continuation lines indented under it).
  struct Usage {
    const char* form;  ///< printed after the program's name (%s: the name, for a pipe)
    const char* what;
  };
  const Usage usages[] = {
      {" script.tcl ?args...?",
       "run a Tcl script (argv and argc as tclsh sets them);\nthe exit status is the script's"},
      {"",
       "in a terminal: an interactive Tcl shell with the dabs commands\n(prompt dabs>, line "
       "editing with Debian's tcl-tclreadline;\nexit or Ctrl-D quits)"},
      {" < commands.tcl",
       "commands from a pipe or a file: each failed command is\nreported on stderr and the exit "
       "status is 1"},
      {" --help | -h", "this text"},
      {" --version", "version, commit, compiler and optional parts of this build"},
  };
  std::printf("Usage:\n");
  for (const Usage& u : usages) {
    char form[64];
    std::snprintf(form, sizeof form, "%s%s", kProgram, u.form);
    std::printf("  %-30s ", form);
    for (const char* c = u.what; *c != '\0'; ++c) {
      std::putchar(*c);
      if (*c == '\n') std::printf("  %-30s ", "");
    }
    std::putchar('\n');
  }
  std::printf(
      "\nScripts use the OpenSees command vocabulary (model, node, element, analyze, ...).\n"
#ifdef DABS_MPI
      "Under MPI: mpirun -n N dabs-mp script.tcl (getPID, getNP, send, recv, Bcast, barrier\n"
      "and ensemble act for the processes mpirun started).\n"
#endif
      "\nEnvironment:\n"
      "  DABS_THREADS=n|auto            threads that update elements (as the `threads n`\n"
      "                                 command; default auto: measured on the model's first\n"
      "                                 steps and again after 400 to 6,400 steps, one thread\n"
      "                                 or all)\n"
      "\nDocumentation: README.md at the top of the source tree (%s): the command table,\n"
      "speed against OpenSees, where dabs differs from OpenSees; docs/ beside it: the case\n"
      "study, contact (impact laws, contact stepping), bearings, ensembles and MPI.\n",
      DABS_SOURCE_DIR);
  return 0;
}

int printVersion() {
  std::printf(
      "%s %s\n"
      "commit:    %s\n"
      "compiler:  %s\n"
      "Tcl:       %s\n"
      "MPI:       %s\n"
      "NLopt:     %s\n"
      "viewer:    %s\n"
      "Python:    not in this version\n",
      kProgram, DABS_VERSION, DABS_COMMIT, DABS_COMPILER, TCL_PATCH_LEVEL,
#ifdef DABS_MPI
      "yes (this program runs under mpirun)",
#else
      DABS_HAS_MPI ? "dabs-mp built beside this program" : "no (Open MPI not found at build time)",
#endif
      DABS_HAS_NLOPT ? "yes (bearing calibration, yoshida_calibration)"
                     : "no (no bearing calibration program)",
      dabs::viewer::viewerBundleBuilt() ? "page bundled (recorder Viewer writes the 3D viewer)"
                                        : "not bundled (node/npm missing at build time)");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  // The options a user tries first. Anything else starting with "--" is an error (exit status 2)
  // rather than a script name or an interactive shell that opens without a word.
  if (argc >= 2) {
    const char* first = argv[1];
    if (std::strcmp(first, "--help") == 0 || std::strcmp(first, "-h") == 0) return printHelp();
    if (std::strcmp(first, "--version") == 0) return printVersion();
    if (std::strncmp(first, "--", 2) == 0) {
      std::fprintf(stderr, "%s: unknown option %s (%s --help lists the options)\n", kProgram, first,
                   kProgram);
      return 2;
    }
  }
#ifdef DABS_MPI
  dabs::parallel::startMpi(&argc, &argv);
#endif
  dabs::tcl::installSignalExit();
  if (argc == 1 && isatty(STDIN_FILENO) == 0) return runPipedInput(argv[0]);
  Tcl_Main(argc, argv, appInit);
  return 0;
}
