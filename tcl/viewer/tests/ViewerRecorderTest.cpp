// SPDX-License-Identifier: MIT
// Over 400 lines: one test file for the viewer recorder, each test a separate part of the file
// it writes.
// The Viewer recorder's page holds the recorded values: the data block is parsed back here with a
// JSON reader and a base64/varint decoder written for this test (independent of the writer) and
// compared with the Node recorder's file and with closed forms.
#include "tcl/viewer/ViewerRecorder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "elements/link/Truss.h"
#include "materials/Elastic.h"
#include "materials/InputError.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/LinearSeries.h"
#include "tcl/domain/LoadPattern.h"
#include "tcl/domain/NodeRecorder.h"
#include "tcl/viewer/ViewerPageTemplate.h"

namespace dabs::domain {
namespace {

// --- a minimal JSON reader (objects, arrays, strings, numbers) -------------------------------
struct Json {
  std::variant<std::nullptr_t, double, std::string, std::vector<Json>, std::map<std::string, Json>>
      v;
  const Json& operator[](const std::string& key) const {
    return std::get<std::map<std::string, Json>>(v).at(key);
  }
  const Json& operator[](std::size_t i) const { return std::get<std::vector<Json>>(v).at(i); }
  std::size_t size() const { return std::get<std::vector<Json>>(v).size(); }
  double num() const { return std::get<double>(v); }
  const std::string& str() const { return std::get<std::string>(v); }
};

class JsonReader {
 public:
  explicit JsonReader(std::string_view s) : s_(s) {}
  Json parse() {
    Json j = value();
    skip();
    if (p_ != s_.size()) throw std::runtime_error("trailing characters in JSON");
    return j;
  }

 private:
  void skip() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  void expect(char c) {
    skip();
    if (p_ >= s_.size() || s_[p_] != c) throw std::runtime_error(std::string("expected ") + c);
    ++p_;
  }
  Json value() {
    skip();
    const char c = s_.at(p_);
    if (c == '{') {
      ++p_;
      std::map<std::string, Json> m;
      skip();
      if (s_.at(p_) == '}') return ++p_, Json{m};
      for (;;) {
        skip();
        std::string key = string();
        expect(':');
        m[key] = value();
        skip();
        if (s_.at(p_++) == '}') return Json{m};
      }
    }
    if (c == '[') {
      ++p_;
      std::vector<Json> a;
      skip();
      if (s_.at(p_) == ']') return ++p_, Json{a};
      for (;;) {
        a.push_back(value());
        skip();
        if (s_.at(p_++) == ']') return Json{a};
      }
    }
    if (c == '"') return Json{string()};
    std::size_t used = 0;
    const double d = std::stod(std::string(s_.substr(p_, 40)), &used);
    p_ += used;
    return Json{d};
  }
  std::string string() {
    expect('"');
    std::string out;
    while (s_.at(p_) != '"') {
      char c = s_[p_++];
      if (c == '\\') {
        c = s_.at(p_++);
        if (c == 'u') {
          out += static_cast<char>(std::stoi(std::string(s_.substr(p_, 4)), nullptr, 16));
          p_ += 4;
          continue;
        }
      }
      out += c;
    }
    ++p_;
    return out;
  }
  std::string_view s_;
  std::size_t p_ = 0;
};

std::vector<unsigned char> fromBase64(const std::string& text) {
  std::vector<unsigned char> out;
  unsigned buffer = 0;
  int bits = 0;
  for (char c : text) {
    int v;
    if (c >= 'A' && c <= 'Z')
      v = c - 'A';
    else if (c >= 'a' && c <= 'z')
      v = c - 'a' + 26;
    else if (c >= '0' && c <= '9')
      v = c - '0' + 52;
    else if (c == '+')
      v = 62;
    else if (c == '/')
      v = 63;
    else
      continue;  // padding
    buffer = buffer << 6 | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<unsigned char>(buffer >> bits & 0xff));
    }
  }
  return out;
}

