// SPDX-License-Identifier: MIT
#pragma once

namespace dabs {

/// Outcome of a numerical operation (material return map, element update, solve, analysis step).
/// Numerical non-convergence is a result, never an exception (style.md section 6). The integer
/// values are what `analyze` returns to Tcl, as OpenSees' analyzeModel does (0 = success).
enum class Status : int {
  Ok = 0,
  NotConverged = -3,  ///< an iteration (local or global) ran out of iterations
  Singular = -2,      ///< a factorisation met a zero pivot
  NonFinite = -4,     ///< NaN or Inf appeared in a trial state
  Failed = -1,        ///< any other failure (invalid state, bad geometry found while updating)
};

/// True when the operation succeeded.
[[nodiscard]] constexpr bool ok(Status s) noexcept { return s == Status::Ok; }

/// Integer code of a status, as returned by Tcl commands.
[[nodiscard]] constexpr int code(Status s) noexcept { return static_cast<int>(s); }

}  // namespace dabs
