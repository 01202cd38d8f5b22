// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "tcl/commands/ArgReader.h"
#include "tcl/commands/Runtime.h"
#include "tcl/domain/TimeSeries.h"

namespace dabs::tcl {

/// Reads `Type tag? options...` of a time series: `Constant`, `Linear`, `Trig|Sine`,
/// `Rectangular`, `Path|Series`, and the rows of timeSeriesTypes(). With `withTag` false the
/// series is anonymous (an inline series such as `pattern Plain 1 "Linear -factor 2" {...}`).
std::shared_ptr<const domain::TimeSeries> parseSeries(Runtime& rt, ArgReader& a, bool withTag);

/// A series given to a pattern as a tag or as an inline spec list.
std::shared_ptr<const domain::TimeSeries> seriesArgument(Runtime& rt, ArgReader& a,
                                                         std::string_view name);

/// Reads a Tcl list of numbers (e.g. the value of -values); throws ArgError naming `key`.
std::vector<double> parseNumberList(ArgReader& a, const std::string& text, std::string_view key);

}  // namespace dabs::tcl
