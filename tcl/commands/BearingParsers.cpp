// SPDX-License-Identifier: MIT
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

std::span<const CommandEntry> bearingCommands() { return {}; }
std::span<const ElementEntry> bearingElementParsers() { return {}; }

}  // namespace dabs::tcl
