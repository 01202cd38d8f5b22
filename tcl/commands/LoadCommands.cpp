// SPDX-License-Identifier: MIT
// Load and time commands: timeSeries, pattern, load, eleLoad, sp, groundMotion, imposedMotion,
// loadConst, setTime, getTime, remove, rayleigh, modalDamping.
#include <string>

#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/SeriesParser.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

void timeSeriesCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("timeSeries");
  auto series = parseSeries(rt, a, true);
  rt.builder.timeSeries[series->tag()] = std::move(series);
}

// Evaluates a pattern body with the pattern current; on error the pattern is removed again, so a
// failed command leaves the model as it was.
void evalBody(Runtime& rt, ArgReader& a, int tag, Tcl_Obj* body) {
  const int previous = rt.currentPattern;
  rt.currentPattern = tag;
  const int status = Tcl_EvalObjEx(rt.interp, body, 0);
  rt.currentPattern = previous;
  if (status != TCL_OK) {
    const std::string inner = Tcl_GetStringResult(rt.interp);
    rt.domain.removePattern(tag);
    a.fail("in the pattern body: " + inner);
  }
  rt.currentPattern = tag;
}

void patternCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("pattern");
  const std::string type = a.word("type");
  a.setContext("pattern " + type);
  const int tag = readNewTag(a, rt.domain.patterns(), "pattern");
  if (type == "Plain") {
    a.setUsage("pattern Plain tag tsTag|{Type args} ?-fact f? { load ..; sp .. }");
    auto series = seriesArgument(rt, a, "tsTag");
    const double fact = a.option("-fact", 1.0);
    Tcl_Obj* body = a.hasMore() ? a.object("body") : nullptr;
    a.finish();
    rt.domain.addPattern(std::make_unique<domain::PlainPattern>(tag, std::move(series), fact));
    rt.currentPattern = tag;
    if (body != nullptr) evalBody(rt, a, tag, body);
  } else if (type == "UniformExcitation") {
    a.setUsage("pattern UniformExcitation tag dir -accel tsTag|{Type args} ?-vel0 v0? ?-fact f?");
    const int dir = a.integer("dir");
    const int ndf = rt.builder.ndf;
    if (dir < 1 || dir > ndf) a.fail(a.lastPosition(), "dir", "must be 1.." + std::to_string(ndf));
    const double vel0 = a.option("-vel0", 0.0);
    const double fact = a.option("-fact", 1.0);
    if (a.flag("-vel") || a.flag("-disp"))
      a.fail(
          "only -accel is supported for UniformExcitation (velocity and displacement records are "
          "integrated from it)");
    if (!a.flag("-accel")) a.fail("needs -accel tsTag");
    auto series = seriesArgument(rt, a, "-accel");
    a.finish();
    rt.domain.addPattern(
        std::make_unique<domain::UniformExcitation>(tag, dir - 1, std::move(series), fact, vel0));
    if (vel0 != 0.0) {
      // Initial relative velocity of every node free in that direction (OpenSees
      // UniformExcitation::setDomain).
      for (auto& [ntag, n] : rt.domain.nodes()) {
        if (dir - 1 >= n.ndf()) continue;
        bool fixed = false;
        for (const auto& sp : rt.domain.fixes())
          fixed = fixed || (sp.node == ntag && sp.dof == dir - 1);
        if (fixed) continue;
        n.vel(dir - 1) = vel0;
        n.committedVel(dir - 1) = vel0;
      }
    }
  } else if (type == "MultipleSupport" || type == "MultiSupport" ||
             type == "MultipleSupportExcitation") {
    a.setUsage("pattern MultipleSupport tag { groundMotion ..; imposedMotion .. }");
    Tcl_Obj* body = a.object("body");
    a.finish();
    rt.domain.addPattern(std::make_unique<domain::MultipleSupportPattern>(tag));
    rt.currentPattern = tag;
    evalBody(rt, a, tag, body);
  } else {
    a.fail(1, "type",
           "expected Plain, UniformExcitation or MultipleSupport (MultiSupport), got \"" + type +
               "\"");
  }
}

