// SPDX-License-Identifier: MIT
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

std::span<const CommandEntry> materialTestCommands() { return {}; }

}  // namespace dabs::tcl
