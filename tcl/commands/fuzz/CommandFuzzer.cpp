// SPDX-License-Identifier: MIT
// libFuzzer harness over the Tcl command layer: each input is a Tcl script run command by command
// (an error does not stop the commands after it, as in the shell) in a fresh interpreter holding
// the dabs commands. Built only with clang and -DDABS_BUILD_FUZZERS=ON; seeds, dictionary and the
// way to run it are in README.md beside this file.
//
// Mutations: a quarter of them are libFuzzer's own, on bytes; the rest change one argument slot
// of one command at a time (StructureMutator.h), guided by the grammar commands.grammar, which
// make-grammar.py derives from the command tables. DABS_FUZZ_BYTES_ONLY=1 in the environment
// leaves only the byte mutations (the harness as it was, for comparisons); DABS_FUZZ_GRAMMAR
// names another grammar file.
//
// The interpreter is made safe (no exec, open, file, source, exit, Tcl's load) and the dabs
// commands that name files write only into the fuzzer's own temporary folder; loops are bounded by
// Tcl's command limit and a time limit, and `analyze` by step limits, so an input cannot hang the
// fuzzer on work it asked for rather than on a fault.
#include <tcl.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "tcl/commands/CommandTable.h"
#include "tcl/commands/fuzz/StructureMutator.h"
#include "tcl/parallel/ParallelCommands.h"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t maxSize);

namespace {

// Commands a fuzz input may run (Tcl's command limit counts every command, procedures included).
constexpr int kCommandLimit = 5000;
// Seconds a fuzz input may run, below libFuzzer's -timeout (10 s in .ci/run): the command limit
// does not count the instructions of a compiled loop (`for {...} {$i <= "n"} {incr i} {lappend l
// $i}` never ends and was counted as no command at all; a mutated seed did that), the time limit
// stops it.
constexpr long kSecondsLimit = 5;

// Wrappers evaluated before each input. Files: every -file, -filePath and -fileTime value and the
// file name of print become names in the temporary folder (a record file is written there once).
// analyze: at most 50 steps per call and 500 per input.
constexpr const char* kPrelude = R"TCL(
namespace eval ::fuzz {}
foreach cmd {recorder timeSeries print printModel analyze} { rename ::$cmd ::fuzz::$cmd }
proc ::fuzz::files {args} {
  set out {}
  set next 0
  foreach a $args {
    if {$next} { lappend out [expr {$next == 2 ? "record.txt" : "out.txt"}]; set next 0; continue }
    if {$a in {-file}} { set next 1 } elseif {$a in {-filePath -fileTime}} { set next 2 }
    lappend out $a
  }
  return $out
}
proc recorder {args} { ::fuzz::recorder {*}[::fuzz::files {*}$args] }
proc timeSeries {args} { ::fuzz::timeSeries {*}[::fuzz::files {*}$args] }
proc print {args} { ::fuzz::print {*}[lsearch -all -inline -not -glob $args {*[./]*}] }
proc printModel {args} { ::fuzz::printModel {*}[lsearch -all -inline -not -glob $args {*[./]*}] }
set ::fuzz::steps 0
proc analyze {n args} {
  if {[string is integer -strict $n]} {
    if {$n > 50} { set n 50 }
    if {[incr ::fuzz::steps [expr {max($n, 1)}]] > 500} { return -code error "fuzz: 500 steps spent" }
  }
  ::fuzz::analyze $n {*}$args
}
)TCL";

// The fuzzer's own temporary folder, the working directory while an input runs: every file an
// input names by a relative path (recorders, print -file, ensemble -out) lands there, and
// record.txt is found there.
std::string gFolder;
// The working directory the fuzzer started in, restored after each input: libFuzzer reads and
// writes its corpus folders relative to it.
std::string gStart;

