// SPDX-License-Identifier: MIT
#include "tcl/parallel/JobFarm.h"

#include <chrono>
#include <cstddef>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace dabs::parallel {

namespace {

// Message tags of the farm's own channel.
constexpr int kRequestTag = 1;  // worker -> 0: "" (first request) or "<index>\n<result>"
constexpr int kAssignTag = 2;   // 0 -> worker: "<index>" or "stop"
constexpr const char* kStop = "stop";

// The dispatcher polls for requests: a blocking MPI receive spins at full speed in Open MPI and
// would take a core from the jobs of process 0. A millisecond's delay in handing out a job is
// nothing beside a job's run time.
constexpr auto kPollInterval = std::chrono::milliseconds(1);

/// Queue of the jobs not yet handed out, shared by process 0's two threads.
class JobQueue {
 public:
  explicit JobQueue(const std::vector<int>& jobs) : jobs_(jobs) {}
  /// Next job, or -1 when none is left.
  int take() {
    std::lock_guard lock(mutex_);
    return next_ < jobs_.size() ? jobs_[next_++] : -1;
  }

 private:
  std::mutex mutex_;
  const std::vector<int>& jobs_;
  std::size_t next_ = 0;
};

// Splits a worker's request into the finished job's index and result; false for a first request.
bool parseFinished(const std::string& text, int& index, std::string& result) {
  if (text.empty()) return false;
  const std::size_t newline = text.find('\n');
  if (newline == std::string::npos) throw std::runtime_error("job farm: malformed request");
  index = std::stoi(text.substr(0, newline));
  result = text.substr(newline + 1);
  return true;
}

}  // namespace

int JobFarm::run(const std::vector<int>& pending, const RunFn& runJob, const StoreFn& store) {
  return comm_.rank() == 0 ? runRoot(pending, runJob, store) : runWorker(runJob);
}

int JobFarm::runRoot(const std::vector<int>& pending, const RunFn& runJob, const StoreFn& store) {
  JobQueue queue(pending);
  std::mutex storeMutex;
  auto storeOne = [&](int index, const std::string& result) {
    std::lock_guard lock(storeMutex);
    store(index, result);
  };
  const int workers = comm_.size() - 1;
  // Answers every worker's requests until each has been told to stop.
  auto dispatch = [&] {
    int stopped = 0;
    while (stopped < workers) {
      std::optional<Communicator::Message> request = comm_.tryReceive(kRequestTag);
      if (!request) {
        std::this_thread::sleep_for(kPollInterval);
        continue;
      }
      int index = 0;
      std::string result;
      if (parseFinished(request->text, index, result)) storeOne(index, result);
      const int next = queue.take();
      comm_.send(request->source, kAssignTag, next < 0 ? std::string(kStop) : std::to_string(next));
      if (next < 0) ++stopped;
    }
  };
  int ran = 0;
  auto runOwn = [&] {
    for (int index = queue.take(); index >= 0; index = queue.take()) {
      const std::string result = runJob(index);
      storeOne(index, result);
      ++ran;
    }
  };
  if (workers == 0) {
    runOwn();
  } else if (comm_.allowsServiceThread()) {
    std::exception_ptr failure;
    std::thread dispatcher([&] {
      try {
        dispatch();
      } catch (...) {
        failure = std::current_exception();
      }
    });
    try {
      runOwn();
    } catch (...) {
      dispatcher.join();
      throw;
    }
    dispatcher.join();
    if (failure) std::rethrow_exception(failure);
  } else {
    dispatch();
  }
  return ran;
}

int JobFarm::runWorker(const RunFn& runJob) {
  int ran = 0;
  comm_.send(0, kRequestTag, "");
  for (;;) {
    const Communicator::Message assign = comm_.receive(0, kAssignTag);
    if (assign.text == kStop) break;
    const int index = std::stoi(assign.text);
    const std::string result = runJob(index);
    ++ran;
    comm_.send(0, kRequestTag, std::to_string(index) + "\n" + result);
  }
  return ran;
}

}  // namespace dabs::parallel
