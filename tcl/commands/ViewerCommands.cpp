// SPDX-License-Identifier: MIT
// recorder Viewer: the web post-processor page (tcl/domain/ViewerRecorder, tcl/viewer).
#include "tcl/commands/ViewerCommands.h"

#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "tcl/commands/TclResult.h"
#include "tcl/viewer/ViewerRecorder.h"

namespace dabs::tcl {

namespace {

constexpr const char* kUsage =
    "recorder Viewer -file page.html ?-dT dt? ?-nodes tags? ?-title text? ?-plots {{label node tag "
    "dof disp|vel|accel} {label ele tag response.. component} ..}? ?-beamSection {{rect width "
    "depth "
    "tags..} {circle diameter tags..} ..}? ?-bearingPad {{lx ly tags..} ..}? ?-block {{lx ly lz "
    "?-dz dz? "
    "nodes..} ..}? ?-gaps {{label nodeA nodeB} ..}?";

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

/// The word read by the ArgReader's rules as an int or a double; fails with the reader's context
/// otherwise.
template <class T>
T toNumber(const ArgReader& a, const std::string& word, const std::string& what) {
  Tcl_Obj* obj = Tcl_NewStringObj(word.c_str(), static_cast<int>(word.size()));
  Tcl_IncrRefCount(obj);
  std::optional<T> v;
  std::string expected = "expected a number";
  if constexpr (std::is_same_v<T, int>) {
    v = integerValue(obj);
    expected = integerExpectation(obj);
  } else {
    v = realValue(obj);
  }
  Tcl_DecrRefCount(obj);
  if (!v) a.fail(what + " " + expected + ", got \"" + word + "\"");
  return *v;
}
int toInteger(const ArgReader& a, const std::string& word, const std::string& what) {
  return toNumber<int>(a, word, what);
}
double toReal(const ArgReader& a, const std::string& word, const std::string& what) {
  return toNumber<double>(a, word, what);
}

domain::ViewerPlot readPlot(Runtime& rt, const ArgReader& a, const std::string& text) {
  const auto w = listWords(rt, a, text, "-plots item");
  const std::string where = "-plots item {" + text + "}";
  if (w.size() < 4)
    a.fail(
        where +
        ": expected {label node tag dof disp|vel|accel} or {label ele tag response.. component}");
  domain::ViewerPlot p;
  p.label = w[0];
  p.tag = toInteger(a, w[2], where + ": tag");
  if (w[1] == "node") {
    if (w.size() != 5) a.fail(where + ": expected {label node tag dof disp|vel|accel}");
    p.source = domain::ViewerPlot::Source::Node;
    p.dof = toInteger(a, w[3], where + ": dof") - 1;
    if (p.dof < 0) a.fail(where + ": dofs start at 1");
    using Q = domain::ViewerPlot::NodeQuantity;
    if (w[4] == "disp")
      p.quantity = Q::Disp;
    else if (w[4] == "vel")
      p.quantity = Q::Vel;
    else if (w[4] == "accel")
      p.quantity = Q::Accel;
    else
      a.fail(where + ": expected disp, vel or accel, got \"" + w[4] + "\"");
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

std::vector<int> toIntegers(const ArgReader& a, const std::vector<std::string>& w, std::size_t from,
                            const std::string& what) {
  std::vector<int> out;
  for (std::size_t i = from; i < w.size(); ++i) out.push_back(toInteger(a, w[i], what));
  if (out.empty()) a.fail(what + ": expected at least one tag");
  return out;
}

/// The first words of an option item read as positive sizes named `names`.
std::vector<double> positiveSizes(const ArgReader& a, const std::vector<std::string>& w,
                                  std::initializer_list<const char*> names,
                                  const std::string& option) {
  std::vector<double> out;
  for (const char* name : names) {
    const double v = toReal(a, w[out.size()], option + ": " + name);
    if (!(v > 0.0)) a.fail(option + ": sizes must be positive");
    out.push_back(v);
  }
  return out;
}

/// Items of a list option, each a Tcl list of at least `minWords` words.
std::vector<std::vector<std::string>> listItems(Runtime& rt, const ArgReader& a,
                                                const std::string& text, const std::string& option,
                                                std::size_t minWords, const std::string& form) {
  std::vector<std::vector<std::string>> items;
  for (const std::string& item : listWords(rt, a, text, option)) {
    auto w = listWords(rt, a, item, option + " item");
    if (w.size() < minWords) a.fail(option + " item {" + item + "}: expected " + form);
    items.push_back(std::move(w));
  }
  return items;
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
  if (auto text = a.optionalWordOption("-beamSection"))
    for (const auto& w : listItems(rt, a, *text, "-beamSection", 3,
                                   "{rect width depth tags..} or {circle diameter tags..}")) {
      domain::ViewerBeamSection s;
      const std::string where = "-beamSection item {" + w[0] + " ..}";
      if (w[0] == "rect") {
        if (w.size() < 4) a.fail(where + ": expected {rect width depth tags..}");
        s.width = toReal(a, w[1], where + ": width");
        s.depth = toReal(a, w[2], where + ": depth");
        s.elements = toIntegers(a, w, 3, where);
      } else if (w[0] == "circle") {
        s.shape = domain::ViewerBeamSection::Shape::Circle;
        s.width = toReal(a, w[1], where + ": diameter");
        s.elements = toIntegers(a, w, 2, where);
      } else {
        a.fail(where + ": expected rect or circle, got \"" + w[0] + "\"");
      }
      if (!(s.width > 0.0) ||
          (s.shape == domain::ViewerBeamSection::Shape::Rect && !(s.depth > 0.0)))
        a.fail(where + ": sizes must be positive");
      options.sections.push_back(std::move(s));
    }
  if (auto text = a.optionalWordOption("-bearingPad"))
    for (const auto& w : listItems(rt, a, *text, "-bearingPad", 3, "{lx ly tags..}")) {
      domain::ViewerPad p;
      const auto size = positiveSizes(a, w, {"lx", "ly"}, "-bearingPad");
      p.lx = size[0];
      p.ly = size[1];
      p.elements = toIntegers(a, w, 2, "-bearingPad");
      options.pads.push_back(std::move(p));
    }
  if (auto text = a.optionalWordOption("-block"))
    for (const auto& w : listItems(rt, a, *text, "-block", 4, "{lx ly lz ?-dz dz? nodes..}")) {
      domain::ViewerBlock b;
      const auto size = positiveSizes(a, w, {"lx", "ly", "lz"}, "-block");
      b.lx = size[0];
      b.ly = size[1];
      b.lz = size[2];
      std::size_t first = 3;
      if (w[3] == "-dz") {
        if (w.size() < 5) a.fail("-block: -dz needs a value");
        b.dz = toReal(a, w[4], "-block: dz");
        first = 5;
      }
      b.nodes = toIntegers(a, w, first, "-block");
      options.blocks.push_back(std::move(b));
    }
  if (auto text = a.optionalWordOption("-gaps"))
    for (const auto& w : listItems(rt, a, *text, "-gaps", 3, "{label nodeA nodeB}")) {
      if (w.size() != 3) a.fail("-gaps item {" + w[0] + " ..}: expected {label nodeA nodeB}");
      options.gaps.push_back(
          {w[0], toInteger(a, w[1], "-gaps: nodeA"), toInteger(a, w[2], "-gaps: nodeB")});
    }
  a.finish();
  auto recorder = std::make_unique<domain::ViewerRecorder>(std::move(options));
  setResult(rt, rt.domain.addRecorder(std::move(recorder)));
}

}  // namespace dabs::tcl