domain::PlainPattern& currentPlain(Runtime& rt, ArgReader& a) {
  const int tag = a.option("-pattern", rt.currentPattern);
  domain::LoadPattern* p = rt.domain.findPattern(tag);
  if (p == nullptr) a.fail("no load pattern to add to; define `pattern Plain` first");
  domain::PlainPattern* plain = p->asPlain();
  if (plain == nullptr) a.fail("pattern " + std::to_string(tag) + " is not a Plain pattern");
  return *plain;
}

domain::MultipleSupportPattern& currentMultiple(Runtime& rt, ArgReader& a) {
  domain::LoadPattern* p = rt.domain.findPattern(rt.currentPattern);
  domain::MultipleSupportPattern* multiple = p != nullptr ? p->asMultipleSupport() : nullptr;
  if (multiple == nullptr) a.fail("must be used inside `pattern MultipleSupport tag { ... }`");
  return *multiple;
}

void loadCmd(Runtime& rt, ArgReader& a) {
  const int node = a.integer("node");
  const domain::Node& n = rt.domain.node(node);
  domain::PlainPattern::NodalLoad load{node, Eigen::VectorXd(n.ndf())};
  for (int i = 0; i < n.ndf(); ++i) load.values(i) = a.real("load value");
  const bool constant = a.flag("-const");
  domain::PlainPattern& p = currentPlain(rt, a);
  a.finish();
  if (constant)
    a.fail("-const loads are not supported; put them in a pattern with a Constant series");
  p.loads.push_back(std::move(load));
}

// eleLoad -ele t1 t2 .. | -range first last -type -beamUniform|-beamPoint values (OpenSees'
// TclCommand_addElementalLoad): member loads in the element's local axes, added to the current
// Plain pattern. 2D: -beamUniform Wy ?Wx? ?aOverL ?bOverL? ?WyB ?WxB????, -beamPoint Py xL ?Px?;
// 3D: -beamUniform Wy Wz ?Wx? ?aOverL ?bOverL? ?WyB ?WzB ?WxB?????, -beamPoint Py Pz xL ?Px?
// (WyB.. the intensities at bOverL of a load varying linearly along the member).
void eleLoadCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("eleLoad");
  const int ndm = rt.builder.ndm;
  a.setUsage(ndm == 3 ? "eleLoad -ele tags.. | -range first last -type -beamUniform Wy Wz ?Wx? "
                        "?aOverL bOverL? ?WyB WzB WxB? | -beamPoint Py Pz xL ?Px?"
                      : "eleLoad -ele tags.. | -range first last -type -beamUniform Wy ?Wx? "
                        "?aOverL bOverL? ?WyB WxB? | -beamPoint Py xL ?Px?");
  std::vector<int> tags;
  while (auto list = a.optionIntegerList("-ele"))
    tags.insert(tags.end(), list->begin(), list->end());
  while (auto range = a.optionTagRange("-range"))
    for (int t = range->first; t <= range->second; ++t) tags.push_back(t);
  if (tags.empty()) a.fail("needs the loaded elements: -ele tags.. or -range first last");
  const auto typeWord = a.optionalWordOption("-type");
  if (!typeWord) a.fail("needs -type -beamUniform or -type -beamPoint");
  std::string type = *typeWord;
  if (!type.empty() && type[0] == '-') type.erase(0, 1);
  if (ndm != 2 && ndm != 3) a.fail("member loads need a 2D or 3D model");
  const std::vector<double> v = a.reals("load values");
  domain::PlainPattern& p = currentPlain(rt, a);
  a.finish();

  elements::BeamLoad load;
  const std::size_t n = v.size();
  auto at = [&v](std::size_t i, double fallback) { return i < v.size() ? v[i] : fallback; };
  if (type == "beamUniform") {
    load.type = elements::BeamLoad::Type::Uniform;
    const std::size_t transverse = ndm == 3 ? 2 : 1;  // Wy (Wz)
    if (n < transverse) a.fail(ndm == 3 ? "-beamUniform needs Wy Wz" : "-beamUniform needs Wy");
    // After aOverL bOverL OpenSees reads the intensities at bOverL, each defaulting to its value
    // at aOverL: 2D Wy Wx, 3D Wy Wz Wx.
    const std::size_t atEnd = transverse + 3;
    if (n > atEnd + transverse + 1)
      a.fail("-beamUniform takes at most " + std::to_string(atEnd + transverse + 1) + " values");
    load.w = Eigen::Vector3d(at(transverse, 0.0), v[0], ndm == 3 ? v[1] : 0.0);
    load.a = at(transverse + 1, 0.0);
    load.b = at(transverse + 2, 1.0);
    if (n > atEnd) {
      const Eigen::Vector3d end(at(atEnd + transverse, load.w.x()), at(atEnd, load.w.y()),
                                ndm == 3 ? at(atEnd + 1, load.w.z()) : 0.0);
      if (end != load.w) load.wEnd = end;
    }
    if (!(load.a >= 0.0 && load.a < load.b && load.b <= 1.0))
      a.fail("-beamUniform needs 0 <= aOverL < bOverL <= 1, got " + std::to_string(load.a) +
             " and " + std::to_string(load.b));
  } else if (type == "beamPoint") {
    load.type = elements::BeamLoad::Type::Point;
    const std::size_t transverse = ndm == 3 ? 2 : 1;  // Py (Pz)
    if (n < transverse + 1 || n > transverse + 2)
      a.fail(ndm == 3 ? "-beamPoint needs Py Pz xL ?Px?" : "-beamPoint needs Py xL ?Px?");
    load.w = Eigen::Vector3d(at(transverse + 1, 0.0), v[0], ndm == 3 ? v[1] : 0.0);
    load.a = v[transverse];
    if (!(load.a >= 0.0 && load.a <= 1.0))
      a.fail("-beamPoint needs 0 <= xL <= 1, got " + std::to_string(load.a));
  } else {
    a.fail("-type expects -beamUniform or -beamPoint, got \"" + *typeWord + "\"");
  }
  const int dofPerNode = ndm == 3 ? 6 : 3;
  for (int tag : tags) {
    const elements::Element* e = rt.domain.findElement(tag);
    if (e == nullptr) a.fail("element " + std::to_string(tag) + " does not exist");
    if (!e->acceptsBeamLoads() || e->dofPerNode() != dofPerNode)
      a.fail("element " + std::to_string(tag) + " (" + std::string(e->typeName()) +
             ") takes no member loads");
  }
  for (int tag : tags) p.memberLoads.push_back({tag, load});
  // A loaded element's force is no longer its stiffness times its displacements: the analysis
  // forms it through the element again.
  rt.domain.touch();
}