/// The page's data: JSON plus decoded series.
struct PageData {
  Json json;
  std::vector<unsigned char> bytes;
  std::size_t frames = 0;
  std::vector<double> series(const Json& descriptor) const {
    const double q = descriptor[0].num();
    std::size_t pos = static_cast<std::size_t>(descriptor[1].num());
    std::vector<double> out;
    long long level = 0;
    for (std::size_t i = 0; i < frames; ++i) {
      unsigned long long zz = 0;
      int shift = 0;
      unsigned char b;
      do {
        b = bytes.at(pos++);
        zz |= static_cast<unsigned long long>(b & 0x7f) << shift;
        shift += 7;
      } while (b & 0x80);
      const long long delta =
          (zz & 1) ? -static_cast<long long>((zz + 1) / 2) : static_cast<long long>(zz / 2);
      level += delta;
      out.push_back(static_cast<double>(level) * q);
    }
    return out;
  }
  double q(const Json& descriptor) const { return descriptor[0].num(); }
};

const std::string kOpen = "<script id=\"dabs-data\" type=\"application/json\">";

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

PageData readPage(const std::string& path) {
  const std::string page = readFile(path);
  const std::size_t a = page.find(kOpen);
  if (a == std::string::npos) throw std::runtime_error("no data block in " + path);
  const std::size_t b = page.find("</script>", a);
  PageData d;
  d.json =
      JsonReader(std::string_view(page).substr(a + kOpen.size(), b - a - kOpen.size())).parse();
  d.bytes = fromBase64(d.json["bytes"].str());
  d.frames = static_cast<std::size_t>(d.json["frames"].num());
  return d;
}

std::vector<std::vector<double>> readRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::vector<double> row;
    double v;
    while (s >> v) row.push_back(v);
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

// A small template standing in for the built page (the real one is tested below).
const std::string kTemplate =
    "<html><body>" + kOpen + std::string(viewer::kViewerDataMarker) + "</script></body></html>";

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("dabs_viewer_test_" + name)).string();
}

/// Imposed displacement of a node component: a sine with a distinct amplitude, frequency and
/// phase per node and component (m).
double imposed(int node, int c, double t) {
  return 0.01 * (node + 1) * (c + 1) *
         std::sin((1.0 + 0.3 * c) * 2.0 * std::numbers::pi * t + node);
}

constexpr double kDt = 0.02;  // s
constexpr int kSteps = 60;
constexpr double kTimeTolerance = 1e-9;  // s, time printed with 10 digits
// Quantization: each value is kept to half its series' q = peak / kQuantizationLevels; the Node
// recorder file (precision 12) adds a rounding far below that.
constexpr double kHalfLevel = 0.5 * (1.0 + 1e-9);

/// Three nodes on the x axis and a truss 1-2 (E = 200e9 Pa, A = 0.01 m2, L = 2 m).
void buildModel(Domain& domain) {
  domain.addNode(1, 3, 3, Eigen::Vector3d(0.0, 0.0, 0.0));
  domain.addNode(2, 3, 3, Eigen::Vector3d(2.0, 0.0, 0.0));
  domain.addNode(3, 3, 3, Eigen::Vector3d(2.0, 1.0, 0.5));
  materials::Elastic::Params mp;
  mp.E = 200e9;
  elements::Truss::Params tp;
  tp.nodes = {1, 2};
  tp.area = 0.01;
  domain.addElement(
      std::make_unique<elements::Truss>(7, tp, std::make_unique<materials::Elastic>(1, mp)));
}

/// Imposes the displacements of step k, updates the truss and commits (which records).
void step(Domain& domain, int k) {
  const double t = kDt * k;
  domain.setTime(t);
  for (auto& [tag, n] : domain.nodes())
    for (int c = 0; c < 3; ++c) {
      n.disp(c) = imposed(tag, c, t);
      n.vel(c) = 0.5 * imposed(tag, c, t);
    }
  Eigen::VectorXd u(6), zero = Eigen::VectorXd::Zero(6);
  u << domain.node(1).disp, domain.node(2).disp;
  ASSERT_EQ(domain.findElement(7)->update({u, zero, zero, t, kDt}), Status::Ok);
  domain.commit();
}

