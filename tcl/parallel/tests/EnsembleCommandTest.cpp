// SPDX-License-Identifier: MIT
#include "tcl/parallel/EnsembleCommand.h"

#include <gtest/gtest.h>
#include <tcl.h>

#include <string>

#include "tcl/commands/CommandTable.h"
#include "tcl/parallel/ParallelCommands.h"

namespace dabs::parallel {
namespace {

// A safe interpreter may not write files (Tcl hides `open` and `file` there); the ensemble writes
// its results, so it refuses to run there, before it runs any job.
TEST(EnsembleCommandTest, RefusesToRunInASafeInterpreter) {
  Tcl_Interp* interp = Tcl_CreateInterp();
  ASSERT_EQ(Tcl_MakeSafe(interp), TCL_OK);
  const std::span<const tcl::CommandEntry> families[] = {parallelCommands()};
  ASSERT_EQ(tcl::registerCommands(interp, families), TCL_OK);
  const int rc = Tcl_Eval(interp,
                          "set ran 0; proc job {j} {incr ::ran; list}; "
                          "ensemble run {{a 1}} job -out dabs-ensemble-safe-test");
  EXPECT_EQ(rc, TCL_ERROR);
  const std::string message = Tcl_GetStringResult(interp);
  EXPECT_NE(message.find("ensemble run"), std::string::npos) << message;
  EXPECT_NE(message.find("safe interpreter"), std::string::npos) << message;
  ASSERT_EQ(Tcl_Eval(interp, "set ran"), TCL_OK);
  EXPECT_STREQ(Tcl_GetStringResult(interp), "0");
  Tcl_DeleteInterp(interp);
}

// The programs pass the parallel commands to the command table: they are registered after the
// library's, and commandEntries (what the Python module exposes) lists them.
TEST(EnsembleCommandTest, ProgramsPassTheParallelCommandsToTheTable) {
  const std::span<const tcl::CommandEntry> families[] = {parallelCommands()};
  Tcl_Interp* interp = Tcl_CreateInterp();
  ASSERT_EQ(tcl::registerCommands(interp, families), TCL_OK);
  for (const char* name : {"getPID", "getNP", "send", "recv", "barrier", "Bcast", "ensemble"}) {
    ASSERT_EQ(Tcl_Eval(interp, (std::string("info commands ") + name).c_str()), TCL_OK);
    EXPECT_STREQ(Tcl_GetStringResult(interp), name);
  }
  Tcl_DeleteInterp(interp);
  const auto entries = tcl::commandEntries(families);
  const auto library = tcl::commandEntries();
  ASSERT_EQ(entries.size(), library.size() + parallelCommands().size());
  EXPECT_EQ(entries.back()->name, parallelCommands().back().name);
}

}  // namespace
}  // namespace dabs::parallel
