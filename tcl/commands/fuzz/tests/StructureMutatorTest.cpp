// SPDX-License-Identifier: MIT
// The fuzzer's structure-aware mutator and its grammar: slot kinds, one change per mutation, the
// blank and list words it was written to produce, and a grammar that covers the command table
// and whose model runs.
#include "tcl/commands/fuzz/StructureMutator.h"

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "tcl/commands/tests/TclFixture.h"

namespace dabs::tcl::fuzz {

namespace {

Grammar committedGrammar() {
  std::ifstream in(std::string(DABS_SOURCE_DIR) + "/tcl/commands/fuzz/commands.grammar");
  std::stringstream text;
  text << in.rdbuf();
  return Grammar::parse(text.str());
}

// Seeds tried in the statistical tests: enough that every kind of change is drawn many times.
constexpr unsigned kSeeds = 2000;

}  // namespace

TEST(StructureMutatorTest, KindIsReadFromTheWord) {
  EXPECT_EQ(kindOf("12"), Kind::Integer);
  EXPECT_EQ(kindOf("-4294967296"), Kind::Integer);
  EXPECT_EQ(kindOf("1.5e3"), Kind::Real);
  EXPECT_EQ(kindOf("NaN"), Kind::Real);
  EXPECT_EQ(kindOf("-mass"), Kind::Option);
  EXPECT_EQ(kindOf("Lobatto 1 3"), Kind::List);
  EXPECT_EQ(kindOf("  "), Kind::Blank);
  EXPECT_EQ(kindOf(""), Kind::Blank);
  EXPECT_EQ(kindOf("Lobatto"), Kind::Word);
}

TEST(StructureMutatorTest, GrammarReadsItsSections) {
  const Grammar g = Grammar::parse(
      "# comment\n%prelude\nmodel basic -ndm 3\n%tail\nanalyze 1\n%command\n"
      "element truss 100 1 2 1.0 1 -rho 2.0\npattern Plain 100 1 { load 2 1.0 }\n");
  EXPECT_EQ(g.prelude, "model basic -ndm 3\n");
  EXPECT_EQ(g.tail, "analyze 1\n");
  ASSERT_EQ(g.templates.size(), 2u);
  EXPECT_EQ(g.templates[1].back(), " load 2 1.0 ");
  EXPECT_EQ(g.options, std::vector<std::string>{"-rho"});
  EXPECT_EQ(g.typeWords, (std::vector<std::string>{"Plain", "truss"}));
}

TEST(StructureMutatorTest, SameSeedSameScript) {
  StructureMutator a(committedGrammar()), b(committedGrammar());
  const std::string script = a.generate(7);
  EXPECT_EQ(script, b.generate(7));
  for (unsigned seed = 0; seed < 50; ++seed)
    EXPECT_EQ(a.mutate(script, seed), b.mutate(script, seed));
}

TEST(StructureMutatorTest, ChangesOneCommandOfAScript) {
  StructureMutator m(committedGrammar());
  const std::string script = m.grammar().prelude + "element forceBeamColumn 100 2 3 1 1\n";
  const std::size_t lines =
      static_cast<std::size_t>(std::count(script.begin(), script.end(), '\n'));
  unsigned changed = 0;
  for (unsigned seed = 1; seed < kSeeds; ++seed) {
    if (seed % 16 == 0) continue;  // a few seeds start a new script instead
    const std::string out = m.mutate(script, seed);
    if (out != script) ++changed;
    // One command changed, inserted, repeated or left out: the rest of the model is kept.
    std::istringstream before(script), after(out);
    std::set<std::string> a, b;
    for (std::string l; std::getline(before, l);) a.insert(l);
    for (std::string l; std::getline(after, l);) b.insert(l);
    std::size_t kept = 0;
    for (const std::string& l : a) kept += b.count(l);
    EXPECT_GE(kept + 2, lines) << out;
  }
  EXPECT_GT(changed, kSeeds * 8 / 10);
}

TEST(StructureMutatorTest, ProducesBlankAndListWordsInArgumentSlots) {
  // The class of input that crashed forceBeamColumn ("  " where the integration rule goes):
  // a blank word, or a list word, in the place of an argument of a valid command.
  StructureMutator m(committedGrammar());
  const std::string script = "element forceBeamColumn 100 2 3 1 1\n";
  std::set<std::string> blankSlots, listSlots;
  for (unsigned seed = 1; seed < kSeeds; ++seed) {
    const std::string out = m.mutate(script, seed);
    int n = 0;
    const char** words = nullptr;
    if (out.rfind("element forceBeamColumn", 0) != 0 ||
        Tcl_SplitList(nullptr, out.c_str(), &n, &words) != TCL_OK)
      continue;
    for (int i = 2; i < n; ++i) {
      if (kindOf(words[i]) == Kind::Blank) blankSlots.insert(std::to_string(i));
      if (kindOf(words[i]) == Kind::List) listSlots.insert(std::to_string(i));
    }
    Tcl_Free(reinterpret_cast<char*>(words));
  }
  EXPECT_GE(blankSlots.size(), 4u);  // every slot from the tag to the integration tag
  EXPECT_GE(listSlots.size(), 4u);
}

TEST(StructureMutatorTest, GrammarHasEveryCommandOfTheTable) {
  // The grammar is derived from the command tables: a command added since it was made is not
  // fuzzed by structure until make-grammar.py is run again.
  const Grammar g = committedGrammar();
  std::set<std::string> first;
  for (const auto& t : g.templates) first.insert(t[0]);
  for (const CommandEntry* e : commandEntries())
    EXPECT_EQ(first.count(std::string(e->name)), 1u)
        << e->name << " has no template: run tcl/commands/fuzz/make-grammar.py";
}

using StructureMutatorModelTest = dabs::tcl::testing::TclFixture;

TEST_F(StructureMutatorModelTest, PreludeAndTailRun) {
  const Grammar g = committedGrammar();
  ok(g.prelude);
  EXPECT_EQ(ok(g.tail), "0");
}

}  // namespace dabs::tcl::fuzz