TEST(ViewerRecorderTest, DisplacementsRoundTripTheNodeRecorderFile) {
  const std::string page = tempPath("roundtrip.html");
  const std::string nodeFile = tempPath("roundtrip.out");
  {
    Domain domain;
    buildModel(domain);
    RecorderOutput out;
    out.file = nodeFile;
    out.time = true;
    out.precision = 12;
    domain.addRecorder(std::make_unique<NodeRecorder>(
        out, std::vector<int>{1, 2, 3}, std::vector<int>{0, 1, 2}, NodeRecorder::Response::Disp, 0,
        std::vector<std::shared_ptr<const TimeSeries>>{}));
    ViewerOptions options;
    options.file = page;
    domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate));
    for (int k = 1; k <= kSteps; ++k) step(domain, k);
    domain.flushRecorders();
  }
  const PageData d = readPage(page);
  const auto rows = readRows(nodeFile);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(kSteps));
  ASSERT_EQ(d.frames, rows.size());
  ASSERT_EQ(d.json["nodes"].size(), 3u);
  EXPECT_EQ(d.json["ndm"].num(), 3.0);
  EXPECT_EQ(d.json["coords"][1][0].num(), 2.0);
  EXPECT_EQ(d.json["coords"][2][2].num(), 0.5);
  for (std::size_t f = 0; f < rows.size(); ++f)
    EXPECT_NEAR(d.json["time"][f].num(), rows[f][0], kTimeTolerance);
  for (std::size_t i = 0; i < 3; ++i) {
    ASSERT_EQ(d.json["nodes"][i].num(), static_cast<double>(i + 1));
    for (std::size_t c = 0; c < 3; ++c) {
      const Json& descriptor = d.json["disp"][3 * i + c];
      const auto values = d.series(descriptor);
      double peak = 0.0;
      for (const auto& row : rows) peak = std::max(peak, std::abs(row[1 + 3 * i + c]));
      EXPECT_NEAR(d.q(descriptor), peak / ViewerRecorder::kQuantizationLevels, 1e-12 * peak);
      for (std::size_t f = 0; f < rows.size(); ++f)
        ASSERT_NEAR(values[f], rows[f][1 + 3 * i + c], kHalfLevel * d.q(descriptor))
            << "node " << i + 1 << " component " << c << " frame " << f;
    }
  }
}

TEST(ViewerRecorderTest, PlotsHoldNodeAndElementResponses) {
  const std::string page = tempPath("plots.html");
  {
    Domain domain;
    buildModel(domain);
    ViewerOptions options;
    options.file = page;
    options.title = "plots </script> \"test\"";
    ViewerPlot vel;
    vel.label = "velocity 3 y";
    vel.tag = 3;
    vel.dof = 1;
    vel.quantity = ViewerPlot::NodeQuantity::Vel;
    ViewerPlot force;
    force.label = "truss force";
    force.source = ViewerPlot::Source::Element;
    force.tag = 7;
    force.response = {"axialForce"};
    options.plots = {vel, force};
    domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate));
    for (int k = 1; k <= kSteps; ++k) step(domain, k);
    domain.flushRecorders();
  }
  const std::string text = readFile(page);
  EXPECT_EQ(text.find("</script>"), text.rfind("</script>"))
      << "the title must not close the data block";
  const PageData d = readPage(page);
  EXPECT_EQ(d.json["title"].str(), "plots </script> \"test\"");
  const Json& element = d.json["elements"][0];
  EXPECT_EQ(element[0].num(), 7.0);
  EXPECT_EQ(element[1].str(), "beam");
  EXPECT_EQ(element[2].str(), "truss");
  ASSERT_EQ(d.json["plots"].size(), 2u);
  EXPECT_EQ(d.json["plots"][0]["label"].str(), "velocity 3 y");
  EXPECT_EQ(d.json["plots"][1]["source"].str(), "element 7 axialForce component 1");
  const auto v = d.series(d.json["plots"][0]["values"]);
  const auto n = d.series(d.json["plots"][1]["values"]);
  const double qv = d.q(d.json["plots"][0]["values"]);
  const double qn = d.q(d.json["plots"][1]["values"]);
  constexpr double kEA_L = 200e9 * 0.01 / 2.0;  // N/m
  for (int k = 1; k <= kSteps; ++k) {
    const double t = kDt * k;
    const auto f = static_cast<std::size_t>(k - 1);
    EXPECT_NEAR(v[f], 0.5 * imposed(3, 1, t), kHalfLevel * qv);
    // Small-displacement truss along x: N = EA/L (u2x - u1x).
    EXPECT_NEAR(n[f], kEA_L * (imposed(2, 0, t) - imposed(1, 0, t)),
                kHalfLevel * qn + 1e-6 * std::abs(n[f]));
  }
}

