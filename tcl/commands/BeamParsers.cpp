// SPDX-License-Identifier: MIT
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

std::span<const CommandEntry> sectionCommands() { return {}; }
std::span<const ElementEntry> beamElementParsers() { return {}; }

}  // namespace dabs::tcl
