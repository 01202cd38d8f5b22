// SPDX-License-Identifier: MIT
#include "tcl/commands/SeriesParser.h"

#include "tcl/commands/CommandTable.h"
#include "tcl/commands/Registry.h"

#include <cmath>
#include <string>

#include "materials/InputError.h"
#include "tcl/domain/ConstantSeries.h"
#include "tcl/domain/LinearSeries.h"
#include "tcl/domain/NearFaultPulseSeries.h"
#include "tcl/domain/PathSeries.h"
#include "tcl/domain/RectangularSeries.h"
#include "tcl/domain/TrigSeries.h"

namespace dabs::tcl {

std::vector<double> parseNumberList(ArgReader& a, const std::string& text, std::string_view key) {
  int count = 0;
  const char** items = nullptr;
  if (Tcl_SplitList(nullptr, text.c_str(), &count, &items) != TCL_OK)
    a.fail(std::string(key) + " expects a Tcl list of numbers");
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(count));
  std::string bad;
  for (int i = 0; i < count && bad.empty(); ++i) {
    char* end = nullptr;
    const double v = std::strtod(items[i], &end);
    if (end == items[i] || *end != '\0' || !std::isfinite(v))
      bad = items[i];
    else
      out.push_back(v);
  }
  Tcl_Free(reinterpret_cast<char*>(items));
  if (!bad.empty()) a.fail(std::string(key) + " expects numbers, got \"" + bad + "\"");
  return out;
}

namespace {

std::shared_ptr<const domain::TimeSeries> parsePath(ArgReader& a, int tag) {
  const double factor = a.option("-factor", 1.0);
  const bool useLast = a.flag("-useLast");
  const bool prependZero = a.flag("-prependZero");
  const double startTime = a.option("-startTime", 0.0);
  const auto dt = a.optionalOption("-dt");
  const auto valuesText = a.optionalWordOption("-values");
  const auto filePath = a.optionalWordOption("-filePath");
  const auto timeText = a.optionalWordOption("-time");
  const auto fileTime = a.optionalWordOption("-fileTime");
  a.finish();
  if (valuesText && filePath) a.fail("give -values or -filePath, not both");
  if (!valuesText && !filePath) a.fail("needs -values {list} or -filePath file");
  std::vector<double> values;
  double fileDt = 0.0;
  if (valuesText) {
    values = parseNumberList(a, *valuesText, "-values");
  } else {
    domain::RecordFile record = domain::readRecordFile(*filePath);
    values = std::move(record.values);
    fileDt = record.dt;
  }
  if (values.empty()) a.fail("the series has no values");
  if (timeText || fileTime) {
    std::vector<double> times;
    if (timeText)
      times = parseNumberList(a, *timeText, "-time");
    else
      times = domain::readRecordFile(*fileTime).values;
    if (times.size() != values.size())
      a.fail("-time has " + std::to_string(times.size()) + " entries but there are " +
             std::to_string(values.size()) + " values");
    for (std::size_t i = 1; i < times.size(); ++i)
      if (!(times[i] > times[i - 1])) a.fail("-time values must increase");
    if (prependZero) {
      times.insert(times.begin(), 0.0);
      values.insert(values.begin(), 0.0);
    }
    return std::make_shared<domain::PathSeries>(tag, std::move(times), std::move(values), factor,
                                                useLast);
  }
  double step = dt.value_or(fileDt);
  if (!(step > 0.0)) a.fail("needs -dt (positive) or a file whose header gives DT");
  if (prependZero) values.insert(values.begin(), 0.0);
  return std::make_shared<domain::PathSeries>(tag, step, std::move(values), factor, startTime,
                                              useLast);
}

using SeriesPtr = std::shared_ptr<const domain::TimeSeries>;

SeriesPtr parseConstant(ArgReader& a, int tag) {
  const double f = a.option("-factor", 1.0);
  a.finish();
  return std::make_shared<domain::ConstantSeries>(tag, f);
}

SeriesPtr parseLinear(ArgReader& a, int tag) {
  const double f = a.option("-factor", 1.0);
  a.finish();
  return std::make_shared<domain::LinearSeries>(tag, f);
}

SeriesPtr parseTrig(ArgReader& a, int tag) {
  const double t0 = a.real("tStart"), t1 = a.real("tEnd"), period = a.real("period");
  const double f = a.option("-factor", 1.0);
  const double shift = a.option("-shift", 0.0);
  const double zeroShift = a.option("-zeroShift", 0.0);
  a.finish();
  if (!(period > 0.0)) a.failArgument("period", "must be positive");
  if (t1 < t0) a.failArgument("tEnd", "must not be before tStart");
  return std::make_shared<domain::TrigSeries>(tag, t0, t1, period, f, shift, zeroShift);
}

SeriesPtr parseRectangular(ArgReader& a, int tag) {
  const double t0 = a.real("tStart"), t1 = a.real("tEnd");
  const double f = a.option("-factor", 1.0);
  a.finish();
  if (t1 < t0) a.failArgument("tEnd", "must not be before tStart");
  return std::make_shared<domain::RectangularSeries>(tag, t0, t1, f);
}

SeriesPtr parseNearFaultPulse(ArgReader& a, int tag) {
  domain::NearFaultPulseSeries::Params p;
  const auto Tp = a.optionalOption("-Tp"), Vp = a.optionalOption("-Vp"),
             gamma = a.optionalOption("-gamma");
  const auto nu = a.optionalOption("-nu"), t0 = a.optionalOption("-t0");
  p.factor = a.option("-factor", 1.0);
  p.velocity = a.flag("-velocity");
  a.finish();
  if (!Tp || !Vp || !gamma || !nu || !t0) a.fail("needs -Tp, -Vp, -gamma, -nu and -t0");
  p.Tp = *Tp;
  p.Vp = *Vp;
  p.gamma = *gamma;
  p.nu = *nu;
  p.t0 = *t0;
  p.validate();
  return std::make_shared<domain::NearFaultPulseSeries>(tag, p);
}

using SeriesParserFn = SeriesPtr (*)(ArgReader& a, int tag);

// OpenSees' names with their synonyms (Sine for Trig, Series for Path, the *Series spellings).
constexpr TypeEntry<SeriesParserFn> kSeries[] = {
    {"Constant", "", parseConstant}, {"ConstantSeries", "", parseConstant},
    {"Linear", "", parseLinear},     {"LinearSeries", "", parseLinear},
    {"Trig", "", parseTrig},         {"Sine", "", parseTrig},
    {"TrigSeries", "", parseTrig},   {"Rectangular", "", parseRectangular},
    {"Path", "", parsePath},         {"Series", "", parsePath},
    {"PathSeries", "", parsePath},   {"NearFaultPulse", "", parseNearFaultPulse},
};

}  // namespace

