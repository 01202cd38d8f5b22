// SPDX-License-Identifier: MIT
#pragma once

// The analysis strategy commands (constraints, numberer, system, test, algorithm, integrator),
// each a table of type words, and the small helpers the other analysis commands share with them.

#include <span>
#include <string>
#include <string_view>

#include "tcl/commands/ArgReader.h"
#include "tcl/commands/CommandTable.h"
#include "tcl/commands/Runtime.h"

namespace dabs::tcl::strategy {

/// A type word and what it selects, for the dispatch tables of commands whose types take no
/// arguments of their own (constraints, numberer, test, analysis).
template <class Kind>
struct KindEntry {
  std::string_view type;
  Kind kind;
};

/// Looks `type` up in `table`; an unknown type is an error at the type word listing the known ones.
template <class Entry>
inline const Entry& lookUp(ArgReader& a, std::span<const Entry> table, const std::string& type) {
  const Entry* entry = findType<Entry>({table}, type);
  if (entry == nullptr) a.failArgument("type", "expected one of " + typeNames<Entry>({table}));
  return *entry;
}

/// Writes a warning to Tcl's stderr channel (OpenSees' `opserr` goes there too).
void warn(const std::string& text);

/// `constraints Plain|Transformation|Penalty ?alphaSP alphaMP?`
void constraintsCommand(Runtime& rt, ArgReader& a);
/// `numberer Plain|RCM|AMD`
void numbererCommand(Runtime& rt, ArgReader& a);
/// `system TYPE ?solver options?` (the options are reported on stderr and ignored)
void systemCommand(Runtime& rt, ArgReader& a);
/// `test NormDispIncr|NormUnbalance|EnergyIncr tol maxIter ?pFlag? ?nType?`
void testCommand(Runtime& rt, ArgReader& a);
/// `algorithm TYPE ?options?`, one parser per type
void algorithmCommand(Runtime& rt, ArgReader& a);
/// `integrator TYPE args`, one parser per type
void integratorCommand(Runtime& rt, ArgReader& a);

}  // namespace dabs::tcl::strategy