// The structure-aware mutator, or null when only byte mutations are wanted.
std::unique_ptr<dabs::tcl::fuzz::StructureMutator> gMutator;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
  Tcl_FindExecutable((*argv)[0]);
  char dir[] = "/tmp/dabs-fuzz-XXXXXX";
  if (mkdtemp(dir) == nullptr) std::abort();
  gFolder = dir;
  // Gone with the fuzzer when it ends by exit (its time or run limit); a crash leaves it with the
  // files the input wrote.
  std::atexit([] {
    std::error_code ignored;
    std::filesystem::remove_all(gFolder, ignored);
  });
  char* cwd = getcwd(nullptr, 0);
  if (cwd == nullptr) std::abort();
  gStart = cwd;
  std::free(cwd);
  // A crash is written while the input runs in gFolder: libFuzzer's artifact paths are made
  // absolute (it reads its flags after this function), so crash files land where they are asked.
  static std::vector<std::string> args;
  static std::vector<char*> pointers;
  bool prefixed = false;
  for (int i = 0; i < *argc; ++i) {
    std::string a = (*argv)[i];
    for (const char* flag : {"-artifact_prefix=", "-exact_artifact_path="}) {
      const std::size_t n = std::strlen(flag);
      if (a.compare(0, n, flag) != 0) continue;
      if (a.size() > n && a[n] != '/') a.insert(n, gStart + "/");
      prefixed = prefixed || flag[1] == 'a';
    }
    args.push_back(a);
  }
  if (!prefixed) args.push_back("-artifact_prefix=" + gStart + "/");
  for (std::string& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  *argc = static_cast<int>(args.size());
  *argv = pointers.data();
  FILE* record = std::fopen((gFolder + "/record.txt").c_str(), "w");
  if (record == nullptr) std::abort();
  std::fputs("0.0 0.1 0.3 -0.2 0.05 0.0\n", record);
  std::fclose(record);
  const char* bytesOnly = std::getenv("DABS_FUZZ_BYTES_ONLY");
  if (bytesOnly == nullptr || std::strcmp(bytesOnly, "1") != 0) {
    const char* path = std::getenv("DABS_FUZZ_GRAMMAR");
    std::ifstream in(path != nullptr ? path : DABS_FUZZ_GRAMMAR);
    std::stringstream text;
    text << in.rdbuf();
    auto grammar = dabs::tcl::fuzz::Grammar::parse(text.str());
    // Without its grammar the mutator would still run, on the seeds' words only: say so.
    std::fprintf(stderr, "dabs fuzz: %zu command templates from %s\n", grammar.templates.size(),
                 path != nullptr ? path : DABS_FUZZ_GRAMMAR);
    gMutator = std::make_unique<dabs::tcl::fuzz::StructureMutator>(std::move(grammar));
  }
  return 0;
}

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size,
                                               std::size_t maxSize, unsigned seed) {
  if (gMutator == nullptr || seed % 4 == 0) return LLVMFuzzerMutate(data, size, maxSize);
  const std::string out =
      gMutator->mutate(std::string_view(reinterpret_cast<const char*>(data), size), seed);
  // A script grown past the size limit gets a byte mutation instead.
  if (out.size() > maxSize || out.empty()) return LLVMFuzzerMutate(data, size, maxSize);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (chdir(gFolder.c_str()) != 0) std::abort();
  Tcl_Interp* interp = Tcl_CreateInterp();
  // The program's command set: the library's and the parallel commands (getPID, send, ensemble...).
  const std::span<const dabs::tcl::CommandEntry> parallel[] = {dabs::parallel::parallelCommands()};
  if (Tcl_MakeSafe(interp) != TCL_OK || dabs::tcl::registerCommands(interp, parallel) != TCL_OK ||
      Tcl_Eval(interp, ("namespace eval ::fuzz {variable dir " + gFolder + "}").c_str()) !=
          TCL_OK ||
      Tcl_Eval(interp, kPrelude) != TCL_OK)
    std::abort();
  Tcl_LimitSetCommands(interp, kCommandLimit);
  Tcl_LimitTypeSet(interp, TCL_LIMIT_COMMANDS);
  Tcl_Time deadline;
  Tcl_GetTime(&deadline);
  deadline.sec += kSecondsLimit;
  Tcl_LimitSetTime(interp, &deadline);
  Tcl_LimitTypeSet(interp, TCL_LIMIT_TIME);
  const std::string script(reinterpret_cast<const char*>(data), size);
  // One complete command at a time, as the shell reads them.
  std::string command;
  std::size_t start = 0;
  while (start < script.size() && !Tcl_LimitExceeded(interp)) {
    std::size_t end = script.find('\n', start);
    end = end == std::string::npos ? script.size() : end + 1;
    command.append(script, start, end - start);
    start = end;
    if (Tcl_CommandComplete(command.c_str()) || start >= script.size()) {
      (void)Tcl_Eval(interp, command.c_str());
      command.clear();
    }
  }
  Tcl_DeleteInterp(interp);
  if (chdir(gStart.c_str()) != 0) std::abort();
  return 0;
}
