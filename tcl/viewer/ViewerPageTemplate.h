// SPDX-License-Identifier: MIT
#pragma once

#include <string_view>

namespace dabs::viewer {

/// Marker in the page template that the Viewer recorder replaces with its JSON data block. It
/// stands inside `<script id="dabs-data" type="application/json">`, before any script code.
inline constexpr std::string_view kViewerDataMarker = "__DABS_VIEWER_DATA__";

/// The self-contained HTML page of the post-processor (three.js scene, uPlot histories, styles and
/// script inlined) with kViewerDataMarker where the data goes. When node/npm were missing at
/// build time this is a plain page that says the viewer was not built, still holding the marker.
std::string_view viewerPageTemplate();

/// True when the page template holds the bundled viewer (node/npm were available at build time).
bool viewerBundleBuilt();

}  // namespace dabs::viewer
