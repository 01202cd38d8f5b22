// SPDX-License-Identifier: MIT
#include "tcl/parallel/EnsembleCommand.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/parallel/JobFarm.h"
#include "tcl/parallel/ParallelState.h"
#include "tcl/parallel/ResultStore.h"

namespace dabs::parallel {

namespace {

using tcl::ArgReader;
using tcl::Runtime;

/// One job of the list: its id and parameters in the order given.
struct Job {
  std::string id;
  Tcl_Obj* dict = nullptr;  // the job as given, handed to the command
  Record params;
};

// Columns every job's record starts with, in this order.
constexpr const char* kFixedColumns[] = {"job", "status", "code", "error", "rank", "seconds"};

bool isFixedColumn(const std::string& key) {
  return std::find_if(std::begin(kFixedColumns), std::end(kFixedColumns),
                      [&](const char* c) { return key == c; }) != std::end(kFixedColumns);
}

std::string text(Tcl_Obj* obj) {
  int size = 0;
  const char* s = Tcl_GetStringFromObj(obj, &size);
  return std::string(s, static_cast<std::size_t>(size));
}

// Reads a dict-shaped list into (key, value) pairs; nullopt when its length is odd or it is no
// list.
std::optional<Record> pairs(Tcl_Obj* obj) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(nullptr, obj, &n, &items) != TCL_OK || n % 2 != 0) return std::nullopt;
  Record out;
  for (int i = 0; i < n; i += 2) out.emplace_back(text(items[i]), text(items[i + 1]));
  return out;
}

bool validId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '.' || c == '_' || c == '-';
  }) && id[0] != '.';
}

std::vector<Job> readJobs(ArgReader& a, Tcl_Obj* list) {
  int n = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(nullptr, list, &n, &items) != TCL_OK)
    a.fail(1, "jobList", "expected a list of jobs");
  const int width = std::max(4, static_cast<int>(std::to_string(n).size()));
  std::vector<Job> jobs;
  std::set<std::string> ids;
  for (int i = 0; i < n; ++i) {
    std::optional<Record> params = pairs(items[i]);
    if (!params)
      a.fail(1, "jobList",
             "job " + std::to_string(i + 1) +
                 " expected a dict of parameters (key value ...), got \"" + text(items[i]) + "\"");
    Job job;
    const std::string number = std::to_string(i + 1);
    job.id = "job" +
             std::string(static_cast<std::size_t>(width) -
                             std::min(number.size(), static_cast<std::size_t>(width)),
                         '0') +
             number;
    for (const auto& [key, value] : *params) {
      if (key == "id") job.id = value;
      if (isFixedColumn(key))
        a.fail(1, "jobList",
               "job " + std::to_string(i + 1) + " has a parameter named \"" + key +
                   "\", a column the ensemble writes itself");
    }
    if (!validId(job.id))
      a.fail(1, "jobList",
             "job " + std::to_string(i + 1) + " id \"" + job.id +
                 "\" expected letters, digits, '.', '_' and '-' (it names a file)");
    if (!ids.insert(job.id).second) a.fail(1, "jobList", "job id \"" + job.id + "\" appears twice");
    job.dict = items[i];
    job.params = std::move(*params);
    jobs.push_back(std::move(job));
  }
  return jobs;
}

std::optional<std::string> valueOf(const Record& record, const std::string& key) {
  for (const auto& [k, v] : record)
    if (k == key) return v;
  return std::nullopt;
}

// A stored result that a rerun keeps: the job finished (ok or failed analysis) with these
// parameters.
bool isDone(const std::optional<Record>& record, const Job& job) {
  if (!record || valueOf(*record, "job") != job.id) return false;
  const std::optional<std::string> status = valueOf(*record, "status");
  if (status != "ok" && status != "failed") return false;
  return std::all_of(job.params.begin(), job.params.end(),
                     [&](const auto& p) { return valueOf(*record, p.first) == p.second; });
}

