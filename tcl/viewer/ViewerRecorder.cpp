// SPDX-License-Identifier: MIT
#include "tcl/viewer/ViewerRecorder.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include "elements/beam/SectionBeamColumn.h"
#include "materials/InputError.h"
#include "materials/section/FiberSection.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/RecorderFile.h"
#include "tcl/viewer/SectionOutline.h"
#include "tcl/viewer/ViewerEncoding.h"
#include "tcl/viewer/ViewerPageTemplate.h"

namespace dabs::domain {

namespace {

// Relative tolerance on -dT, as in ResponseRecorder: round-off in accumulated time skips no frame.
constexpr double kDeltaTTolerance = 1e-10;

double nodeValue(const Node& n, int dof, ViewerPlot::NodeQuantity quantity) {
  if (dof >= n.ndf()) return 0.0;
  switch (quantity) {
    case ViewerPlot::NodeQuantity::Disp: return n.disp(dof);
    case ViewerPlot::NodeQuantity::Vel: return n.vel(dof);
    case ViewerPlot::NodeQuantity::Accel: return n.accel(dof);
  }
  return 0.0;
}

}  // namespace

std::string_view viewerElementKind(std::string_view typeName) {
  if (typeName == "elasticBeamColumn" || typeName == "forceBeamColumn" ||
      typeName == "dispBeamColumn" || typeName == "truss")
    return "beam";
  if (typeName == "yoshidaBearing") return "bearing";
  if (typeName == "nodeToSurface") return "contact";
  if (typeName == "zeroLength" || typeName == "zeroLengthSection") return "link";
  return "other";
}

ViewerRecorder::ViewerRecorder(ViewerOptions options, std::string_view pageTemplate)
    : options_(std::move(options)),
      template_(pageTemplate.empty() ? viewer::viewerPageTemplate() : pageTemplate) {
  if (template_.find(viewer::kViewerDataMarker) == std::string::npos)
    throw InputError("template", "has no data marker");
  if (options_.deltaT < 0.0) throw InputError("-dT", "must not be negative");
  std::ofstream probe(options_.file, std::ios::trunc);
  if (!probe) throw InputError("-file", "cannot write \"" + options_.file + "\"");
}

ViewerRecorder::~ViewerRecorder() {
  try {
    if (initialized_ && (!everWritten_ || written_ != frames())) write();
  } catch (...) {
    // A destructor must not throw; the page was written at the last flush that could.
  }
}

void ViewerRecorder::initialize(const Domain& domain) {
  initialized_ = false;
  nodes_ = options_.nodes;
  if (nodes_.empty())
    for (const auto& [tag, node] : domain.nodes()) nodes_.push_back(tag);
  for (int tag : nodes_)
    if (domain.findNode(tag) == nullptr)
      throw InputError("-nodes", "node " + std::to_string(tag) + " does not exist");
  coords_.clear();
  ndm_ = 1;
  for (int tag : nodes_) {
    const Node& n = domain.node(tag);
    for (int c = 0; c < 3; ++c) coords_.push_back(n.coords()(c));
    ndm_ = std::max(ndm_, n.ndm());
  }
  const std::set<int> drawn(nodes_.begin(), nodes_.end());
  elements_.clear();
  contacts_.clear();
  bearings_.clear();
  for (const auto& [tag, e] : domain.elements()) {
    const auto& en = e->nodeTags();
    if (!std::all_of(en.begin(), en.end(), [&](int n) { return drawn.count(n) != 0; })) continue;
    const std::string_view kind = viewerElementKind(e->typeName());
    std::vector<double> outline;
    if (kind == "beam") {
      if (const auto* b = dynamic_cast<const elements::SectionBeamColumn<3>*>(e.get());
          b != nullptr && b->numSections() > 0)
        if (const auto* f = dynamic_cast<const materials::section::FiberSection3d*>(&b->section(0)))
          outline = fiberOutline(*f);
    }
    elements_.push_back({tag, std::string(kind), std::string(e->typeName()), en, outline});
    if (kind == "contact") contacts_.push_back(tag);
    if (kind == "bearing") bearings_.push_back(tag);
  }
  auto drawnElement = [&](int tag, const char* option, std::string_view kind) -> DrawnElement& {
    for (DrawnElement& d : elements_)
      if (d.tag == tag) {
        if (d.kind != kind)
          throw InputError(option, "element " + std::to_string(tag) + " (" + d.type +
                                       ") is not a " + std::string(kind));
        return d;
      }
    throw InputError(option, "element " + std::to_string(tag) +
                                 " does not exist or has nodes that are not drawn");
  };
  for (const ViewerBeamSection& s : options_.sections) {
    if (!(s.width > 0.0) || (s.shape == ViewerBeamSection::Shape::Rect && !(s.depth > 0.0)))
      throw InputError("-beamSection", "sizes must be positive");
    for (int tag : s.elements) {
      DrawnElement& d = drawnElement(tag, "-beamSection", "beam");
      if (s.shape == ViewerBeamSection::Shape::Circle) {
        d.outline = circleOutline(s.width);
      } else {
        const double y = 0.5 * s.width, z = 0.5 * s.depth;
        d.outline = {-y, -z, y, -z, y, z, -y, z};
      }
    }
  }
  for (const ViewerPad& p : options_.pads) {
    if (!(p.lx > 0.0) || !(p.ly > 0.0)) throw InputError("-bearingPad", "sizes must be positive");
    for (int tag : p.elements) drawnElement(tag, "-bearingPad", "bearing").outline = {p.lx, p.ly};
  }
  for (const ViewerBlock& b : options_.blocks) {
    if (!(b.lx > 0.0) || !(b.ly > 0.0) || !(b.lz > 0.0))
      throw InputError("-block", "sizes must be positive");
    for (int n : b.nodes)
      if (drawn.count(n) == 0)
        throw InputError("-block", "node " + std::to_string(n) + " is not drawn");
  }
  for (const ViewerGap& g : options_.gaps)
    for (int n : {g.nodeA, g.nodeB})
      if (drawn.count(n) == 0)
        throw InputError("-gaps",
                         "\"" + g.label + "\": node " + std::to_string(n) + " is not drawn");
  for (const ViewerPlot& p : options_.plots) {
    if (p.source == ViewerPlot::Source::Node) {
      const Node& n = domain.node(p.tag);
      if (p.dof < 0 || p.dof >= n.ndf())
        throw InputError("-plots", "\"" + p.label + "\": node " + std::to_string(p.tag) +
                                       " has no dof " + std::to_string(p.dof + 1));
      continue;
    }
    const elements::Element* e = domain.findElement(p.tag);
    if (e == nullptr)
      throw InputError("-plots",
                       "\"" + p.label + "\": element " + std::to_string(p.tag) + " does not exist");
    const auto r = domain.elementResponse(p.tag, p.response);
    if (!r || p.component < 0 || p.component >= r->size())
      throw InputError("-plots", "\"" + p.label + "\": element " + std::to_string(p.tag) + " (" +
                                     std::string(e->typeName()) +
                                     ") has no such response component");
  }
  initialized_ = true;
}

void ViewerRecorder::elementsRead(std::vector<int>& tags) const {
  tags.insert(tags.end(), contacts_.begin(), contacts_.end());
  for (const ViewerPlot& p : options_.plots)
    if (p.source == ViewerPlot::Source::Element) tags.push_back(p.tag);
}

void ViewerRecorder::record(const Domain& domain) {
  if (!initialized_) return;
  const double t = domain.time();
  if (options_.deltaT > 0.0 && !time_.empty() &&
      t < nextTime_ - kDeltaTTolerance * std::max(1.0, std::abs(nextTime_)))
    return;
  nextTime_ = t + options_.deltaT;
  if (time_.empty()) {
    // The ground motions are those present at the first frame (a script may define its patterns
    // after the recorder); the recorded series keep one value per pattern per frame.
    ground_.clear();
    for (const auto& [tag, p] : domain.patterns())
      if (const auto* u = dynamic_cast<const UniformExcitation*>(p.get());
          u != nullptr && u->dof() < 3)
        ground_.emplace_back(tag, u->dof());
  }
  time_.push_back(t);
  for (int tag : nodes_) {
    const Node* n = domain.findNode(tag);
    for (int c = 0; c < 3; ++c)
      disp_.push_back(n != nullptr && c < std::min(n->ndm(), n->ndf()) ? n->disp(c) : 0.0);
  }
  auto scalar = [&](int tag, const char* name) {
    const std::string words[1] = {name};
    const auto r = domain.elementResponse(tag, words);
    return r && r->size() > 0 ? (*r)(0) : 0.0;
  };
  for (int tag : contacts_) {
    status_.push_back(scalar(tag, "status"));
    gap_.push_back(scalar(tag, "gap"));
    force_.push_back(scalar(tag, "contactForce"));  // normal component N
  }
  for (int tag : bearings_) {
    damage_.push_back(scalar(tag, "damage"));
    strain_.push_back(scalar(tag, "shearStrain"));
  }
  for (const auto& [tag, dof] : ground_) {
    const auto& patterns = domain.patterns();
    const auto it = patterns.find(tag);
    groundAccel_.push_back(it != patterns.end() ? it->second->factor(t) : 0.0);
  }
  for (const ViewerPlot& p : options_.plots) {
    double v = 0.0;
    if (p.source == ViewerPlot::Source::Node) {
      if (const Node* n = domain.findNode(p.tag)) v = nodeValue(*n, p.dof, p.quantity);
    } else if (domain.findElement(p.tag) != nullptr) {
      const auto r = domain.elementResponse(p.tag, p.response);
      if (r && p.component < r->size()) v = (*r)(p.component);
    }
    plotValues_.push_back(v);
  }
}

std::string ViewerRecorder::dataJson() const {
  const std::size_t n = frames();
  std::string json;
  std::string bytes;
  json.reserve(64 * (nodes_.size() + elements_.size()) + 16 * n);
  json += "{\"format\":\"dabs-viewer\",\"version\":2,\"title\":";
  appendString(json, options_.title);
  json += ",\"ndm\":" + std::to_string(ndm_);
  json += ",\"frames\":" + std::to_string(n) + ",\"time\":[";
  for (std::size_t f = 0; f < n; ++f) {
    if (f) json += ',';
    appendNumber(json, time_[f], 10);
  }
  json += "],\"nodes\":[";
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    if (i) json += ',';
    json += std::to_string(nodes_[i]);
  }
  json += "],\"coords\":[";
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    json += i ? ",[" : "[";
    for (int c = 0; c < 3; ++c) {
      if (c) json += ',';
      appendNumber(json, coords_[3 * i + static_cast<std::size_t>(c)], 10);
    }
    json += ']';
  }
  json += "],\"elements\":[";
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    const DrawnElement& e = elements_[i];
    json += i ? ",[" : "[";
    json += std::to_string(e.tag);
    json += ',';
    appendString(json, e.kind);
    json += ',';
    appendString(json, e.type);
    json += ",[";
    for (std::size_t k = 0; k < e.nodes.size(); ++k) {
      if (k) json += ',';
      json += std::to_string(e.nodes[k]);
    }
    json += "],[";
    for (std::size_t k = 0; k < e.outline.size(); ++k) {
      if (k) json += ',';
      appendNumber(json, e.outline[k], 6);
    }
    json += "]]";
  }
  json += "],\"blocks\":[";
  bool first = true;
  for (const ViewerBlock& b : options_.blocks)
    for (int node : b.nodes) {
      json += first ? "[" : ",[";
      first = false;
      json += std::to_string(node);
      for (double v : {b.lx, b.ly, b.lz, b.dz}) {
        json += ',';
        appendNumber(json, v, 6);
      }
      json += ']';
    }
  json += "],\"gaps\":[";
  for (std::size_t i = 0; i < options_.gaps.size(); ++i) {
    json += i ? ",[" : "[";
    appendString(json, options_.gaps[i].label);
    json += ',';
    json += std::to_string(options_.gaps[i].nodeA);
    json += ',';
    json += std::to_string(options_.gaps[i].nodeB);
    json += ']';
  }
  json += "],\"disp\":[";
  const std::size_t perFrame = 3 * nodes_.size();
  for (std::size_t s = 0; s < perFrame; ++s) {
    if (s) json += ',';
    appendSeries(json, bytes, disp_, s, perFrame, n, false, kQuantizationLevels);
  }
  json += "],\"contacts\":[";
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    json += i ? ",[" : "[";
    json += std::to_string(contacts_[i]);
    json += ',';
    appendSeries(json, bytes, status_, i, contacts_.size(), n, true, kQuantizationLevels);
    json += ',';
    appendSeries(json, bytes, gap_, i, contacts_.size(), n, false, kQuantizationLevels);
    json += ',';
    appendSeries(json, bytes, force_, i, contacts_.size(), n, false, kQuantizationLevels);
    json += ']';
  }
  json += "],\"bearings\":[";
  for (std::size_t i = 0; i < bearings_.size(); ++i) {
    json += i ? ",[" : "[";
    json += std::to_string(bearings_[i]);
    json += ',';
    appendSeries(json, bytes, damage_, i, bearings_.size(), n, true, kQuantizationLevels);
    json += ',';
    appendSeries(json, bytes, strain_, i, bearings_.size(), n, false, kQuantizationLevels);
    json += ']';
  }
  json += "],\"ground\":[";
  for (std::size_t i = 0; i < ground_.size(); ++i) {
    json += i ? ",[" : "[";
    json += std::to_string(ground_[i].second);
    json += ',';
    appendSeries(json, bytes, groundAccel_, i, ground_.size(), n, false, kQuantizationLevels);
    json += ']';
  }
  json += "],\"plots\":[";
  const std::size_t nPlots = options_.plots.size();
  for (std::size_t i = 0; i < nPlots; ++i) {
    const ViewerPlot& p = options_.plots[i];
    json += i ? ",{\"label\":" : "{\"label\":";
    appendString(json, p.label);
    std::string source;
    if (p.source == ViewerPlot::Source::Node) {
      static constexpr const char* kQuantity[] = {"disp", "vel", "accel"};
      source = "node " + std::to_string(p.tag) + " dof " + std::to_string(p.dof + 1) + " " +
               kQuantity[static_cast<int>(p.quantity)];
    } else {
      source = "element " + std::to_string(p.tag);
      for (const auto& w : p.response) source += " " + w;
      source += " component " + std::to_string(p.component + 1);
    }
    json += ",\"source\":";
    appendString(json, source);
    json += ",\"values\":";
    appendSeries(json, bytes, plotValues_, i, nPlots, n, false, kQuantizationLevels);
    json += '}';
  }
  json += "],\"bytes\":\"" + base64(bytes) + "\"}";
  return json;
}

void ViewerRecorder::write() {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t at = template_.find(viewer::kViewerDataMarker);
  // Written to a temporary file and renamed, so a browser never reads half a page.
  const std::string json = dataJson();
  const std::size_t after = at + viewer::kViewerDataMarker.size();
  RecorderFile::replaceAtomically(options_.file, {std::string_view(template_).substr(0, at), json,
                                                  std::string_view(template_).substr(after)});
  written_ = frames();
  everWritten_ = true;
  lastWrite_ = std::chrono::steady_clock::now();
  lastWriteDuration_ = lastWrite_ - start;
}

void ViewerRecorder::flush() {
  if (everWritten_ && written_ == frames()) return;
  if (everWritten_ &&
      std::chrono::steady_clock::now() - lastWrite_ < kMinRewriteRatio * lastWriteDuration_)
    return;
  write();
}

}  // namespace dabs::domain
