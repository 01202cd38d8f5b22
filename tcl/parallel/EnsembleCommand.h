// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/commands/Registry.h"

namespace dabs::parallel {

/// `ensemble run jobList command ?-out dir?`: runs every job of jobList, each a dict of
/// parameters, as `{*}command job` in a fresh model (after `wipe`), spread over the processes by
/// the JobFarm. The command returns a dict of results (an optional key `code` is the analysis
/// status: 0 ok, anything else failed). Each job's result goes to `dir/jobs/<id>.csv` when it
/// finishes (atomically), then all of them to `dir/results.csv`; a rerun skips the jobs whose
/// result is there (ok or failed) with the same parameters. A job raising a Tcl error is recorded
/// with status `error` and its message, is run again by a rerun, and the others go on. The id of a
/// job is its `id` key, or job0001, job0002, ... by position. Returns (on every process) a dict:
/// jobs, ran, skipped, ok, failed, error, file.
void ensembleCmd(tcl::Runtime& rt, tcl::ArgReader& a);

}  // namespace dabs::parallel