// Runs one job on this process: wipe, `{*}command job`, and its record as CSV.
std::string runJob(Runtime& rt, ParallelState& state, Tcl_Obj* command, const Job& job, int rank) {
  const auto start = std::chrono::steady_clock::now();
  state.inJob = true;
  int rc = Tcl_EvalEx(rt.interp, "wipe", -1, TCL_EVAL_GLOBAL);
  if (rc == TCL_OK) {
    Tcl_Obj* call = Tcl_DuplicateObj(command);
    Tcl_IncrRefCount(call);
    rc = Tcl_ListObjAppendElement(rt.interp, call, job.dict);
    if (rc == TCL_OK) rc = Tcl_EvalObjEx(rt.interp, call, TCL_EVAL_GLOBAL);
    Tcl_DecrRefCount(call);
  }
  state.inJob = false;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Tcl_Obj* result = Tcl_GetObjResult(rt.interp);
  Tcl_IncrRefCount(result);
  Tcl_ResetResult(rt.interp);

  std::string status = "ok";
  std::string code;
  std::string error;
  Record results;
  if (rc != TCL_OK) {
    status = "error";
    error = text(result);
  } else if (std::optional<Record> values = pairs(result); !values) {
    status = "error";
    error = "the command returned \"" + text(result) + "\", expected a dict of results";
  } else {
    for (auto& [key, value] : *values) {
      if (key == "code") {
        int c = 0;
        Tcl_Obj* v = Tcl_NewStringObj(value.c_str(), -1);
        Tcl_IncrRefCount(v);
        const bool isInt = Tcl_GetIntFromObj(nullptr, v, &c) == TCL_OK;
        Tcl_DecrRefCount(v);
        if (!isInt) {
          status = "error";
          error = "result code \"" + value + "\" expected an integer (0 for a completed analysis)";
        } else if (c != 0 && status == "ok") {
          status = "failed";
        }
        code = value;
      } else if (isFixedColumn(key) || valueOf(job.params, key)) {
        status = "error";
        error = "result key \"" + key + "\" repeats a job parameter or an ensemble column";
      } else {
        results.emplace_back(key, value);
      }
    }
  }
  Tcl_DecrRefCount(result);
  char secondsText[32];
  std::snprintf(secondsText, sizeof secondsText, "%.3f", seconds);
  Record record = {{"job", job.id},
                   {"status", status},
                   {"code", code},
                   {"error", error},
                   {"rank", std::to_string(rank)},
                   {"seconds", secondsText}};
  record.insert(record.end(), job.params.begin(), job.params.end());
  record.insert(record.end(), results.begin(), results.end());
  return ResultStore::toCsv(record);
}

}  // namespace

