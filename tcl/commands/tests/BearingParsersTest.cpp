// SPDX-License-Identifier: MIT
// Bad input to `element yoshidaBearing ... -afterFailure drop h ?-seat Ks mu_s mu_k ?Kst??` and to
// `-vertical kumar G Kbulk Di Do ts tr n ?-tc ..?`: each
// error names the command, the argument by its position on the command line (the command word
// is argument 0) and what was expected, and leaves the model unchanged.

#include <gtest/gtest.h>

#include <string>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl {
namespace {

class BearingParsersTest : public testing::TclFixture {
 protected:
  /// Two coincident 6-dof nodes and a Yoshida material 1.
  void bearingModel() {
    ok("model basic -ndm 3 -ndf 6");
    ok("node 1 0 0 0; node 2 0 0 0");
    ok("biaxialMaterial Yoshida 1 150.0 0.012 2.0 0.0 0.0 1.0 0.0");
  }
  int elementCount() { return std::stoi(ok("llength [getEleTags]")); }
  /// What `print -ele tag` writes (through a file, as print writes to the console).
  std::string printed(int tag) {
    const std::string file = ::testing::TempDir() + "bearing-print.txt";
    ok("print -file " + file + " -ele " + std::to_string(tag));
    return ok("set f [open " + file + "]; set text [read $f]; close $f; file delete " + file +
              "; set text");
  }
  // "element yoshidaBearing 5 1 2 1 -Tr 0.2 -Kv 1e6": -Tr is argument 6, -Kv 8, the next
  // option word 10 (so in "-afterFailure drop h -seat Ks ..": drop 11, h 12, Ks 14).
  static std::string bearing(const std::string& options) {
    return "element yoshidaBearing 5 1 2 1 -Tr 0.2 -Kv 1e6 " + options;
  }
};

::testing::AssertionResult has(const std::string& message, const std::string& part) {
  if (message.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << part << "\" not in: " << message;
}

TEST_F(BearingParsersTest, DropModeIsAcceptedWithAndWithoutSeat) {
  bearingModel();
  ok(bearing("-afterFailure drop 0.25"));
  // Defaults: Ks = Kv, mu_s = mu_k = 0.5, Kst = Ks.
  EXPECT_TRUE(has(printed(5), "afterFailure drop 0.25 seat 1e+06 0.5 0.5 1e+06"));
  ok("node 3 0 0 0; node 4 0 0 0");
  ok("element yoshidaBearing 6 3 4 1 -Tr 0.2 -Kv 1e6 -afterFailure drop 0.25 -seat 2e6 0.6 0.4");
  EXPECT_TRUE(has(printed(6), "afterFailure drop 0.25 seat 2e+06 0.6 0.4 2e+06"));
  ok("node 7 0 0 0; node 8 0 0 0");
  ok("element yoshidaBearing 7 7 8 1 -Tr 0.2 -Kv 1e6 -seat 2e6 0.6 0.4 5e5 -afterFailure drop 0");
  EXPECT_TRUE(has(printed(7), "afterFailure drop 0 seat 2e+06 0.6 0.4 500000"));
  EXPECT_EQ(ok("eleResponse 7 seatForce"), "0.0 0.0 0.0");
  EXPECT_EQ(ok("eleResponse 7 dropped"), "0.0");
}

TEST_F(BearingParsersTest, DropErrorsNameTheArgumentAndWhatWasExpected) {
  bearingModel();
  std::string m = error(bearing("-afterFailure drop"));
  EXPECT_TRUE(has(m,
                  "element yoshidaBearing 5: argument 12 (h) expected a number after "
                  "-afterFailure drop, got nothing"));
  m = error(bearing("-afterFailure drop -seat 1e6 0.5 0.4"));
  EXPECT_TRUE(has(m, "argument 12 (h) expected a number after -afterFailure drop, got \"-seat\""));
  m = error(bearing("-afterFailure drop -0.1"));
  EXPECT_TRUE(has(m,
                  "element yoshidaBearing 5: argument 12: h (drop height) must not be "
                  "negative, got \"-0.1\""));
  m = error(bearing("-afterFailure drop 0.2 -seat 1e6 0.3 0.4"));
  EXPECT_TRUE(has(m, "argument 16 (-seat) mu_k must not exceed mu_s, got \"0.4\""));
  m = error(bearing("-afterFailure drop 0.2 -seat 0 0.5 0.4"));
  EXPECT_TRUE(has(m, "argument 14 (-seat) Ks (seat stiffness) must be positive, got \"0\""));
  m = error(bearing("-afterFailure drop 0.2 -seat 1e6 0.5 0.4 -2"));
  EXPECT_TRUE(has(m, "argument 17 (-seat) Kst (seat tangential stiffness) must be positive"));
  m = error(bearing("-afterFailure drop 0.2 -seat 1e6 0.5"));
  EXPECT_TRUE(has(m, "(-seat) expected 3 or 4 numbers after -seat (Ks mu_s mu_k ?Kst?)"));
  m = error(bearing("-afterFailure drop 0.2 -seat 1e6 0.5 0.4 1e6 7"));
  EXPECT_TRUE(has(m, "argument 18 (-seat) is a fifth value"));
  m = error(bearing("-afterFailure drop 0.2 -seat abc 0.5 0.4"));
  EXPECT_TRUE(has(m, "argument 14 (-seat) expected numbers after -seat, got \"abc\""));
  m = error(bearing("-seat 1e6 0.5 0.4"));
  EXPECT_TRUE(has(m, "(-seat) needs -afterFailure drop h"));
  m = error(bearing("-afterFailure release -seat 1e6 0.5 0.4"));
  EXPECT_TRUE(has(m, "(-seat) needs -afterFailure drop h"));
  m = error(bearing("-afterFailure fall"));
  EXPECT_TRUE(has(m,
                  "argument 11 (-afterFailure) expected keep, release, stop or drop, got "
                  "\"fall\""));
  EXPECT_TRUE(has(m, "usage: element yoshidaBearing"));
  EXPECT_EQ(elementCount(), 0);           // nothing was added
  ok(bearing("-afterFailure drop 0.2"));  // the tag is still free
}

// "element yoshidaBearing 5 1 2 1 -vertical kumar G Kbulk Di Do ts tr n": -vertical is argument
// 6, kumar 7, G 8 ... n 14, the next option word 15 and its value 16.
std::string kumarBearing(const std::string& options) {
  return "element yoshidaBearing 5 1 2 1 -vertical kumar 800 2e6 0.1 0.8 0.003 0.01 20 " + options;
}

TEST_F(BearingParsersTest, VerticalKumarIsAcceptedWithItsOptions) {
  bearingModel();
  ok(kumarBearing(""));
  // Defaults: tc 0, kc 10, phi 0.5, ac 1, every effect on; Tr = n tr.
  EXPECT_TRUE(has(printed(5),
                  "vertical kumar 800 2e+06 0.1 0.8 0.003 0.01 20 tc 0 kc 10 phi 0.5 ac 1 "
                  "cavitation 1 buckling 1 kvShear 1"));
  EXPECT_TRUE(has(printed(5), "Tr 0.2 Kv "));
  EXPECT_EQ(ok("eleResponse 5 maxTension"), "0.0");
  EXPECT_EQ(ok("eleResponse 5 verticalBranch"), "0.0");
  ok("node 3 0 0 0; node 4 0 0 0");
  ok("element yoshidaBearing 6 3 4 1 -Kt 10 -vertical kumar 800 2e6 0 0.8 0.003 0.01 20 -tc 0.01 "
     "-kc 20 -phi 0.3 -ac 2 -cavitation 0 -buckling 0 -kvShear 0");
  EXPECT_TRUE(has(printed(6), "tc 0.01 kc 20 phi 0.3 ac 2 cavitation 0 buckling 0 kvShear 0"));
  EXPECT_FALSE(has(printed(6), "pDelta"));
  // The seat's default stiffness follows Kv, here Kv0 from the geometry.
  ok("node 11 0 0 0; node 12 0 0 0");
  ok("element yoshidaBearing 8 11 12 1 -vertical kumar 800 2e6 0.1 0.8 0.003 0.01 20 "
     "-afterFailure drop 0.3");
  const std::string text = printed(8);
  const std::size_t at = text.find(" Kv ") + 4;
  const std::string kv0 = text.substr(at, text.find(' ', at) - at);
  EXPECT_TRUE(has(text, "afterFailure drop 0.3 seat " + kv0 + " 0.5 0.5 " + kv0));
  ok("node 9 0 0 0; node 10 0 0 0");
  ok("element yoshidaBearing 7 9 10 1 -Tr 0.2 -Kv 1e6 -pDelta");  // with the linear axial spring
  EXPECT_TRUE(has(printed(7), "pDelta"));
}

TEST_F(BearingParsersTest, VerticalKumarErrorsNameTheArgumentAndWhatWasExpected) {
  bearingModel();
  std::string m = error("element yoshidaBearing 5 1 2 1 -vertical kumar 800 2e6 0.1 0.8 0.003");
  EXPECT_TRUE(has(m,
                  "element yoshidaBearing 5: argument 13 (tr) expected a number after -vertical "
                  "kumar (G Kbulk Di Do ts tr n), got nothing"));
  m = error("element yoshidaBearing 5 1 2 1 -vertical kumar 800 2e6 0.1 0.8 x 0.01 20");
  EXPECT_TRUE(has(m, "argument 12 (ts) expected a number after -vertical kumar"));
  EXPECT_TRUE(has(m, "got \"x\""));
  m = error("element yoshidaBearing 5 1 2 1 -vertical linear 800");
  EXPECT_TRUE(has(m, "argument 7 (-vertical) expected kumar, got \"linear\""));
  m = error(kumarBearing("").replace(kumarBearing("").find(" 800 "), 5, " -800 "));
  EXPECT_TRUE(has(m, "argument 8: G (shear modulus) must be positive, got \"-800\""));
  m = error("element yoshidaBearing 5 1 2 1 -vertical kumar 800 2e6 0.9 0.8 0.003 0.01 20");
  EXPECT_TRUE(has(m, "argument 10: Di (inner diameter) must be less than Do, got \"0.9\""));
  m = error("element yoshidaBearing 5 1 2 1 -vertical kumar 800 2e6 0.1 0.8 0.003 0.01 2.5");
  EXPECT_TRUE(has(m, "argument 14: n (number of rubber layers) must be a whole number >= 1"));
  m = error(kumarBearing("-phi 1.5"));
  EXPECT_TRUE(has(m, "argument 16: phi (damage index) must be in [0, 1), got \"1.5\""));
  m = error(kumarBearing("-kc 0"));
  EXPECT_TRUE(has(m, "argument 16: kc (cavitation parameter) must be positive, got \"0\""));
  m = error(kumarBearing("-buckling 2"));
  EXPECT_TRUE(has(m, "argument 16 (-buckling) expected 0 or 1, got \"2\""));
  m = error(kumarBearing("-Kv 1e6"));
  EXPECT_TRUE(has(m, "argument 16 (-Kv) is not allowed with -vertical kumar"));
  m = error(kumarBearing("-Tr 0.2"));
  EXPECT_TRUE(has(m, "argument 16 (-Tr) is not allowed with -vertical kumar (Tr = n tr)"));
  m = error(bearing("-phi 0.3"));
  EXPECT_TRUE(has(m, "argument 11 (-phi) needs -vertical kumar, got \"0.3\""));
  m = error("element yoshidaBearing 5 1 2 1 -Kt 10");
  EXPECT_TRUE(has(m, "-Tr (total rubber thickness) is required"));
  EXPECT_TRUE(has(m, "usage: element yoshidaBearing"));
  EXPECT_EQ(elementCount(), 0);  // nothing was added
  ok(kumarBearing(""));          // the tag is still free
}

}  // namespace
}  // namespace dabs::tcl
