// SPDX-License-Identifier: MIT
// The uniaxialMaterial parsers called directly through an ArgReader built from Tcl objects, as
// the dispatcher will call them (type word consumed, tag read with readNewTag).

#include "tcl/commands/UniaxialParsers.h"

#include <gtest/gtest.h>
#include <tcl.h>

#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "materials/Concrete02.h"
#include "materials/InputError.h"
#include "materials/ElasticPPGap.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {
namespace {

using ParseFn = uniaxial::MaterialPtr (*)(ArgReader&, int);

class UniaxialParsersTest : public ::testing::Test {
 protected:
  void SetUp() override { interp_ = Tcl_CreateInterp(); }
  void TearDown() override {
    for (Tcl_Obj* o : objs_) Tcl_DecrRefCount(o);
    Tcl_DeleteInterp(interp_);
  }

  /// ArgReader over `line` (words separated by spaces) positioned after type and tag.
  ArgReader reader(const std::string& line, int& tag) {
    std::istringstream in(line);
    std::vector<Tcl_Obj*> objv;
    for (std::string w; in >> w;) {
      Tcl_Obj* o = Tcl_NewStringObj(w.c_str(), -1);
      Tcl_IncrRefCount(o);
      objs_.push_back(o);
      objv.push_back(o);
    }
    std::string usage;
    for (const auto& row : uniaxialParsers())
      if (objv.size() > 1 && row.type == Tcl_GetString(objv[1])) usage = std::string(row.usage);
    ArgReader args(static_cast<int>(objv.size()), objv.data(), usage, 2);
    tag = readNewTag(args, builder_.uniaxial, "uniaxialMaterial");
    return args;
  }

  uniaxial::MaterialPtr parse(ParseFn fn, const std::string& line) {
    int tag = 0;
    ArgReader args = reader(line, tag);
    return fn(args, tag);
  }

  /// The error message of parsing `line`, or "" when it parses.
  /// A validation error is reported as the command table reports it (ArgReader::failInput).
  std::string error(ParseFn fn, const std::string& line) {
    try {
      int tag = 0;
      ArgReader args = reader(line, tag);
      try {
        fn(args, tag);
      } catch (const InputError& e) {
        args.failInput(e);
      }
    } catch (const ArgError& e) {
      return e.what();
    }
    return "";
  }
  std::string compositeError(uniaxial::MaterialPtr (*fn)(ArgReader&, int,
                                                         const domain::ModelBuilder&),
                             const std::string& line) {
    try {
      int tag = 0;
      ArgReader args = reader(line, tag);
      try {
        fn(args, tag, builder_);
      } catch (const InputError& e) {
        args.failInput(e);
      }
    } catch (const ArgError& e) {
      return e.what();
    }
    return "";
  }

