// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <span>
#include <vector>

#include "tcl/commands/Registry.h"

namespace dabs::tcl {

/// What Tcl holds as ClientData for one command: the runtime and the table row.
struct CommandBinding {
  Runtime* runtime;
  const CommandEntry* entry;
};

/// Families of commands a program adds to those of this library, after them (the programs pass
/// the parallel commands of tcl/parallel, which depends on this library and not the reverse).
using CommandFamilies = std::span<const std::span<const CommandEntry>>;

/// Creates a Runtime for `interp`, registers every command of every family of this library and
/// of `extra`, and arranges for the runtime to be deleted with the interpreter. Returns TCL_OK or
/// TCL_ERROR.
int registerCommands(Tcl_Interp* interp, CommandFamilies extra = {});

/// The rows of every command registerCommands creates with the same `extra`, in table order (for
/// bindings that expose each command under its own name, such as the Python module). The rows
/// have static storage.
std::vector<const CommandEntry*> commandEntries(CommandFamilies extra = {});

/// Runs one command row: builds the ArgReader, calls the row, and turns ArgError/InputError into a
/// Tcl error whose message names the command and argument (style.md section 5).
int runCommand(Runtime& rt, const CommandEntry& entry, int objc, Tcl_Obj* const objv[]);

/// Finds a row by type name among several tables (for `uniaxialMaterial`, `element`); null if none.
template <class Entry>
const Entry* findType(std::initializer_list<std::span<const Entry>> tables, std::string_view type) {
  for (const auto& table : tables)
    for (const Entry& e : table)
      if (e.type == type) return &e;
  return nullptr;
}

/// Comma-separated list of the type names in several tables (for error messages).
template <class Entry>
std::string typeNames(std::initializer_list<std::span<const Entry>> tables) {
  std::string out;
  for (const auto& table : tables)
    for (const Entry& e : table) out += (out.empty() ? "" : ", ") + std::string(e.type);
  return out;
}

}  // namespace dabs::tcl