void spCmd(Runtime& rt, ArgReader& a) {
  const int node = a.integer("node");
  const int dof = a.integer("dof");
  const double value = a.real("value");
  const bool constant = a.flag("-const");
  const domain::Node& n = rt.domain.node(node);
  if (dof < 1 || dof > n.ndf()) a.fail(2, "dof", "must be 1.." + std::to_string(n.ndf()));
  domain::PlainPattern& p = currentPlain(rt, a);
  a.finish();
  for (const auto& fix : rt.domain.fixes())
    if (fix.node == node && fix.dof == dof - 1)
      a.fail("node " + std::to_string(node) + " dof " + std::to_string(dof) +
             " is fixed; an sp cannot also prescribe it");
  p.prescribed.push_back({node, dof - 1, value, constant});
  rt.domain.touch();
}

void groundMotionCmd(Runtime& rt, ArgReader& a) {
  domain::MultipleSupportPattern& p = currentMultiple(rt, a);
  const int tag = a.integer("tag");
  a.setContext("groundMotion " + std::to_string(tag));
  if (p.groundMotions.count(tag) != 0)
    a.fail(1, "tag", "groundMotion " + std::to_string(tag) + " already exists");
  const std::string type = a.word("type");
  if (type != "Plain") a.fail(2, "type", "expected Plain, got \"" + type + "\"");
  std::shared_ptr<const domain::TimeSeries> accel, vel, disp;
  const double fact = a.option("-fact", 1.0);
  if (a.flag("-accel")) accel = seriesArgument(rt, a, "-accel");
  if (a.flag("-vel")) vel = seriesArgument(rt, a, "-vel");
  if (a.flag("-disp")) disp = seriesArgument(rt, a, "-disp");
  a.finish();
  if (!accel && !vel && !disp) a.fail("needs -accel, -vel or -disp");
  p.groundMotions[tag] = std::make_unique<domain::GroundMotion>(accel, vel, disp, fact);
}

