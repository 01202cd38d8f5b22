// SPDX-License-Identifier: MIT
#pragma once

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "tcl/domain/Recorder.h"

namespace dabs::domain {

/// One plotted time history of `recorder Viewer -plots`: a node response component or one
/// component of an element response.
struct ViewerPlot {
  enum class Source { Node, Element };
  enum class NodeQuantity { Disp, Vel, Accel };
  std::string label;  ///< name shown above the plot
  Source source = Source::Node;
  int tag = 0;  ///< node or element tag
  int dof = 0;  ///< node dof, 0-based
  NodeQuantity quantity = NodeQuantity::Disp;
  std::vector<std::string> response;  ///< element response words, e.g. {"gap"}
  int component = 0;                  ///< element response component, 0-based
};

/// Cross-section drawn for beam elements (`-beamSection`): a rectangle width x depth (local y x
/// local z) or a circle of diameter `width`.
struct ViewerBeamSection {
  enum class Shape { Rect, Circle };
  Shape shape = Shape::Rect;
  double width = 0.0;         ///< rectangle width along local y, or circle diameter (m)
  double depth = 0.0;         ///< rectangle depth along local z (m)
  std::vector<int> elements;  ///< beam element tags
};

/// Bearing pads drawn between the two nodes of bearing elements (`-bearingPad`).
struct ViewerPad {
  double lx = 0.0, ly = 0.0;  ///< plan size along global X and Y (m)
  std::vector<int> elements;  ///< bearing element tags
};

/// Solid blocks drawn at nodes and moving with them (`-block`): pier caps, footings.
struct ViewerBlock {
  double lx = 0.0, ly = 0.0, lz = 0.0;  ///< size along global X, Y, Z (m)
  double dz = 0.0;                      ///< centre of the block above the node (m)
  std::vector<int> nodes;
};

/// A joint whose relative displacement (node b minus node a) the page prints (`-gaps`).
struct ViewerGap {
  std::string label;
  int nodeA = 0, nodeB = 0;
};

/// Options of `recorder Viewer`.
struct ViewerOptions {
  std::string file;               ///< output HTML page
  double deltaT = 0.0;            ///< record a frame only when at least dT passed (0: every step)
  std::vector<int> nodes;         ///< nodes drawn (empty: all nodes when the recorder is created)
  std::vector<ViewerPlot> plots;  ///< plotted time histories
  std::string title;              ///< page title
  std::vector<ViewerBeamSection> sections;  ///< drawn beam sections (fiber sections: automatic)
  std::vector<ViewerPad> pads;              ///< drawn bearing pads
  std::vector<ViewerBlock> blocks;          ///< drawn blocks at nodes
  std::vector<ViewerGap> gaps;              ///< joints whose gaps are printed
};

/// `recorder Viewer`: records the deformed shape, contact status, bearing damage and chosen time
/// histories, and writes ONE self-contained HTML page (tcl/viewer: three.js scene, uPlot plots,
/// data inlined) that opens from disk.
///
/// Data block (JSON in `<script id="dabs-data">`, read by tcl/viewer/src/data.js): model
/// (node tags and coordinates, elements with a kind: beam, bearing, contact, link, other, and a
/// drawn shape: a beam's section outline in local (y, z) -- from -beamSection, else the convex hull
/// of a fiber section's fibers scaled to the section's area -- or a bearing's pad size), blocks,
/// gaps, the frame times, per contact its status, gap and normal force, per bearing its damage and
/// shear strain, the ground acceleration of every UniformExcitation pattern (with its dof), and per
/// series [q, offset]: values q * k_i, with integers k_i stored as zigzag
/// LEB128 varints of k_i - k_{i-1} at byte `offset` of the base64 string "bytes". q is the peak
/// |value| / kQuantizationLevels (1 for status and damage, which are integers), so every value is
/// kept to half of q, i.e. 5 significant digits of the series' peak, in about 2 bytes.
///
/// The page is rewritten at flush() (end of every analyze) when frames were added, at most once
/// per kMinRewriteRatio times the duration of the last write (so `analyze 1` in a loop does not
/// rewrite a large page at every step), and always by the destructor (wipe, remove, exit).
class ViewerRecorder final : public Recorder {
 public:
  /// Quantization of a series: q = max |value| / kQuantizationLevels.
  static constexpr double kQuantizationLevels = 1e5;
  /// Minimum wall time between rewrites at flush(), as a multiple of the last write's duration.
  static constexpr double kMinRewriteRatio = 20.0;

  /// `pageTemplate` holds dabs::viewer::kViewerDataMarker where the data block goes; empty means
  /// the built-in page (dabs::viewer::viewerPageTemplate()). Throws InputError when the file
  /// cannot be written or the template has no marker.
  explicit ViewerRecorder(ViewerOptions options, std::string_view pageTemplate = {});
  ~ViewerRecorder() override;
  /// Resolves the nodes and elements drawn and checks the plotted quantities exist.
  void initialize(const Domain& domain) override;
  void record(const Domain& domain) override;
  /// The contacts (status, gap, force at every frame) and the elements plotted.
  void elementsRead(std::vector<int>& tags) const override;
  /// Rewrites the page when frames were added (see the class comment for the rate limit).
  void flush() override;
  /// Writes the page now.
  void write();
  /// The JSON data block for the frames recorded so far.
  std::string dataJson() const;
  /// Number of frames recorded.
  std::size_t frames() const noexcept { return time_.size(); }

 private:
  struct DrawnElement {
    int tag;
    std::string kind;
    std::string type;
    std::vector<int> nodes;
    std::vector<double> outline;  // beams: section outline, y z pairs; bearings: pad lx ly
  };
  ViewerOptions options_;
  std::string template_;
  std::vector<int> nodes_;
  std::vector<double> coords_;  // 3 per node
  int ndm_ = 1;
  bool initialized_ = false;  // initialize() succeeded
  std::vector<DrawnElement> elements_;
  std::vector<int> contacts_;                // nodeToSurface element tags
  std::vector<int> bearings_;                // yoshidaBearing element tags
  std::vector<std::pair<int, int>> ground_;  // UniformExcitation pattern tag, dof (0-based)
  // Recorded values, frame by frame: time; 3 translations per node; status, gap and normal force
  // per contact; damage and shear strain per bearing; ground acceleration per pattern; one value
  // per plot.
  std::vector<double> time_, disp_, status_, gap_, force_, damage_, strain_, groundAccel_,
      plotValues_;
  double nextTime_ = 0.0;
  std::size_t written_ = 0;  // frames in the file
  bool everWritten_ = false;
  std::chrono::steady_clock::time_point lastWrite_{};
  std::chrono::duration<double> lastWriteDuration_{0.0};
};

/// Element kind drawn by the viewer for an element type name: "beam" (elasticBeamColumn,
/// forceBeamColumn, dispBeamColumn, truss), "bearing" (yoshidaBearing), "contact"
/// (nodeToSurface), "link" (zeroLength, zeroLengthSection) or "other".
std::string_view viewerElementKind(std::string_view typeName);

}  // namespace dabs::domain
