// SPDX-License-Identifier: MIT
// recorder Viewer: the web post-processor page (tcl/domain/ViewerRecorder, tcl/viewer).
#include "tcl/commands/ViewerCommands.h"

#include <memory>
#include <string>

#include "tcl/commands/TclResult.h"
#include "tcl/domain/ViewerRecorder.h"

namespace dabs::tcl {

namespace {

constexpr const char* kUsage =
    "recorder Viewer -file page.html ?-dT dt? ?-nodes tags? ?-title text? ?-plots {{label node tag "
    "dof disp|vel|accel} {label ele tag response.. component} ..}?";

/// Words of a Tcl list; fails with the reader's context when `text` is not a list.
std::vector<std::string> listWords(Runtime& rt, const ArgReader& a, const std::string& text,
                                   const std::string& what) {
  Tcl_Obj* obj = Tcl_NewStringObj(text.c_str(), static_cast<int>(text.size()));
  Tcl_IncrRefCount(obj);
  int n = 0;
  Tcl_Obj** items = nullptr;
  const int rc = Tcl_ListObjGetElements(rt.interp, obj, &n, &items);
  std::vector<std::string> words;
  if (rc == TCL_OK)
    for (int i = 0; i < n; ++i) words.emplace_back(Tcl_GetString(items[i]));
  Tcl_DecrRefCount(obj);
  if (rc != TCL_OK) a.fail(what + " is not a Tcl list: \"" + text + "\"");
  return words;
}

int toInteger(const ArgReader& a, const std::string& word, const std::string& what) {
  std::size_t used = 0;
  int v = 0;
  try {
    v = std::stoi(word, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != word.size()) a.fail(what + " expected an integer, got \"" + word + "\"");
  return v;
}

domain::ViewerPlot readPlot(Runtime& rt, const ArgReader& a, const std::string& text) {
  const auto w = listWords(rt, a, text, "-plots item");
  const std::string where = "-plots item {" + text + "}";
  if (w.size() < 4) a.fail(where + ": expected {label node tag dof disp|vel|accel} or {label ele tag response.. component}");
  domain::ViewerPlot p;
  p.label = w[0];
  p.tag = toInteger(a, w[2], where + ": tag");
  if (w[1] == "node") {
    if (w.size() != 5) a.fail(where + ": expected {label node tag dof disp|vel|accel}");
    p.source = domain::ViewerPlot::Source::Node;
    p.dof = toInteger(a, w[3], where + ": dof") - 1;
    if (p.dof < 0) a.fail(where + ": dofs start at 1");
    using Q = domain::ViewerPlot::NodeQuantity;
    if (w[4] == "disp") p.quantity = Q::Disp;
    else if (w[4] == "vel") p.quantity = Q::Vel;
    else if (w[4] == "accel") p.quantity = Q::Accel;
    else a.fail(where + ": expected disp, vel or accel, got \"" + w[4] + "\"");
  } else if (w[1] == "ele" || w[1] == "element") {
    p.source = domain::ViewerPlot::Source::Element;
    p.response.assign(w.begin() + 3, w.end() - 1);
    p.component = toInteger(a, w.back(), where + ": component") - 1;
    if (p.component < 0) a.fail(where + ": components start at 1");
  } else {
    a.fail(where + ": expected node or ele after the label, got \"" + w[1] + "\"");
  }
  return p;
}

}  // namespace

void viewerRecorderCommand(Runtime& rt, ArgReader& a) {
  a.setUsage(kUsage);
  domain::ViewerOptions options;
  const auto file = a.optionalWordOption("-file");
  if (!file) a.fail("-file page.html is required");
  options.file = *file;
  options.deltaT = a.option("-dT", 0.0);
  if (options.deltaT < 0.0) a.fail("-dT must not be negative");
  if (auto nodes = a.optionIntegerList("-nodes")) options.nodes = *nodes;
  options.title = a.option("-title", std::string());
  if (auto plots = a.optionalWordOption("-plots"))
    for (const std::string& item : listWords(rt, a, *plots, "-plots"))
      options.plots.push_back(readPlot(rt, a, item));
  a.finish();
  auto recorder = std::make_unique<domain::ViewerRecorder>(std::move(options));
  setResult(rt, rt.domain.addRecorder(std::move(recorder)));
}

}  // namespace dabs::tcl
