// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tcl/parallel/Communicator.h"

namespace dabs::parallel {

/// Hands jobs out to the processes as they become free (dynamic scheduling: run times differ by
/// an order of magnitude between a quiet and a pounding run, so a fixed share per process would
/// leave most of them waiting for the slowest).
///
/// Process 0 owns the queue. A worker asks for a job, runs it and asks again, sending the finished
/// job's result with its request; process 0 stores each result as it arrives. Process 0 runs jobs
/// too: a dispatcher thread answers the workers while its main thread runs jobs (when the
/// communicator allows a second thread; otherwise process 0 only dispatches). Jobs are handed out
/// in the order given. With one process, the main thread runs every job in order.
class JobFarm {
 public:
  /// Runs job `index` on this process and returns its result (on the main thread only).
  using RunFn = std::function<std::string(int index)>;
  /// Stores the result of job `index` on process 0; called from process 0's main thread and from
  /// its dispatcher thread, one call at a time.
  using StoreFn = std::function<void(int index, const std::string& result)>;

  /// `comm` must be a channel used by nothing else while the farm runs (Communicator::duplicate).
  explicit JobFarm(Communicator& comm) : comm_(comm) {}

  /// Runs the jobs `pending` (read on process 0 only; the others get them one by one) and returns
  /// the number of jobs this process ran. Collective: every process calls it; it returns on
  /// process 0 once every result is stored.
  int run(const std::vector<int>& pending, const RunFn& runJob, const StoreFn& store);

 private:
  int runRoot(const std::vector<int>& pending, const RunFn& runJob, const StoreFn& store);
  int runWorker(const RunFn& runJob);

  Communicator& comm_;
};

}  // namespace dabs::parallel
