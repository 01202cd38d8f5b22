// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace dabs {
class InputError;
}

namespace dabs::tcl {

/// A command argument that cannot be used. The message names the command (and type and tag when
/// known), the argument's position and name, the bad token and the usage line, e.g.
/// `uniaxialMaterial Restrainer 7: argument 4 (gap) expected a number, got "abc"; usage: ...`.
class ArgError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The one argument parser of the Tcl layer (style.md section 5): reads positional arguments in
/// order and `-key value` options from anywhere after them, over Tcl's objc/objv, so no command
/// writes its own parsing loop. Every failure throws ArgError with a complete message.
///
/// Positional readers stop at an option word (a token starting with '-' that is not a number), so
/// a missing positional argument is reported as such. Options are consumed wherever they stand;
/// `finish()` rejects anything left over.
class ArgReader {
 public:
  /// `objv[0]` is the command word; reading starts at `objv[first]`.
  ArgReader(int objc, Tcl_Obj* const objv[], std::string usage, int first = 1);

  /// Sets the prefix of error messages, e.g. "uniaxialMaterial Steel02 7", once type and tag are
  /// read.
  void setContext(std::string context) { context_ = std::move(context); }
  /// Replaces the usage line shown in error messages (after a type word selected a sub-command).
  void setUsage(std::string usage) { usage_ = std::move(usage); }
  const std::string& context() const noexcept { return context_; }
  const std::string& usage() const noexcept { return usage_; }

  // --- positional arguments -------------------------------------------------------------
  /// Next positional argument as an integer.
  int integer(std::string_view name);
  /// Next positional argument as a real number.
  double real(std::string_view name);
  /// Next positional argument as a word (any string, including one starting with '-').
  std::string word(std::string_view name);
  /// Next positional argument as a Tcl object (e.g. a script body), without conversion.
  Tcl_Obj* object(std::string_view name);
  /// Next positional argument as a real number when one follows, else nullopt.
  std::optional<double> optionalReal(std::string_view name);
  /// Next positional argument as an integer when one follows, else nullopt.
  std::optional<int> optionalInteger(std::string_view name);
  /// All following positional integers (at least `atLeast`).
  std::vector<int> integers(std::string_view name, std::size_t atLeast = 1);
  /// All following positional real numbers (at least `atLeast`).
  std::vector<double> reals(std::string_view name, std::size_t atLeast = 1);
  /// Exactly `count` following real numbers.
  std::vector<double> reals(std::string_view name, std::size_t count, bool exact);
  /// True when another positional (non-option) argument follows.
  bool hasPositional() const;
  /// True when any unread argument remains.
  bool hasMore() const;
  /// The next unread token, without consuming it ("" at the end).
  std::string_view peek() const;

  // --- options -------------------------------------------------------------------------
  /// Consumes a bare flag such as "-time"; true when present.
  bool flag(std::string_view key);
  /// Consumes "-key value" and returns the value, or `fallback` when absent.
  double option(std::string_view key, double fallback);
  int option(std::string_view key, int fallback);
  std::string option(std::string_view key, const std::string& fallback);
  /// Consumes "-key value" when present.
  std::optional<double> optionalOption(std::string_view key);
  std::optional<std::string> optionalWordOption(std::string_view key);
  /// Consumes the number right after the value of option `key`, which must have been read (as in
  /// "-afterFailure drop h", read by optionalWordOption("-afterFailure") and then
  /// realAfterOption("-afterFailure", "h")); the number is recorded under `name`.
  double realAfterOption(std::string_view key, std::string_view name);
  /// Consumes the numbers right after the value of option `key` (read before), one per name, each
  /// recorded under its name (as in "-vertical kumar G Kbulk ...").
  std::vector<double> realsAfterOption(std::string_view key,
                                       std::initializer_list<std::string_view> names);
  /// Consumes "-key v1 v2 ... vn" (exactly n reals) when present.
  std::optional<std::vector<double>> optionReals(std::string_view key, std::size_t n);
  /// Consumes "-key v1 v2 ..." with every following number when present (at least one).
  std::optional<std::vector<double>> optionRealList(std::string_view key);
  /// Consumes "-key i1 i2 ..." with every following integer when present (at least one).
  std::optional<std::vector<int>> optionIntegerList(std::string_view key);

