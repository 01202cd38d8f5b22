// SPDX-License-Identifier: MIT
#include "tcl/commands/Runtime.h"

#include <cstdlib>
#include <string>

#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/analysis/driver/ThreadChoice.h"
#include "tcl/commands/CommandTable.h"

namespace dabs::tcl {

Runtime::Runtime(Tcl_Interp* interpreter)
    : interp(interpreter), analysis(std::make_unique<analysis::AnalysisBuilder>(domain)) {
  analysis->modelBuilt = [this] { heap.adviseGrowth(); };
  analysis->log = [this](const std::string& line) {
    Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR);
    if (err != nullptr) {
      Tcl_WriteChars(err, line.c_str(), static_cast<int>(line.size()));
      Tcl_WriteChars(err, "\n", 1);
    }
  };
  // DABS_THREADS=n (or auto) runs element state determination on n threads for scripts that do
  // not say `threads` themselves (an OpenSees script runs unchanged); another value is reported
  // and the analysis keeps the automatic choice (ThreadChoice).
  if (const char* env = std::getenv("DABS_THREADS")) {
    if (const auto n = analysis::ThreadChoice::parseCount(env))
      analysis->setThreads(*n);
    else
      analysis->log(std::string("DABS_THREADS=\"") + env +
                    "\" ignored: expected a whole number from 1 to " +
                    std::to_string(analysis::ThreadChoice::kMaxThreads) +
                    " or auto; the count is chosen by measurement");
  }
}

Runtime::~Runtime() {
  // Recorders flush in the domain's destructor; the analysis refers to the domain, so it goes
  // first.
  analysis.reset();
}

void Runtime::requireModel(const char* command) const {
  if (!builder.defined())
    throw InputError(command, "needs a model first: give `model basic -ndm n ?-ndf m?`");
}

}  // namespace dabs::tcl