// The drawing data: beam sections, blocks and gaps as given; the ground acceleration of a
// UniformExcitation pattern defined after the recorder, at every frame: fact * t for a Linear
// series.
TEST(ViewerRecorderTest, DrawingDataAndGroundAcceleration) {
  const std::string page = tempPath("drawing.html");
  constexpr double kFact = 2.5;
  {
    Domain domain;
    buildModel(domain);
    ViewerOptions options;
    options.file = page;
    ViewerBeamSection rect;
    rect.width = 4.0;
    rect.depth = 1.5;
    rect.elements = {7};
    options.sections = {rect};
    ViewerBlock block;
    block.lx = 1.0;
    block.ly = 2.0;
    block.lz = 3.0;
    block.dz = -1.5;
    block.nodes = {1, 3};
    options.blocks = {block};
    options.gaps = {{"Gap1", 1, 2}};
    domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate));
    domain.addPattern(std::make_unique<UniformExcitation>(
        5, 1, std::make_shared<LinearSeries>(1, 1.0), kFact, 0.0));
    for (int k = 1; k <= kSteps; ++k) step(domain, k);
    domain.flushRecorders();
  }
  const PageData d = readPage(page);
  const Json& outline = d.json["elements"][0][4];
  ASSERT_EQ(outline.size(), 8u);
  // corners (-w/2, -d/2), (w/2, -d/2), (w/2, d/2), (-w/2, d/2)
  const double want[8] = {-2.0, -0.75, 2.0, -0.75, 2.0, 0.75, -2.0, 0.75};
  for (std::size_t i = 0; i < 8; ++i) EXPECT_DOUBLE_EQ(outline[i].num(), want[i]);
  ASSERT_EQ(d.json["blocks"].size(), 2u);
  EXPECT_EQ(d.json["blocks"][1][0].num(), 3.0);
  EXPECT_EQ(d.json["blocks"][1][4].num(), -1.5);
  EXPECT_EQ(d.json["gaps"][0][0].str(), "Gap1");
  EXPECT_EQ(d.json["gaps"][0][2].num(), 2.0);
  ASSERT_EQ(d.json["ground"].size(), 1u);
  EXPECT_EQ(d.json["ground"][0][0].num(), 1.0);  // dof 2 (Y), 0-based
  const auto a = d.series(d.json["ground"][0][1]);
  const double q = d.q(d.json["ground"][0][1]);
  for (int k = 1; k <= kSteps; ++k)
    EXPECT_NEAR(a[static_cast<std::size_t>(k - 1)], kFact * kDt * k, kHalfLevel * q);
}

TEST(ViewerRecorderTest, RejectsShapesOnTheWrongElements) {
  Domain domain;
  buildModel(domain);
  ViewerOptions options;
  options.file = tempPath("wrong.html");
  ViewerPad pad;
  pad.lx = pad.ly = 1.0;
  pad.elements = {7};  // a truss, not a bearing
  options.pads = {pad};
  EXPECT_THROW(domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate)),
               InputError);
  options.pads.clear();
  options.gaps = {{"G", 1, 99}};
  EXPECT_THROW(domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate)),
               InputError);
}

TEST(ViewerRecorderTest, DeltaTRecordsTheSameFramesAsTheNodeRecorder) {
  const std::string page = tempPath("dt.html");
  const std::string nodeFile = tempPath("dt.out");
  {
    Domain domain;
    buildModel(domain);
    RecorderOutput out;
    out.file = nodeFile;
    out.time = true;
    out.deltaT = 0.1;
    domain.addRecorder(std::make_unique<NodeRecorder>(
        out, std::vector<int>{2}, std::vector<int>{0}, NodeRecorder::Response::Disp, 0,
        std::vector<std::shared_ptr<const TimeSeries>>{}));
    ViewerOptions options;
    options.file = page;
    options.deltaT = 0.1;
    options.nodes = {2, 3};
    domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate));
    for (int k = 1; k <= kSteps; ++k) step(domain, k);
  }  // the destructors write
  const PageData d = readPage(page);
  const auto rows = readRows(nodeFile);
  // Steps at 0.02 s, frames every 0.1 s from the first: 0.02, 0.12, ..., 1.12.
  ASSERT_EQ(rows.size(), 12u);
  ASSERT_EQ(d.frames, rows.size());
  for (std::size_t f = 0; f < rows.size(); ++f)
    EXPECT_NEAR(d.json["time"][f].num(), rows[f][0], kTimeTolerance);
  EXPECT_EQ(d.json["nodes"].size(), 2u);
  EXPECT_EQ(d.json["elements"].size(), 0u) << "truss 1-2 has a node that is not drawn";
}