  /// Consumes "-key first last" (two integer tags, first <= last) when present.
  std::optional<std::pair<int, int>> optionTagRange(std::string_view key);

  /// Throws when any argument is left unread.
  void finish() const;

  /// Throws an ArgError about the argument at position `pos` (1-based, as in the command line).
  [[noreturn]] void fail(std::size_t pos, std::string_view name, std::string_view what) const;
  /// Throws an ArgError about the command as a whole.
  [[noreturn]] void fail(std::string_view what) const;
  /// Position (1-based) of the most recently read positional argument.
  std::size_t lastPosition() const noexcept { return last_; }
  /// Position (1-based) of the argument last read under `name`: a positional argument's name, or
  /// an option's key with or without its '-' (the position of the option's first value); 0 when
  /// nothing was read under that name. Every reader records it, so a validation error raised
  /// after reading (an InputError naming a field) can point at the argument it is about.
  std::size_t positionOf(std::string_view name) const noexcept;
  /// Throws an ArgError about the argument read under `name` ("argument N (name) what, got
  /// "token""), or about the command as a whole ("name what") when none was read under it.
  [[noreturn]] void failArgument(std::string_view name, std::string_view what) const;
  /// Throws an ArgError about the `index`-th value (from 0) of the list read under `name`.
  [[noreturn]] void failArgument(std::string_view name, std::size_t index,
                                 std::string_view what) const;
  /// Throws an ArgError for a validation error: "argument N: <field reason>, got "token"" at the
  /// argument read under its field, or "<field reason>" about the command as a whole when the
  /// field is empty or was not read. The command table reports every escaping InputError so.
  [[noreturn]] void failInput(const InputError& error) const;
  /// The token at position `pos` (1-based, as positionOf returns), "" past the end.
  std::string_view token(std::size_t pos) const { return pos < tokens_.size() ? text(pos) : ""; }

 private:
  std::size_t findKey(std::string_view key) const;  // index in tokens_ or npos
  std::size_t nextUnread() const;                   // index of next unused token or size
  std::string_view text(std::size_t i) const;
  [[noreturn]] void expected(std::size_t i, std::string_view name, std::string_view what) const;
  void record(std::string_view name, std::size_t i);  // argument i was read under `name`
  // The last (name, position) read under `name` (or under "-name"), or null.
  const std::pair<std::string, std::size_t>* readUnder(std::string_view name) const;

  std::vector<Tcl_Obj*> tokens_;  // tokens_[0] is the command word
  std::vector<bool> used_;
  // No token before it is unread (tokens are only ever marked used): nextUnread starts there, so
  // reading a list of n arguments is linear in n, not quadratic.
  mutable std::size_t firstUnread_ = 0;
  std::string usage_;
  std::string context_;
  std::size_t last_ = 0;
  std::vector<std::pair<std::string, std::size_t>> named_;  // (name, position) of every read
};

/// True for a token that is an option word: starts with '-' followed by a letter.
bool isOptionWord(std::string_view token) noexcept;

// The reader's own number rules, for words it does not hand out itself (items of a Tcl list
// given as one argument, a word that may be a tag or a spec).
/// `obj` as an int (within 32 bits, never wrapped around), or nullopt.
std::optional<int> integerValue(Tcl_Obj* obj);
/// `obj` as a finite real number, or nullopt.
std::optional<double> realValue(Tcl_Obj* obj);
/// What an integer word expects: "expected an integer", with the range when `obj` is a decimal
/// integer too large for an int.
std::string integerExpectation(Tcl_Obj* obj);
/// True when `token` is a decimal integer (optionally signed) of any size.
bool isIntegerWord(std::string_view token) noexcept;

}  // namespace dabs::tcl
