// SPDX-License-Identifier: MIT
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

std::span<const UniaxialEntry> uniaxialParsers() { return {}; }

}  // namespace dabs::tcl