void imposedMotionCmd(Runtime& rt, ArgReader& a) {
  domain::MultipleSupportPattern& p = currentMultiple(rt, a);
  const int node = a.integer("node");
  const int dof = a.integer("dof");
  const int gm = a.integer("gmTag");
  a.finish();
  const domain::Node& n = rt.domain.node(node);
  if (dof < 1 || dof > n.ndf()) a.fail(2, "dof", "must be 1.." + std::to_string(n.ndf()));
  if (p.groundMotions.count(gm) == 0)
    a.fail(3, "gmTag", "groundMotion " + std::to_string(gm) + " does not exist");
  // A fixed support dof follows the motion while the pattern exists, as under OpenSees'
  // Transformation handler (its Plain handler ignores the motion, its Penalty handler averages the
  // two constraints); removing the pattern fixes the dof again.
  bool fixed = false;
  for (const auto& fix : rt.domain.fixes())
    fixed = fixed || (fix.node == node && fix.dof == dof - 1);
  if (fixed) rt.domain.removeFix(node, dof - 1);
  p.imposed.push_back({node, dof - 1, gm, fixed});
  rt.domain.touch();
}

void loadConstCmd(Runtime& rt, ArgReader& a) {
  const auto time = a.optionalOption("-time");
  a.finish();
  rt.domain.setLoadConst();
  if (time) rt.domain.setCommittedTime(*time);
  rt.analysis->invalidate();
}

void setTimeCmd(Runtime& rt, ArgReader& a) {
  const double t = a.real("time");
  a.finish();
  rt.domain.setCommittedTime(t);
  rt.analysis->invalidate();
}

// getTime ?format?: OpenSees returns the time formatted with "%f" (6 decimals), so loops such as
// `while {[getTime] < $tEnd}` stop where their author expects despite round-off in the sum of
// steps.
void getTimeCmd(Runtime& rt, ArgReader& a) {
  const std::string format = a.hasMore() ? a.word("format") : "%f";
  a.finish();
  Tcl_Obj* time = Tcl_NewDoubleObj(rt.domain.committedTime());
  Tcl_IncrRefCount(time);
  // Tcl's own formatter (the `format` command's), so a format the script could pass to `format`
  // gives the same text, and a bad one is reported as such.
  Tcl_Obj* text = Tcl_Format(rt.interp, format.c_str(), 1, &time);
  Tcl_DecrRefCount(time);
  if (text == nullptr) a.failArgument("format", std::string(Tcl_GetStringResult(rt.interp)));
  Tcl_SetObjResult(rt.interp, text);
}

// getLoadFactor patternTag: the pattern's factor at the current time. For a UniformExcitation
// pattern that is the ground acceleration (series times -fact), the value the analysis multiplies
// by -M r; an energy balance needs it for the input work.
void getLoadFactorCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("patternTag");
  a.finish();
  const domain::LoadPattern* p = rt.domain.findPattern(tag);
  if (p == nullptr)
    a.fail(1, "patternTag", "load pattern " + std::to_string(tag) + " does not exist");
  if (!p->hasFactor())
    a.fail(1, "patternTag",
           "pattern " + std::to_string(tag) +
               " is MultipleSupport, whose ground motions have no single factor");
  setResult(rt, p->factor(rt.domain.time()));
}

