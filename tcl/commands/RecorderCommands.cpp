// SPDX-License-Identifier: MIT
// recorder Node|EnvelopeNode|Element|EnvelopeElement|Drift, and record.
#include <string>

#include "materials/InputError.h"
#include "materials/ResponseArgs.h"
#include "tcl/commands/CommandTable.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/SeriesParser.h"
#include "tcl/commands/TclResult.h"
#include "tcl/commands/ViewerCommands.h"
#include "tcl/domain/DriftRecorder.h"
#include "tcl/domain/ElementRecorder.h"
#include "tcl/domain/NodeRecorder.h"

namespace dabs::tcl {

namespace {

domain::RecorderOutput readOutput(ArgReader& a, bool envelope) {
  domain::RecorderOutput out;
  const auto file = a.optionalWordOption("-file");
  if (!file) a.fail("-file fileName is required");
  out.file = *file;
  // -load is OpenSees' synonym of -time (the pseudo time of a static analysis is its load factor).
  const bool time = a.flag("-time");
  const bool load = a.flag("-load");
  out.time = time || load;
  // -closeOnWrite: OpenSees closes the file after each row so other programs see it; every row
  // already reaches the operating system when its step is committed, so nothing else is needed.
  (void)a.flag("-closeOnWrite");
  out.deltaT = a.option("-dT", 0.0);
  out.precision = a.option("-precision", 6);
  out.envelope = envelope;
  if (out.deltaT < 0.0) a.fail("-dT must not be negative");
  if (out.precision < 1 || out.precision > 17) a.fail("-precision must be 1 to 17");
  return out;
}

// Tags of `-node`/`-ele` plus the existing tags within `-nodeRange`/`-eleRange` (as OpenSees'
// recorders skip the missing ones); the range walks the model's ordered map, so `1 2147483647`
// costs no more than the model's size.
template <class Map>
std::vector<int> readRange(ArgReader& a, const char* listKey, const char* rangeKey,
                           const Map& existing) {
  std::vector<int> tags;
  if (auto list = a.optionIntegerList(listKey)) tags = *list;
  if (auto range = a.optionTagRange(rangeKey)) {
    const std::size_t before = tags.size();
    for (auto it = existing.lower_bound(range->first);
         it != existing.end() && it->first <= range->second; ++it)
      tags.push_back(it->first);
    if (tags.size() == before)
      a.fail(std::string(rangeKey) + " " + std::to_string(range->first) + " " +
             std::to_string(range->second) + " holds no existing tag");
  }
  return tags;
}

void nodeRecorder(Runtime& rt, ArgReader& a, bool envelope) {
  domain::RecorderOutput out = readOutput(a, envelope);
  std::vector<int> nodes = readRange(a, "-node", "-nodeRange", rt.domain.nodes());
  if (nodes.empty()) a.fail("needs -node tags or -nodeRange a b");
  const auto dofs = a.optionIntegerList("-dof");
  if (!dofs) a.fail("-dof dofs is required");
  std::vector<std::shared_ptr<const domain::TimeSeries>> series;
  if (auto ts = a.optionIntegerList("-timeSeries")) {
    for (int t : *ts) series.push_back(t == 0 || t == -1 ? nullptr : rt.builder.series(t));
    // OpenSees ignores the option, with a warning, unless there is one series per dof.
    if (series.size() != dofs->size()) {
      series.clear();
      if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr) {
        const std::string text = "recorder Node: " + std::to_string(ts->size()) +
                                 " time series for " + std::to_string(dofs->size()) +
                                 " dofs; -timeSeries is ignored\n";
        Tcl_WriteChars(err, text.c_str(), static_cast<int>(text.size()));
      }
    }
  }
  const std::string response = a.word("response");
  using R = domain::NodeRecorder::Response;
  R kind{};
  int mode = 0;
  if (response == "disp")
    kind = R::Disp;
  else if (response == "vel")
    kind = R::Vel;
  else if (response == "accel")
    kind = R::Accel;
  else if (response == "incrDisp")
    kind = R::IncrDisp;
  else if (response == "reaction")
    kind = R::Reaction;
  else if (response.rfind("eigen", 0) == 0) {
    kind = R::Eigen;
    const std::string rest = response.substr(5);
    if (!rest.empty())
      mode = responseInteger(rest).value_or(0);
    else
      mode = a.integer("mode");
    if (mode < 1) a.fail("eigen needs a mode number from 1");
  } else {
    a.fail("response must be disp, vel, accel, incrDisp, reaction or eigen i, got \"" + response +
           "\"");
  }
  a.finish();
  std::vector<int> zeroBased;
  for (int d : *dofs) {
    // Checked before the shift: d - 1 of the smallest int overflows.
    if (d < 1) a.failArgument("-dof", "expected dofs from 1");
    zeroBased.push_back(d - 1);
  }
  auto recorder = std::make_unique<domain::NodeRecorder>(out, nodes, zeroBased, kind, mode, series);
  setResult(rt, rt.domain.addRecorder(std::move(recorder)));
}

void elementRecorder(Runtime& rt, ArgReader& a, bool envelope) {
  domain::RecorderOutput out = readOutput(a, envelope);
  std::vector<int> eles = readRange(a, "-ele", "-eleRange", rt.domain.elements());
  if (eles.empty()) a.fail("needs -ele tags or -eleRange a b");
  std::vector<std::string> response;
  while (a.hasMore()) response.push_back(a.word("response"));
  auto recorder = std::make_unique<domain::ElementRecorder>(out, eles, response);
  setResult(rt, rt.domain.addRecorder(std::move(recorder)));
}

void driftRecorder(Runtime& rt, ArgReader& a) {
  domain::RecorderOutput out = readOutput(a, false);
  const auto iNodes = a.optionIntegerList("-iNode");
  const auto jNodes = a.optionIntegerList("-jNode");
  const auto dofs = a.optionIntegerList("-dof");
  const auto perp = a.optionIntegerList("-perpDirn");
  a.finish();
  if (!iNodes || !jNodes || !dofs || !perp) a.fail("needs -iNode, -jNode, -dof and -perpDirn");
  std::vector<int> d0, p0;
  for (int d : *dofs) d0.push_back(d - 1);
  for (int p : *perp) p0.push_back(p - 1);
  auto recorder = std::make_unique<domain::DriftRecorder>(out, *iNodes, *jNodes, d0, p0);
  setResult(rt, rt.domain.addRecorder(std::move(recorder)));
}

// OpenSees' window recorders draw on screen; dabs opens no windows (its page is `recorder
// Viewer`), so scripts that also plot run unchanged and this one is noted and skipped.
void windowRecorder(Runtime& /*rt*/, ArgReader& a) {
  while (a.hasMore()) (void)a.word("option");
  if (Tcl_Channel err = Tcl_GetStdChannel(TCL_STDERR); err != nullptr) {
    const std::string text =
        a.context() + ": dabs opens no windows; ignored (see recorder Viewer)\n";
    Tcl_WriteChars(err, text.c_str(), static_cast<int>(text.size()));
  }
}

void nodeRecorderType(Runtime& rt, ArgReader& a) { nodeRecorder(rt, a, false); }
void envelopeNodeRecorderType(Runtime& rt, ArgReader& a) { nodeRecorder(rt, a, true); }
void elementRecorderType(Runtime& rt, ArgReader& a) { elementRecorder(rt, a, false); }
void envelopeElementRecorderType(Runtime& rt, ArgReader& a) { elementRecorder(rt, a, true); }

using RecorderParser = void (*)(Runtime& rt, ArgReader& a);

constexpr TypeEntry<RecorderParser> kRecorders[] = {
    {"Node", "", nodeRecorderType},       {"EnvelopeNode", "", envelopeNodeRecorderType},
    {"Element", "", elementRecorderType}, {"EnvelopeElement", "", envelopeElementRecorderType},
    {"Drift", "", driftRecorder},         {"Viewer", "", viewerRecorderCommand},
    {"plot", "", windowRecorder},         {"display", "", windowRecorder},
};

void recorderCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("recorder");
  const std::string type = a.word("type");
  const auto* entry = findType<TypeEntry<RecorderParser>>({kRecorders}, type);
  if (entry == nullptr)
    a.failArgument("type", "expected one of " + typeNames<TypeEntry<RecorderParser>>({kRecorders}));
  a.setContext("recorder " + type);
  entry->parse(rt, a);
}

void recordCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  rt.domain.record();
  if (auto error = rt.domain.takeRecorderError()) throw InputError("", *error);
  rt.domain.flushRecorders();
}

constexpr CommandEntry kCommands[] = {
    {"recorder",
     "recorder Node|EnvelopeNode -file f ?-time|-load? ?-closeOnWrite? ?-dT dt? ?-precision p? "
     "?-timeSeries tags? -node tags|-nodeRange a b -dof dofs "
     "disp|vel|accel|incrDisp|reaction|eigen i; recorder Element|EnvelopeElement -file f ?-time? "
     "-ele tags|-eleRange a b "
     "response; recorder Drift -file f -iNode .. -jNode .. -dof .. -perpDirn ..; "
     "recorder Viewer -file page.html ?-dT dt? ?-nodes tags? ?-plots {..}? ?-title text?; recorder "
     "plot|display ... (ignored)",
     recorderCmd},
    {"record", "record", recordCmd},
};

}  // namespace

std::span<const CommandEntry> recorderCommands() { return kCommands; }

}  // namespace dabs::tcl