std::shared_ptr<const domain::TimeSeries> parseSeries(Runtime& rt, ArgReader& a, bool withTag) {
  const std::string type = a.word("type");
  const auto* entry = findType<TypeEntry<SeriesParserFn>>({kSeries}, type);
  if (entry == nullptr)
    a.fail(a.positionOf("type"), "type",
           "\"" + type +
               "\" is not a known time series (Constant, Linear, Trig, Rectangular, Path, "
               "NearFaultPulse)");
  int tag = 0;
  if (withTag) {
    a.setContext(a.context() + " " + type);
    tag = readNewTag(a, rt.builder.timeSeries, "timeSeries");
  }
  return entry->parse(a, tag);
}

std::shared_ptr<const domain::TimeSeries> seriesArgument(Runtime& rt, ArgReader& a,
                                                         std::string_view name) {
  Tcl_Obj* obj = a.object(name);
  if (const auto tag = integerValue(obj)) return rt.builder.series(*tag);
  // A number is a tag, never a one-word spec: a tag out of range is reported as such.
  if (isIntegerWord(Tcl_GetString(obj)))
    a.failArgument(name, integerExpectation(obj) + " (a time series tag)");
  int count = 0;
  Tcl_Obj** items = nullptr;
  if (Tcl_ListObjGetElements(nullptr, obj, &count, &items) != TCL_OK || count == 0)
    a.failArgument(name, "expected a time series tag or spec");
  ArgReader inner(count, items, "Type ?args?", 0);
  inner.setContext(a.context() + " (" + std::string(name) + ")");
  return parseSeries(rt, inner, false);
}

}  // namespace dabs::tcl