void removeCmd(Runtime& rt, ArgReader& a) {
  const std::string what = a.word("what");
  if (what == "recorders") {
    a.finish();
    rt.domain.removeAllRecorders();
    return;
  }
  if (what == "recorder") {
    const int tag = a.integer("tag");
    a.finish();
    rt.domain.removeRecorder(tag);
    return;
  }
  if (what == "element" || what == "ele") {
    const int tag = a.integer("tag");
    a.finish();
    rt.domain.removeElement(tag);
  } else if (what == "node") {
    const int tag = a.integer("tag");
    a.finish();
    rt.domain.removeNode(tag);
  } else if (what == "loadPattern" || what == "pattern") {
    const int tag = a.integer("tag");
    a.finish();
    rt.domain.removePattern(tag);
    if (rt.currentPattern == tag) rt.currentPattern = -1;
  } else if (what == "timeSeries") {
    const int tag = a.integer("tag");
    a.finish();
    if (rt.builder.timeSeries.erase(tag) == 0)
      a.fail(2, "tag", "timeSeries " + std::to_string(tag) + " does not exist");
    return;
  } else if (what == "sp" || what == "fix") {
    const int node = a.integer("node");
    const int dof = a.integer("dof");
    a.finish();
    if (dof < 1) a.fail(3, "dof", "expected a dof from 1, got " + std::to_string(dof));
    if (rt.domain.removeFix(node, dof - 1) == 0)
      a.fail("node " + std::to_string(node) + " dof " + std::to_string(dof) + " is not fixed");
  } else {
    a.fail(1, "what",
           "expected element, node, loadPattern, timeSeries, sp, recorder or recorders, got \"" +
               what + "\"");
  }
  rt.analysis->invalidate();
}

void rayleighCmd(Runtime& rt, ArgReader& a) {
  const double aM = a.real("alphaM"), bK = a.real("betaK"), bK0 = a.real("betaKinit"),
               bKc = a.real("betaKcomm");
  a.finish();
  // Negative factors give negative damping, which feeds energy into the model.
  const char* names[4] = {"alphaM", "betaK", "betaKinit", "betaKcomm"};
  const double values[4] = {aM, bK, bK0, bKc};
  for (std::size_t k = 0; k < 4; ++k)
    if (values[k] < 0.0)
      a.fail(k + 1, names[k], "must not be negative, got " + std::to_string(values[k]));
  rt.domain.setRayleigh(domain::RayleighFactors{aM, bK, bK0, bKc});
}

void modalDampingCmd(Runtime& rt, ArgReader& a) {
  std::vector<double> zeta = a.reals("zeta");
  a.finish();
  const std::size_t modes = rt.domain.eigenvalues.size();
  if (modes == 0) a.fail("needs an `eigen n` analysis first");
  if (zeta.size() != 1 && zeta.size() != modes)
    a.fail("give one ratio or one per computed mode (" + std::to_string(modes) + ")");
  for (double z : zeta)
    if (z < 0.0) a.fail("damping ratios must not be negative");
  rt.domain.modalDamping = zeta;
  rt.domain.touch();
}

constexpr CommandEntry kCommands[] = {
    {"timeSeries", "timeSeries Constant|Linear|Trig|Rectangular|Path tag args...", timeSeriesCmd},
    {"pattern", "pattern Plain|UniformExcitation|MultipleSupport|MultiSupport tag args...",
     patternCmd},
    {"load", "load node v1 .. vndf ?-pattern tag?", loadCmd},
    {"sp", "sp node dof value ?-const? ?-pattern tag?", spCmd},
    {"eleLoad", "eleLoad -ele tags.. | -range first last -type -beamUniform|-beamPoint values..",
     eleLoadCmd},
    {"groundMotion", "groundMotion tag Plain ?-accel ts? ?-vel ts? ?-disp ts? ?-fact f?",
     groundMotionCmd},
    {"imposedMotion", "imposedMotion node dof gmTag", imposedMotionCmd},
    {"imposedSupportMotion", "imposedSupportMotion node dof gmTag", imposedMotionCmd},
    {"loadConst", "loadConst ?-time t?", loadConstCmd},
    {"setTime", "setTime t", setTimeCmd},
    {"getTime", "getTime ?format?", getTimeCmd},
    {"getLoadFactor", "getLoadFactor patternTag", getLoadFactorCmd},
    {"remove", "remove element|node|loadPattern|timeSeries|sp|recorder|recorders ?tag? ?dof?",
     removeCmd},
    {"rayleigh", "rayleigh alphaM betaK betaKinit betaKcomm", rayleighCmd},
    {"modalDamping", "modalDamping zeta ?zeta2 ...?", modalDampingCmd},
};

}  // namespace

std::span<const CommandEntry> loadCommands() { return kCommands; }

}  // namespace dabs::tcl
