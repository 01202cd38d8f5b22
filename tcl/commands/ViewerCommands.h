// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/commands/ArgReader.h"
#include "tcl/commands/Runtime.h"

namespace dabs::tcl {

/// `recorder Viewer -file page.html ?-dT dt? ?-nodes tags? ?-plots {plot ...}? ?-title text?`
/// with each plot `{label node tag dof disp|vel|accel}` or `{label ele tag response.. component}`
/// (dof and component from 1). Adds a domain::ViewerRecorder and sets the result to its tag.
/// Called by `recorder` with the reader positioned after the type word.
void viewerRecorderCommand(Runtime& rt, ArgReader& a);

}  // namespace dabs::tcl