// h:mm:ss, or m:ss under an hour.
std::string clockText(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

/// The progress lines of an ensemble (process 0, standard error): after each finished job, the
/// count done of those to run, the failures and errors so far, the time elapsed and an estimate
/// of the time left (elapsed per job done times the jobs left), and the job's id, status and
/// time. Called one job at a time (JobFarm::StoreFn), from either of process 0's threads, so it
/// writes with stdio alone (not through the interpreter).
class Progress {
 public:
  Progress(int total, bool on) : total_(total), on_(on) {}
  void finished(const std::string& id, const Record& record) {
    ++done_;
    const std::optional<std::string> status = valueOf(record, "status");
    failed_ += status == "failed";
    errors_ += status == "error";
    if (!on_) return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double left = elapsed / done_ * (total_ - done_);
    const std::string seconds = valueOf(record, "seconds").value_or("?");
    std::fprintf(stderr,
                 "ensemble: %d/%d done, %d failed, %d errors, %s elapsed, about %s left "
                 "(%s %s in %s s)\n",
                 done_, total_, failed_, errors_, clockText(elapsed).c_str(),
                 clockText(left).c_str(), id.c_str(), status.value_or("?").c_str(),
                 seconds.c_str());
    std::fflush(stderr);
  }

 private:
  int total_;
  bool on_;
  int done_ = 0, failed_ = 0, errors_ = 0;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

void ensembleCmd(Runtime& rt, ArgReader& a) {
  const std::string sub = a.word("subcommand");
  if (sub != "run") a.fail(a.lastPosition(), "subcommand", "expected run, got \"" + sub + "\"");
  a.setContext("ensemble run");
  Tcl_Obj* jobsGiven = a.object("jobList");
  Tcl_Obj* command = a.object("command");
  const std::string outDir = a.option("-out", std::string("ensemble-out"));
  const bool progressAsked = a.flag("-progress");
  a.finish();
  ParallelState& state = ParallelState::of(rt.interp);
  if (state.inJob) a.fail("an ensemble job cannot run an ensemble");
  // It writes files, which a safe interpreter may not (Tcl hides `open` and `file` there).
  if (Tcl_IsSafe(rt.interp) != 0) a.fail("not available in a safe interpreter (it writes files)");
  Communicator& comm = *state.farm;
  const int rank = comm.rank();

  // Process 0's job list is the one run (every process runs the same script, but a list built from
  // a clock or a random draw could differ); every process checks it the same way, so all agree.
  Tcl_Obj* jobsList = Tcl_NewStringObj(comm.broadcast(text(jobsGiven), 0).c_str(), -1);
  Tcl_IncrRefCount(jobsList);
  struct Release {
    Tcl_Obj* obj;
    ~Release() { Tcl_DecrRefCount(obj); }
  } release{jobsList};
  const std::vector<Job> jobs = readJobs(a, jobsList);

  // Process 0 reads what earlier runs left and decides what is pending; a failure there (an output
  // folder that cannot be made) is reported on every process instead of leaving them waiting.
  std::optional<ResultStore> store;
  std::vector<std::optional<Record>> records(jobs.size());
  std::vector<int> pending;
  std::string setupError;
  if (rank == 0) {
    try {
      store.emplace(outDir);
      for (std::size_t i = 0; i < jobs.size(); ++i) {
        records[i] = store->read(jobs[i].id);
        if (!isDone(records[i], jobs[i])) {
          records[i].reset();
          pending.push_back(static_cast<int>(i));
        }
      }
    } catch (const std::exception& e) {
      setupError = e.what();
    }
  }
  setupError = comm.broadcast(setupError, 0);
  if (!setupError.empty()) a.fail("-out " + outDir + ": " + setupError);

  // A result that cannot be written (a full disk) is reported at the end; the other jobs go on.
  std::string storeError;
  // Progress on process 0's standard error, a line per finished job, when it is a terminal or
  // when asked (-progress): never in the results.
  Progress progress(static_cast<int>(pending.size()),
                    rank == 0 && (progressAsked || isatty(STDERR_FILENO) != 0));
  // The farm's processes take the cores: under more than one, an automatic thread count would try
  // two threads against a busy core in every job's trials, so its jobs run on one thread
  // (a count the script asked for stands) and the choice comes back afterwards.
  struct OneThreadPerProcess {
    analysis::AnalysisBuilder& analysis;
    bool set;
    ~OneThreadPerProcess() {
      if (set) analysis.setThreads(0);
    }
  } oneThread{*rt.analysis, comm.size() > 1 && rt.analysis->threadsAsked() == 0};
  if (oneThread.set) rt.analysis->setThreads(1);
  JobFarm farm(comm);
  farm.run(
      pending,
      [&](int index) {
        return runJob(rt, state, command, jobs[static_cast<std::size_t>(index)], rank);
      },
      [&](int index, const std::string& csv) {
        const auto i = static_cast<std::size_t>(index);
        records[i] = ResultStore::fromCsv(csv);
        try {
          store->write(jobs[i].id, csv);
        } catch (const std::exception& e) {
          if (storeError.empty()) storeError = e.what();
        }
        progress.finished(jobs[i].id, *records[i]);
      });

  // Process 0 merges and tells every process the outcome: "ok <summary>" or "error <message>".
  std::string outcome;
  if (rank == 0) {
    int ok = 0, failed = 0, errors = 0;
    std::vector<Record> rows;
    for (const auto& record : records) {
      if (!record) continue;
      const std::optional<std::string> status = valueOf(*record, "status");
      ok += status == "ok";
      failed += status == "failed";
      errors += status == "error";
      rows.push_back(*record);
    }
    const std::filesystem::path merged = std::filesystem::path(outDir) / "results.csv";
    try {
      store->writeMerged(rows, merged);
    } catch (const std::exception& e) {
      if (storeError.empty()) storeError = e.what();
    }
    Tcl_Obj* summary = Tcl_NewListObj(0, nullptr);
    Tcl_IncrRefCount(summary);
    auto add = [&](const char* key, const std::string& value) {
      Tcl_ListObjAppendElement(nullptr, summary, Tcl_NewStringObj(key, -1));
      Tcl_ListObjAppendElement(nullptr, summary, Tcl_NewStringObj(value.c_str(), -1));
    };
    add("jobs", std::to_string(jobs.size()));
    add("ran", std::to_string(pending.size()));
    add("skipped", std::to_string(jobs.size() - pending.size()));
    add("ok", std::to_string(ok));
    add("failed", std::to_string(failed));
    add("error", std::to_string(errors));
    add("file", merged.string());
    outcome = storeError.empty() ? "ok " + text(summary) : "error " + storeError;
    Tcl_DecrRefCount(summary);
  }
  outcome = comm.broadcast(outcome, 0);
  if (outcome.rfind("error ", 0) == 0) a.fail("-out " + outDir + ": " + outcome.substr(6));
  Tcl_SetObjResult(rt.interp, Tcl_NewStringObj(outcome.c_str() + 3, -1));
}

}  // namespace dabs::parallel
