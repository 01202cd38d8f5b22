// SPDX-License-Identifier: MIT
// `recorder Viewer` drawing options: accepted forms, and errors that name the option and what was
// expected, with the model left without a new recorder.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tcl/commands/tests/TclFixture.h"

#include <unistd.h>

namespace dabs::tcl::testing {
namespace {

class ViewerCommandsTest : public TclFixture {
 protected:
  void SetUp() override {
    TclFixture::SetUp();
    // One page per process: ctest runs these tests in parallel processes.
    page_ = (std::filesystem::temp_directory_path() /
             ("dabs_viewer_commands_test_" + std::to_string(::getpid()) + ".html"))
                .string();
    // two nodes, a beam, a bearing-free model: enough for the options' checks
    ok("model basic -ndm 3 -ndf 6; node 1 0 0 0; node 2 5 0 0; node 3 5 0 0; "
       "geomTransf Linear 1 0 0 1; element elasticBeamColumn 7 1 2 1.0 2e8 8e7 1.0 1.0 1.0 1");
  }
  std::string viewer(const std::string& options) {
    return "recorder Viewer -file " + page_ + " " + options;
  }
  std::string page_;
};

TEST_F(ViewerCommandsTest, AcceptsSectionsBlocksAndGaps) {
  ok(viewer(
      "-beamSection {{rect 4.0 1.5 7}} -block {{1 2 3 -dz -1.5 1 2} {1 1 1 3}} -gaps {{G 2 3}}"));
  ok(viewer("-beamSection {{circle 2.0 7}}"));
}

TEST_F(ViewerCommandsTest, ErrorsNameTheOptionAndWhatWasExpected) {
  EXPECT_NE(error(viewer("-beamSection {{square 1 1 7}}"))
                .find("expected rect or circle, got \"square\""),
            std::string::npos);
  EXPECT_NE(error(viewer("-beamSection {{rect 1 x 7}}")).find("depth expected a number, got \"x\""),
            std::string::npos);
  EXPECT_NE(error(viewer("-beamSection {{rect -1 1 7}}")).find("sizes must be positive"),
            std::string::npos);
  EXPECT_NE(error(viewer("-beamSection {{rect 1 1}}")).find("expected {rect width depth tags..}"),
            std::string::npos);
  EXPECT_NE(error(viewer("-bearingPad {{1 1 7}}"))
                .find("-bearingPad element 7 (elasticBeamColumn) is not a bearing"),
            std::string::npos);
  EXPECT_NE(error(viewer("-block {{1 1 1 -dz}}")).find("-block"), std::string::npos);
  EXPECT_NE(error(viewer("-block {{1 1 1 99}}")).find("-block node 99 is not drawn"),
            std::string::npos);
  EXPECT_NE(error(viewer("-gaps {{G 1}}")).find("expected {label nodeA nodeB}"), std::string::npos);
  EXPECT_NE(error(viewer("-gaps {{G 1 99}}")).find("node 99 is not drawn"), std::string::npos);
  EXPECT_EQ(ok("llength [getNodeTags]"), "3");
}

TEST_F(ViewerCommandsTest, PlotIndicesAreWholeIntegersByTheReadersRules) {
  ok(viewer("-plots {{d node 2 1 disp}}"));
  EXPECT_NE(
      error(viewer("-plots {{d node 2 1.5 disp}}")).find("dof expected an integer, got \"1.5\""),
      std::string::npos);
  EXPECT_NE(
      error(viewer("-plots {{d node 99999999999 1 disp}}"))
          .find("tag expected an integer from -2147483648 to 2147483647, got \"99999999999\""),
      std::string::npos);
  EXPECT_NE(error(viewer("-plots {{f ele 7 force 2.0}}")).find("component expected an integer"),
            std::string::npos);
}

}  // namespace
}  // namespace dabs::tcl::testing
