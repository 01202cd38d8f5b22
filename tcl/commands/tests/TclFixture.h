// SPDX-License-Identifier: MIT
#pragma once

// A Tcl interpreter with the dabs commands, for tests of the command layer.

#include <gtest/gtest.h>
#include <tcl.h>

#include <string>

#include "tcl/commands/CommandTable.h"

namespace dabs::tcl::testing {

class TclFixture : public ::testing::Test {
 protected:
  void SetUp() override {
    interp_ = Tcl_CreateInterp();
    ASSERT_EQ(registerCommands(interp_), TCL_OK);
  }
  void TearDown() override { Tcl_DeleteInterp(interp_); }

  /// Evaluates a script that must succeed and returns its result.
  std::string ok(const std::string& script) {
    const int status = Tcl_Eval(interp_, script.c_str());
    const std::string result = Tcl_GetStringResult(interp_);
    EXPECT_EQ(status, TCL_OK) << script << " -> " << result;
    return result;
  }
  /// Evaluates a script that must fail and returns the error message.
  std::string error(const std::string& script) {
    const int status = Tcl_Eval(interp_, script.c_str());
    const std::string result = Tcl_GetStringResult(interp_);
    EXPECT_EQ(status, TCL_ERROR) << script << " -> " << result;
    return result;
  }
  double number(const std::string& script) { return std::stod(ok(script)); }

  Tcl_Interp* interp_ = nullptr;
};

}  // namespace dabs::tcl::testing
