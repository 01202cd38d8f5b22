// SPDX-License-Identifier: MIT
// The argument reader records where each argument was read, so a validation error raised after
// reading can name the argument's position and token.
#include "tcl/commands/ArgReader.h"

#include <gtest/gtest.h>
#include <tcl.h>

#include <optional>
#include <string>
#include <vector>

#include "materials/InputError.h"

namespace dabs::tcl {
namespace {

/// The words of a command line as Tcl objects (kept alive for the reader's lifetime).
class Words {
 public:
  explicit Words(std::initializer_list<const char*> words) {
    // Tcl's object types are set up with the library, before the first object is made.
    static const bool initialised = [] {
      Tcl_FindExecutable(nullptr);
      return true;
    }();
    static_cast<void>(initialised);
    for (const char* w : words) {
      Tcl_Obj* o = Tcl_NewStringObj(w, -1);
      Tcl_IncrRefCount(o);
      objs_.push_back(o);
    }
  }
  ~Words() {
    for (Tcl_Obj* o : objs_) Tcl_DecrRefCount(o);
  }
  Words(const Words&) = delete;
  Words& operator=(const Words&) = delete;
  int count() const { return static_cast<int>(objs_.size()); }
  Tcl_Obj* const* data() const { return objs_.data(); }

 private:
  std::vector<Tcl_Obj*> objs_;
};

std::string failure(const ArgReader& args, const char* name, const char* what) {
  try {
    args.failArgument(name, what);
  } catch (const ArgError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ArgReaderTest, PositionsOfPositionalArgumentsAndOptions) {
  Words w{"uniaxialMaterial", "Gap", "7", "100.0", "0.05", "-Fy", "2.5", "-b", "0.1"};
  ArgReader args(w.count(), w.data(), "uniaxialMaterial Gap tag k gap ?-Fy Fy -b b?", 2);
  EXPECT_EQ(args.integer("tag"), 7);
  EXPECT_EQ(args.real("k"), 100.0);
  EXPECT_EQ(args.real("gap"), 0.05);
  EXPECT_EQ(args.option("-b", 0.0), 0.1);
  EXPECT_EQ(args.option("-Fy", 0.0), 2.5);
  args.finish();
  EXPECT_EQ(args.positionOf("tag"), 2u);
  EXPECT_EQ(args.positionOf("gap"), 4u);
  EXPECT_EQ(args.positionOf("-Fy"), 6u);  // the option's value
  EXPECT_EQ(args.positionOf("Fy"), 6u);   // a validation error names the field without '-'
  EXPECT_EQ(args.positionOf("b"), 8u);
  EXPECT_EQ(args.positionOf("eta"), 0u);  // never read
}

TEST(ArgReaderTest, RealsAfterAWordOptionRecordEachUnderItsName) {
  Words w{"element", "yoshidaBearing", "5", "-vertical", "kumar", "800", "2e6", "0.1", "-kc", "20"};
  ArgReader args(w.count(), w.data(), "element yoshidaBearing tag ?-vertical kumar G K Di?", 2);
  args.setContext("element yoshidaBearing 5");
  args.integer("tag");
  EXPECT_EQ(args.optionalWordOption("-vertical"), std::optional<std::string>("kumar"));
  const std::vector<double> v = args.realsAfterOption("-vertical", {"G", "K", "Di"});
  EXPECT_EQ(v, (std::vector<double>{800.0, 2e6, 0.1}));
  EXPECT_EQ(args.option("-kc", 10.0), 20.0);
  args.finish();
  EXPECT_EQ(args.positionOf("G"), 5u);
  EXPECT_EQ(args.positionOf("Di"), 7u);
  // Too few numbers: the error names the first missing one and lists what was expected.
  Words few{"element", "yoshidaBearing", "5", "-vertical", "kumar", "800", "-kc", "20"};
  ArgReader short_(few.count(), few.data(), "usage", 2);
  short_.setContext("element yoshidaBearing 5");
  short_.integer("tag");
  short_.optionalWordOption("-vertical");
  try {
    short_.realsAfterOption("-vertical", {"G", "K", "Di"});
    ADD_FAILURE() << "no error";
  } catch (const ArgError& e) {
    EXPECT_EQ(std::string(e.what()),
              "element yoshidaBearing 5: argument 6 (K) expected a number after -vertical kumar "
              "(G K Di), got \"-kc\"; usage: usage");
  }
}

TEST(ArgReaderTest, FailArgumentNamesPositionAndTokenOrTheCommand) {
  Words w{"uniaxialMaterial", "Gap", "7", "-100.0", "0.05"};
  ArgReader args(w.count(), w.data(), "uniaxialMaterial Gap tag k gap", 2);
  args.setContext("uniaxialMaterial Gap 7");
  args.integer("tag");
  args.real("k");
  args.real("gap");
  EXPECT_EQ(failure(args, "k", "must be positive"),
            "uniaxialMaterial Gap 7: argument 3 (k) must be positive, got \"-100.0\"; usage: "
            "uniaxialMaterial Gap tag k gap");
  // A field that was not read (a default) is reported for the command as a whole.
  EXPECT_EQ(failure(args, "Fy", "must be positive"),
            "uniaxialMaterial Gap 7: Fy must be positive; usage: uniaxialMaterial Gap tag k gap");
}

TEST(ArgReaderTest, ListsRecordTheirFirstValue) {
  Words w{"fix", "3", "1", "1", "0", "-tags", "4", "5"};
  ArgReader args(w.count(), w.data(), "fix node flags..");
  args.integer("node");
  const std::vector<int> flags = args.integers("flags");
  EXPECT_EQ(flags.size(), 3u);
  EXPECT_EQ(args.positionOf("flags"), 2u);
  EXPECT_TRUE(args.optionIntegerList("-tags").has_value());
  EXPECT_EQ(args.positionOf("tags"), 6u);
}

TEST(ArgReaderTest, FailArgumentWithAnIndexPointsIntoAList) {
  Words w{"equalDOF", "1", "2", "1", "3", "1"};
  ArgReader args(w.count(), w.data(), "equalDOF rNode cNode dofs..");
  args.integer("rNode");
  args.integer("cNode");
  (void)args.integers("dof");
  std::string message;
  try {
    args.failArgument("dof", 2, "is given twice");
  } catch (const ArgError& e) {
    message = e.what();
  }
  EXPECT_EQ(
      message,
      "equalDOF: argument 5 (dof) is given twice, got \"1\"; usage: equalDOF rNode cNode dofs..");
}

std::string inputFailure(const ArgReader& args, const InputError& error) {
  try {
    args.failInput(error);
  } catch (const ArgError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ArgReaderTest, FailInputKeepsTheErrorsSentenceAtItsArgument) {
  Words w{"node", "7", "-mass", "-2.0"};
  ArgReader args(w.count(), w.data(), "node tag ?-mass m?");
  args.integer("tag");
  (void)args.optionReals("-mass", 1);
  // The field is the subject of the sentence; the token is added unless the sentence has it.
  EXPECT_EQ(inputFailure(args, InputError("mass", "must not be negative")),
            "node: argument 3: mass must not be negative, got \"-2.0\"; usage: node tag ?-mass m?");
  EXPECT_EQ(inputFailure(args, InputError("tag", "7 already exists")),
            "node: argument 1: tag 7 already exists; usage: node tag ?-mass m?");
  // No field, or one never read: the command as a whole.
  EXPECT_EQ(inputFailure(args, InputError("", "the model is empty")),
            "node: the model is empty; usage: node tag ?-mass m?");
  EXPECT_EQ(inputFailure(args, InputError("ndf", "must be 1 to 6")),
            "node: ndf must be 1 to 6; usage: node tag ?-mass m?");
}

}  // namespace
}  // namespace dabs::tcl
