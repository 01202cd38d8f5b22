// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <span>
#include <string_view>

#include "elements/Element.h"
#include "materials/UniaxialMaterial.h"
#include "tcl/commands/ArgReader.h"
#include "tcl/commands/Runtime.h"

namespace dabs::tcl {

/// A Tcl command: reads its arguments with `args` (positioned after the command word) and sets the
/// interpreter result on success; throws ArgError or InputError on bad input (the dispatcher turns
/// them into TCL_ERROR with the message), and must not change the model before all checks passed.
using CommandFn = void (*)(Runtime& rt, ArgReader& args);

/// One row of the command table.
struct CommandEntry {
  std::string_view name;
  std::string_view usage;  ///< shown in error messages
  CommandFn fn;
};

/// Parses `uniaxialMaterial <type> tag ...` after the tag; returns the validated prototype.
using UniaxialParser = std::unique_ptr<materials::UniaxialMaterial> (*)(Runtime& rt,
                                                                        ArgReader& args, int tag);
/// Parses `element <type> tag ...` after the tag; returns the element (not yet in the domain).
using ElementParser = std::unique_ptr<elements::Element> (*)(Runtime& rt, ArgReader& args, int tag);

/// One row of a type-dispatch table (`uniaxialMaterial`, `element`).
template <class Parser>
struct TypeEntry {
  std::string_view type;
  std::string_view usage;  ///< full usage line, e.g. "uniaxialMaterial Elastic tag E ?eta? ?Eneg?"
  Parser parse;
};
using UniaxialEntry = TypeEntry<UniaxialParser>;
using ElementEntry = TypeEntry<ElementParser>;

// Each family of commands lives in its own file and exposes its rows here; CommandTable.cpp
// registers them all. Adding a family means adding one function and one line there.

std::span<const CommandEntry> modelCommands();         // ModelCommands.cpp
std::span<const CommandEntry> loadCommands();          // LoadCommands.cpp
std::span<const CommandEntry> analysisCommands();      // AnalysisCommands.cpp
std::span<const CommandEntry> queryCommands();         // QueryCommands.cpp
std::span<const CommandEntry> recorderCommands();      // RecorderCommands.cpp
std::span<const CommandEntry> materialTestCommands();  // MaterialTestCommands.cpp
std::span<const CommandEntry> sectionCommands();       // SectionParsers.cpp (section, fiber, ...)
std::span<const CommandEntry> beamCommands();     // BeamParsers.cpp (geomTransf, beamIntegration)
std::span<const CommandEntry> bearingCommands();  // BearingParsers.cpp (biaxialMaterial)
std::span<const CommandEntry> contactCommands();  // ContactParsers.cpp (pounding)

std::span<const UniaxialEntry> uniaxialParsers();         // UniaxialParsers.cpp
std::span<const UniaxialEntry> contactUniaxialParsers();  // ContactParsers.cpp (Restrainer, Bumper)

std::span<const ElementEntry> linkElementParsers();     // LinkParsers.cpp (zeroLength, truss)
std::span<const ElementEntry> beamElementParsers();     // BeamParsers.cpp
std::span<const ElementEntry> bearingElementParsers();  // BearingParsers.cpp
std::span<const ElementEntry> contactElementParsers();  // ContactParsers.cpp

/// Reads `tag`, checks it is unused in `map`, and sets the reader's context to "<cmd> <type>
/// <tag>". Shared by every type-dispatching command so tag checks read the same everywhere.
template <class Map>
int readNewTag(ArgReader& args, const Map& map, std::string_view what) {
  const int tag = args.integer("tag");
  args.setContext(args.context() + " " + std::to_string(tag));
  if (map.count(tag) != 0)
    args.fail(args.lastPosition(), "tag",
              std::string(what) + " " + std::to_string(tag) + " already exists");
  return tag;
}

}  // namespace dabs::tcl