  Tcl_Interp* interp_ = nullptr;
  std::vector<Tcl_Obj*> objs_;
  domain::ModelBuilder builder_;
};

/// Passes when `text` contains `part`; prints the text otherwise.
::testing::AssertionResult Contains(const std::string& text, const std::string& part) {
  if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "\"" << text << "\" does not contain \"" << part << "\"";
}

TEST_F(UniaxialParsersTest, TableHasEveryTypeOnceWithItsUsage) {
  std::set<std::string> types;
  for (const auto& row : uniaxialParsers()) {
    EXPECT_TRUE(types.insert(std::string(row.type)).second) << row.type;
    EXPECT_EQ(row.usage.substr(0, 17 + row.type.size() + 4),
              "uniaxialMaterial " + std::string(row.type) + " tag");
    EXPECT_NE(row.parse, nullptr);
  }
  EXPECT_EQ(types, (std::set<std::string>{"Elastic", "ElasticPP", "ElasticPPGap", "Steel01",
                                          "Steel02", "Concrete01", "Concrete02", "Viscous", "ENT",
                                          "Parallel", "Series", "Fatigue"}));
}

TEST_F(UniaxialParsersTest, Steel02DefaultsAndOptionalGroups) {
  auto m = parse(uniaxial::parseSteel02, "uniaxialMaterial Steel02 7 400 2e5 0.01");
  const auto& p = dynamic_cast<const materials::Steel02&>(*m).params();
  EXPECT_EQ(m->tag(), 7);
  EXPECT_DOUBLE_EQ(p.R0, 15.0);
  EXPECT_DOUBLE_EQ(p.cR1, 0.925);
  EXPECT_DOUBLE_EQ(p.cR2, 0.15);
  EXPECT_DOUBLE_EQ(p.a2, 1.0);
  auto full = parse(uniaxial::parseSteel02,
                    "uniaxialMaterial Steel02 8 400 2e5 0.01 18 0.9 0.1 0.02 1 0.03 1 50");
  const auto& q = dynamic_cast<const materials::Steel02&>(*full).params();
  EXPECT_DOUBLE_EQ(q.R0, 18.0);
  EXPECT_DOUBLE_EQ(q.a3, 0.03);
  EXPECT_DOUBLE_EQ(q.sigInit, 50.0);
}

TEST_F(UniaxialParsersTest, ErrorsNameTheArgument) {
  const std::string bad = error(uniaxial::parseSteel02, "uniaxialMaterial Steel02 7 abc 2e5 0.01");
  EXPECT_TRUE(Contains(bad, "uniaxialMaterial Steel02 7: argument 3 (Fy) expected a number"));
  EXPECT_TRUE(Contains(bad, "usage: uniaxialMaterial Steel02 tag Fy E b"));
  EXPECT_TRUE(Contains(error(uniaxial::parseSteel02, "uniaxialMaterial Steel02 7 -400 2e5 0.01"),
                       "argument 3: Fy must be positive, got \"-400\""));
  EXPECT_TRUE(Contains(error(uniaxial::parseSteel02, "uniaxialMaterial Steel02 7 400 2e5 0.01 18"),
                       "(cR1)"));
  EXPECT_TRUE(Contains(
      error(uniaxial::parseSteel01, "uniaxialMaterial Steel01 7 400 2e5 0.01 0.1 5"), "(a3)"));
  EXPECT_TRUE(Contains(
      error(uniaxial::parseConcrete01, "uniaxialMaterial Concrete01 4 -30 -0.002 -6 -0.001"),
      "argument 6: epsU must exceed epsc0"));
  EXPECT_TRUE(Contains(
      error(uniaxial::parseConcrete02, "uniaxialMaterial Concrete02 4 -30 -0.002 -6 -0.006 0.1 3"),
      "(Ets)"));
  EXPECT_TRUE(Contains(error(uniaxial::parseElastic, "uniaxialMaterial Elastic 1 100 1 2 3"),
                       "unexpected argument \"3\""));
  EXPECT_TRUE(Contains(error(uniaxial::parseViscous, "uniaxialMaterial Viscous 1 10 -1"),
                       "argument 4: alpha must be positive, got \"-1\""));
  EXPECT_TRUE(Contains(error(uniaxial::parseENT, "uniaxialMaterial ENT 1"), "(E)"));
}

TEST_F(UniaxialParsersTest, ElasticPPGapDamageWord) {
  auto a = parse(uniaxial::parseElasticPPGap, "uniaxialMaterial ElasticPPGap 6 1000 -50 -0.001");
  EXPECT_FALSE(dynamic_cast<const materials::ElasticPPGap&>(*a).params().damage);
  auto b =
      parse(uniaxial::parseElasticPPGap, "uniaxialMaterial ElasticPPGap 7 1000 5 0.002 0.0 damage");
  EXPECT_TRUE(dynamic_cast<const materials::ElasticPPGap&>(*b).params().damage);
  auto c =
      parse(uniaxial::parseElasticPPGap, "uniaxialMaterial ElasticPPGap 8 1000 5 0.002 damage");
  EXPECT_TRUE(dynamic_cast<const materials::ElasticPPGap&>(*c).params().damage);
  EXPECT_TRUE(Contains(
      error(uniaxial::parseElasticPPGap, "uniaxialMaterial ElasticPPGap 9 1000 5 0.002 0.1 broken"),
      "unexpected argument \"broken\""));
  EXPECT_TRUE(Contains(
      error(uniaxial::parseElasticPPGap, "uniaxialMaterial ElasticPPGap 9 1000 5 0.002 1.5"),
      "argument 6: eta must be less than 1, got \"1.5\""));
}

TEST_F(UniaxialParsersTest, Concrete02DefaultsAsOpenSees) {
  auto m = parse(uniaxial::parseConcrete02, "uniaxialMaterial Concrete02 5 -30 -0.002 -6 -0.006");
  const auto& p = dynamic_cast<const materials::Concrete02&>(*m).params();
  EXPECT_DOUBLE_EQ(p.lambda, 0.1);
  EXPECT_DOUBLE_EQ(p.ft, 3.0);
  EXPECT_DOUBLE_EQ(p.Ets, 1500.0);
}

TEST_F(UniaxialParsersTest, ParallelAndSeriesUsePrototypes) {
  builder_.uniaxial[1] = parse(uniaxial::parseElastic, "uniaxialMaterial Elastic 1 100");
  builder_.uniaxial[2] = parse(uniaxial::parseElastic, "uniaxialMaterial Elastic 2 300");
  int tag = 0;
  {
    ArgReader args = reader("uniaxialMaterial Parallel 3 1 2 -factors 2 0.5", tag);
    auto m = uniaxial::parseParallel(args, tag, builder_);
    EXPECT_DOUBLE_EQ(m->getInitialTangent(), 2.0 * 100.0 + 0.5 * 300.0);
  }
  {
    ArgReader args = reader("uniaxialMaterial Series 4 1 2", tag);
    auto m = uniaxial::parseSeries(args, tag, builder_);
    EXPECT_DOUBLE_EQ(m->getInitialTangent(), 75.0);
  }
  EXPECT_TRUE(Contains(compositeError(uniaxial::parseParallel, "uniaxialMaterial Parallel 3 1 9"),
                       "argument 4 (matTag) uniaxialMaterial 9 does not exist"));
  EXPECT_TRUE(Contains(
      compositeError(uniaxial::parseParallel, "uniaxialMaterial Parallel 3 1 2 -factors 1"),
      "-factors"));
  EXPECT_TRUE(Contains(compositeError(uniaxial::parseSeries, "uniaxialMaterial Series 4 1"),
                       "(matTag) expected at least 2 integers"));
}

TEST_F(UniaxialParsersTest, DuplicateTagIsRejectedByReadNewTag) {
  builder_.uniaxial[1] = parse(uniaxial::parseENT, "uniaxialMaterial ENT 1 100");
  EXPECT_TRUE(Contains(error(uniaxial::parseENT, "uniaxialMaterial ENT 1 100"),
                       "uniaxialMaterial 1 already exists"));
}

}  // namespace
}  // namespace dabs::tcl
