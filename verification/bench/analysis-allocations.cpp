// SPDX-License-Identifier: MIT
// Heap allocations in the time-step loop of a whole model: the multi-span bridge of
// opensees/bridge.tcl is built and run for warm-up steps, then `analyze` runs on while every
// malloc/calloc/realloc made by dabs' own code (and the Eigen code inlined in it) is counted.
// Linked with -Wl,--wrap=malloc,... (see CMakeLists.txt); Tcl's own allocations are not ours and
// are not counted. Prints allocations per step and per Newton iteration, with and without
// recorders. The goal is none per iteration.
//
//   bench_analysis_allocations ?nSpans? ?steps?
#include <tcl.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tcl/commands/CommandTable.h"

extern "C" {
void* __real_malloc(std::size_t n);
void* __real_calloc(std::size_t n, std::size_t size);
void* __real_realloc(void* p, std::size_t n);
}

namespace {
std::atomic<long> gMallocs{0};

long statistic(Tcl_Interp* interp, const char* key) {
  if (Tcl_Eval(interp, (std::string("dict get [analysisStatistics] ") + key).c_str()) != TCL_OK)
    return -1;
  return std::atol(Tcl_GetStringResult(interp));
}

bool eval(Tcl_Interp* interp, const std::string& script) {
  if (Tcl_Eval(interp, script.c_str()) == TCL_OK) return true;
  std::fprintf(stderr, "%s\n", Tcl_GetStringResult(interp));
  return false;
}

/// Runs `steps` steps and prints allocations per step and per iteration.
bool measure(Tcl_Interp* interp, const char* label, int steps) {
  const long iterationsBefore = statistic(interp, "iterations");
  const long before = gMallocs.load();
  if (!eval(interp, "analyze " + std::to_string(steps) + " 0.005")) return false;
  const long mallocs = gMallocs.load() - before;
  const long iterations = statistic(interp, "iterations") - iterationsBefore;
  std::printf(
      "%-18s steps %5d  iterations %6ld  allocations %8ld  per step %8.3f  per iteration %8.3f\n",
      label, steps, iterations, mallocs, double(mallocs) / steps,
      iterations > 0 ? double(mallocs) / double(iterations) : 0.0);
  return true;
}
}  // namespace

extern "C" {
void* __wrap_malloc(std::size_t n) {
  gMallocs.fetch_add(1, std::memory_order_relaxed);
  return __real_malloc(n);
}
void* __wrap_calloc(std::size_t n, std::size_t size) {
  gMallocs.fetch_add(1, std::memory_order_relaxed);
  return __real_calloc(n, size);
}
void* __wrap_realloc(void* p, std::size_t n) {
  gMallocs.fetch_add(1, std::memory_order_relaxed);
  return __real_realloc(p, n);
}
}

int main(int argc, char** argv) {
  const int spans = argc > 1 ? std::atoi(argv[1]) : 3;
  const int steps = argc > 2 ? std::atoi(argv[2]) : 400;
  Tcl_FindExecutable(argv[0]);
  Tcl_Interp* interp = Tcl_CreateInterp();
  (void)Tcl_Init(interp);
  if (dabs::tcl::registerCommands(interp) != TCL_OK) return 2;
  const std::string script =
      std::string(DABS_SOURCE_DIR) + "/verification/bench/opensees/bridge.tcl";
  // Build the model and run 200 warm-up steps (first factorisations, recorder buffers).
  if (!eval(interp, "set argv {" + std::to_string(spans) +
                        " 200 [file join [pwd] allocations-out]}; set argc 3; source {" + script +
                        "}"))
    return 1;
  if (!measure(interp, "with recorders", steps)) return 1;
  if (!eval(interp, "remove recorders")) return 1;
  if (!measure(interp, "without recorders", steps)) return 1;
  Tcl_DeleteInterp(interp);
  return 0;
}
