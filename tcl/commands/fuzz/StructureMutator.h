// SPDX-License-Identifier: MIT
// The structure-aware half of the command fuzzer: it reads an input as Tcl commands and words and
// changes one argument slot at a time, where libFuzzer's own mutations change bytes (which rarely
// turn a number into a blank word and keep the command valid around it). See README.md.
#pragma once

#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace dabs::tcl::fuzz {

/// What an argument slot holds, read from the word itself.
enum class Kind { Integer, Real, Option, List, Blank, Word };

/// The kind of `word`: an integer, a real number, an option word (-letter...), a list of more
/// than one word, a blank (empty or white space only) word, or any other word.
Kind kindOf(std::string_view word);

/// The grammar file commands.grammar (made by make-grammar.py): a small model, an analysis and
/// command lines whose words are the argument slots of every command and type word.
struct Grammar {
  std::string prelude;                              ///< commands making a small 3D model
  std::string tail;                                 ///< an analysis of a few steps
  std::vector<std::vector<std::string>> templates;  ///< the words of each command line
  std::vector<std::string> options;                 ///< every option word of the templates
  std::vector<std::string> typeWords;               ///< every second word that is not a number

  /// Reads the grammar file's text (sections %prelude, %tail, %command; '#' lines are comments).
  static Grammar parse(std::string_view text);
};

/// Makes new scripts from old ones by one change to their structure. Deterministic for a seed,
/// as libFuzzer's custom mutators must be.
class StructureMutator {
 public:
  explicit StructureMutator(Grammar grammar);

  /// `script` changed once: a word replaced by a value of another kind (a number by a blank word,
  /// a list, NaN, an option, ...), a word taken from a template of the same command, an option
  /// repeated, words grouped into a list or a list spread into words, a word deleted, a template
  /// inserted; or, for an empty or unreadable script, a new one (see generate()).
  std::string mutate(std::string_view script, unsigned seed);

  /// A new script: the prelude, one template with one slot changed, and sometimes the tail.
  std::string generate(unsigned seed);

  const Grammar& grammar() const noexcept { return grammar_; }

 private:
  // A command of a script: its words, or its text when it is not a plain list of words (a
  // comment, a command Tcl cannot split as a list).
  struct Command {
    std::vector<std::string> words;
    std::string text;
    bool parsed = false;
  };

  static std::vector<Command> split(std::string_view script);
  static std::string join(const std::vector<Command>& commands);
  // Changes one slot of `words` (never the command word unless `anyWord`); false when no
  // change applies.
  bool mutateWords(std::vector<std::string>& words, bool anyWord);
  std::string valueOfKind(Kind kind);
  const std::vector<std::string>* templateLike(const std::vector<std::string>& words);

  Grammar grammar_;
  std::mt19937 rng_;
  int depth_ = 0;  // nesting of script bodies being mutated (pattern {...}, section {...})
};

}  // namespace dabs::tcl::fuzz
