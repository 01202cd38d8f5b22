// SPDX-License-Identifier: MIT
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

std::span<const CommandEntry> contactCommands() { return {}; }
std::span<const UniaxialEntry> contactUniaxialParsers() { return {}; }
std::span<const ElementEntry> contactElementParsers() { return {}; }

}  // namespace dabs::tcl