TEST(ViewerRecorderTest, RejectsUnknownNodesAndResponses) {
  Domain domain;
  buildModel(domain);
  ViewerOptions options;
  options.file = tempPath("bad.html");
  options.nodes = {1, 99};
  EXPECT_THROW(domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate)),
               InputError);
  options.nodes = {};
  ViewerPlot p;
  p.label = "bad";
  p.source = ViewerPlot::Source::Element;
  p.tag = 7;
  p.response = {"noSuchResponse"};
  options.plots = {p};
  EXPECT_THROW(domain.addRecorder(std::make_unique<ViewerRecorder>(options, kTemplate)),
               InputError);
  options.plots = {};
  EXPECT_THROW(ViewerRecorder(options, "<html>no marker</html>"), InputError);
}

TEST(ViewerRecorderTest, ElementKindsFollowTypeNames) {
  EXPECT_EQ(viewerElementKind("elasticBeamColumn"), "beam");
  EXPECT_EQ(viewerElementKind("forceBeamColumn"), "beam");
  EXPECT_EQ(viewerElementKind("dispBeamColumn"), "beam");
  EXPECT_EQ(viewerElementKind("truss"), "beam");
  EXPECT_EQ(viewerElementKind("yoshidaBearing"), "bearing");
  EXPECT_EQ(viewerElementKind("nodeToSurface"), "contact");
  EXPECT_EQ(viewerElementKind("zeroLength"), "link");
  EXPECT_EQ(viewerElementKind("somethingElse"), "other");
}

// Page size limit: 8,000 frames of 100 nodes stay under 10 MB (with the built page template).
TEST(ViewerRecorderTest, CaseStudySizedPageStaysUnderTenMegabytes) {
  constexpr int kNodes = 100;
  constexpr int kFrames = 8000;
  constexpr double kLimitBytes = 10e6;
  const std::string page = tempPath("large.html");
  {
    Domain domain;
    for (int i = 0; i < kNodes; ++i)
      domain.addNode(i + 1, 3, 6, Eigen::Vector3d(10.0 * i, 0.0, 0.0));
    ViewerOptions options;
    options.file = page;
    domain.addRecorder(std::make_unique<ViewerRecorder>(options));
    for (int k = 1; k <= kFrames; ++k) {
      const double t = 0.005 * k;
      domain.setTime(t);
      for (auto& [tag, n] : domain.nodes())
        for (int c = 0; c < 3; ++c)
          n.disp(c) = 0.2 * std::sin(2.0 * std::numbers::pi * t / (0.8 + 0.1 * c) + 0.05 * tag) *
                      std::exp(-0.05 * t);
      domain.commit();
    }
  }
  const auto size = static_cast<double>(std::filesystem::file_size(page));
  EXPECT_LT(size, kLimitBytes);
  const PageData d = readPage(page);
  EXPECT_EQ(d.frames, static_cast<std::size_t>(kFrames));
  const auto last = d.series(d.json["disp"][3 * (kNodes - 1) + 2]);
  const double t = 0.005 * kFrames;
  const double expected =
      0.2 * std::sin(2.0 * std::numbers::pi * t / 1.0 + 0.05 * kNodes) * std::exp(-0.05 * t);
  EXPECT_NEAR(last.back(), expected, kHalfLevel * d.q(d.json["disp"][3 * (kNodes - 1) + 2]));
  if (viewer::viewerBundleBuilt()) {
    EXPECT_NE(readFile(page).find("dabsViewer"), std::string::npos)
        << "the page holds the viewer script";
  }
}

}  // namespace
}  // namespace dabs::domain
