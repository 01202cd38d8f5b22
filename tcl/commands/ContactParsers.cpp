// SPDX-License-Identifier: MIT
// Girder pounding: `uniaxialMaterial Restrainer|Bumper`, `element nodeToSurface` and the
// `pounding` command that creates the contact pairs between two girder ends both ways.

#include <tcl.h>

#include <array>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contact/NodeToSurfaceContact3d.h"
#include "materials/GapSpring.h"
#include "materials/InputError.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

using contact::NodeToSurfaceParams;

// --- uniaxialMaterial Restrainer | Bumper tag k gap ?-Fy Fy -b b? -------------------------

materials::GapSpringParams readGapSpring(ArgReader& args) {
  materials::GapSpringParams p;
  p.k = args.real("k");
  p.gap = args.real("gap");
  const auto fy = args.optionalOption("-Fy");
  const auto b = args.optionalOption("-b");
  args.finish();
  if (b && !fy)
    args.failArgument("-b", "needs -Fy (the post-yield ratio of a spring that never yields)");
  if (fy) p.Fy = *fy;
  if (b) p.b = *b;
  p.validate();  // an InputError names k, gap, Fy or b: the command table points at its argument
  return p;
}

std::unique_ptr<materials::UniaxialMaterial> parseRestrainer(Runtime& /*rt*/, ArgReader& args,
                                                             int tag) {
  return std::make_unique<materials::GapSpring>(
      materials::GapSpring::restrainer(tag, readGapSpring(args)));
}

std::unique_ptr<materials::UniaxialMaterial> parseBumper(Runtime& /*rt*/, ArgReader& args,
                                                         int tag) {
  return std::make_unique<materials::GapSpring>(
      materials::GapSpring::bumper(tag, readGapSpring(args)));
}

// --- contact options shared by nodeToSurface and pounding -----------------------------------

/// Reads -K K | -EAL E A L, -law, -n, -v0, -Kt, -e, -et, -mu_s, -mu_k, -masses M1 M2, -search
/// and validates them.
/// When only one friction coefficient is given the other takes its value. A validation error
/// points at the option it is about (the reader recorded where each was read).
NodeToSurfaceParams readContactOptions(ArgReader& args) {
  NodeToSurfaceParams p;
  const auto K = args.optionalOption("-K");
  const auto EAL = args.optionReals("-EAL", 3);
  if (K && EAL) args.fail("give either -K K or -EAL E A L, not both");
  if (!K && !EAL) args.fail("the contact stiffness is missing: give -K K or -EAL E A L");
  if (K) p.K = *K;
  if (EAL) {
    const auto& v = *EAL;
    if (!(v[2] > 0.0)) args.failArgument("-EAL", 2, "the length L must be positive");
    p.K = v[0] * v[1] / v[2];  // axial stiffness of the contactor body (Zhu et al. 2002)
  }
  if (const auto law = args.optionalWordOption("-law")) {
    if (*law == "kelvin")
      p.law = contact::ImpactLaw::Kelvin;
    else if (*law == "hertz")
      p.law = contact::ImpactLaw::Hertz;
    else if (*law == "hertzdamp")
      p.law = contact::ImpactLaw::HertzDamp;
    else if (*law == "jankowski")
      p.law = contact::ImpactLaw::Jankowski;
    else
      args.failArgument("-law",
                        "expected kelvin, hertz, hertzdamp or jankowski, got \"" + *law + "\"");
  }
  const bool power = p.law == contact::ImpactLaw::Hertz || p.law == contact::ImpactLaw::HertzDamp;
  if (const auto n = args.optionalOption("-n")) {
    if (!power) args.failArgument("-n", "is the exponent of -law hertz or hertzdamp only");
    p.n = *n;
  }
  if (const auto v0 = args.optionalOption("-v0")) {
    if (p.law != contact::ImpactLaw::HertzDamp)
      args.failArgument("-v0", "is the approach speed of -law hertzdamp only");
    p.v0 = *v0;
  } else if (p.law == contact::ImpactLaw::HertzDamp) {
    args.fail("-law hertzdamp needs -v0 v0 (the approach speed its damping is tuned to)");
  }
  if (p.law != contact::ImpactLaw::Kelvin && EAL)
    args.failArgument("-EAL", "gives a linear stiffness; -law " +
                                  std::string(contact::NormalLaw::name(p.law)) +
                                  " needs -K in force/length^n");
  p.Kt = args.option("-Kt", 0.0);
  p.e = args.option("-e", 1.0);
  p.et = args.option("-et", 1.0);
  const auto muS = args.optionalOption("-mu_s");
  const auto muK = args.optionalOption("-mu_k");
  p.muS = muS ? *muS : (muK ? *muK : 0.0);
  p.muK = muK ? *muK : p.muS;
  if (const auto m = args.optionReals("-masses", 2)) {
    p.M1 = (*m)[0];
    p.M2 = (*m)[1];
  }
  p.search = args.option("-search", p.search);
  try {
    p.validate();
  } catch (const InputError& e) {
    // Fields that are not one option each: K may come from -EAL, M1 and M2 share -masses.
    if (e.field() == "K" && EAL)
      args.failArgument("-EAL", "gives K = E A / L, which " + e.reason());
    if ((e.field() == "M1" || e.field() == "M2") && args.positionOf("-masses") != 0)
      args.failArgument("-masses", e.field() == "M1" ? 0 : 1, e.what());
    args.failInput(e);
  }
  return p;
}

/// The argument names under which a contactor and its face's four nodes were read, so that an
/// InputError about one of them points at it.
struct ContactFields {
  std::string contactor;
  std::array<std::string, 4> face;
};

/// Builds the element for the nodes' ndf (3 or 6); throws InputError (field from `fields`) when a
/// node is missing or repeated, the five nodes do not share one ndf or the model is not 3D. The
/// element is not yet in the domain.
std::unique_ptr<elements::Element> makeContact(const Runtime& rt, int tag, int contactor,
                                               const std::array<int, 4>& face,
                                               const NodeToSurfaceParams& p,
                                               const ContactFields& fields) {
  const domain::Node* k = rt.domain.findNode(contactor);
  if (k == nullptr)
    throw InputError(fields.contactor, "node " + std::to_string(contactor) + " does not exist");
  if (k->ndm() != 3)
    throw InputError(fields.contactor, "nodeToSurface needs a 3D model (model basic -ndm 3)");
  for (int i = 0; i < 4; ++i) {
    const int n = face[i];
    const std::string& field = fields.face[i];
    if (n == contactor)
      throw InputError(field, "node " + std::to_string(n) + " is also the contactor node");
    for (int j = 0; j < i; ++j)
      if (face[j] == n) throw InputError(field, "node " + std::to_string(n) + " appears twice");
    const domain::Node* t = rt.domain.findNode(n);
    if (t == nullptr) throw InputError(field, "node " + std::to_string(n) + " does not exist");
    if (t->ndf() != k->ndf())
      throw InputError(field, "node " + std::to_string(n) + " has " + std::to_string(t->ndf()) +
                                  " dofs but the contactor " + std::to_string(contactor) + " has " +
                                  std::to_string(k->ndf()) + "; all five must agree");
  }
  if (k->ndf() == 3)
    return std::make_unique<contact::NodeToSurfaceContact3d<3>>(tag, contactor, face, p);
  if (k->ndf() == 6)
    return std::make_unique<contact::NodeToSurfaceContact3d<6>>(tag, contactor, face, p);
  throw InputError(fields.contactor, "nodeToSurface works in -ndf 3 and -ndf 6 models, node " +
                                         std::to_string(contactor) + " has " +
                                         std::to_string(k->ndf()));
}

// --- element nodeToSurface tag cNode a b c d -K K ... ---------------------------------------

std::unique_ptr<elements::Element> parseNodeToSurface(Runtime& rt, ArgReader& args, int tag) {
  const ContactFields fields{"cNode", {"a", "b", "c", "d"}};
  const int contactor = args.integer(fields.contactor);
  std::array<int, 4> face{};
  for (int i = 0; i < 4; ++i) face[i] = args.integer(fields.face[i]);
  const NodeToSurfaceParams p = readContactOptions(args);
  args.finish();
  return makeContact(rt, tag, contactor, face, p, fields);
}

// --- pounding tag -side1 {nodes} {a b c d} -side2 {nodes} {a b c d} <options> ---------------

/// The node tags of the list argument read under `name` (`exactly` of them when nonzero).
std::vector<int> readTagList(const ArgReader& args, const std::string& text,
                             const std::string& name, std::size_t exactly) {
  int count = 0;
  const char** items = nullptr;
  if (Tcl_SplitList(nullptr, text.c_str(), &count, &items) != TCL_OK)
    args.failArgument(name, "is not a Tcl list");
  std::vector<int> tags;
  bool good = true;
  for (int i = 0; i < count && good; ++i) {
    int value = 0;
    good = Tcl_GetInt(nullptr, items[i], &value) == TCL_OK;
    tags.push_back(value);
  }
  Tcl_Free(reinterpret_cast<char*>(items));
  if (!good) args.failArgument(name, "must list node tags");
  if (tags.empty()) args.failArgument(name, "must list at least one node");
  if (exactly != 0 && tags.size() != exactly)
    args.failArgument(name, "must list exactly " + std::to_string(exactly) + " nodes (a b c d)");
  return tags;
}

/// Creates, for girder ends 1 and 2, one nodeToSurface element per side-1 contactor against the
/// side-2 face and per side-2 contactor against the side-1 face, all with the same options.
/// Numbering: tags tag, tag+1, ..., tag+n-1, side-1 contactors first (in list order), then
/// side-2 contactors; an error when any of them is taken. All-or-nothing: every element is built
/// first, and if adding one fails those already added are removed before the error is raised.
/// The result is the list of element tags.
void pounding(Runtime& rt, ArgReader& args) {
  rt.requireModel("pounding");
  const int tag = args.integer("tag");
  args.setContext(args.context() + " " + std::to_string(tag));
  const NodeToSurfaceParams p = readContactOptions(args);
  std::optional<std::vector<int>> contactors[2];
  std::array<int, 4> faces[2]{};
  while (args.hasMore()) {
    const std::string key(args.peek());
    const int side = key == "-side1" ? 0 : key == "-side2" ? 1 : -1;
    if (side < 0) args.fail("unexpected argument \"" + key + "\" (expected -side1 or -side2)");
    if (contactors[side]) args.fail(key + " given twice");
    const std::string nodes = *args.optionalWordOption(key);
    contactors[side] = readTagList(args, nodes, key, 0);
    const std::string faceName = side == 0 ? "face1" : "face2";
    const auto f = readTagList(args, args.word(faceName), faceName, 4);
    std::copy(f.begin(), f.end(), faces[side].begin());
  }
  if (!contactors[0] || !contactors[1]) args.fail("both -side1 and -side2 are required");
  args.finish();

  // Pairs: side-1 nodes against face 2, then side-2 nodes against face 1.
  std::vector<std::pair<int, int>> pairs;  // (contactor, face index)
  for (int n : *contactors[0]) pairs.emplace_back(n, 1);
  for (int n : *contactors[1]) pairs.emplace_back(n, 0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const int t = tag + static_cast<int>(i);
    if (rt.domain.findElement(t) != nullptr)
      args.failArgument("tag", "numbers the " + std::to_string(pairs.size()) + " elements " +
                                   std::to_string(tag) + " to " +
                                   std::to_string(tag + static_cast<int>(pairs.size()) - 1) +
                                   ", but element " + std::to_string(t) + " already exists");
  }
  // A node of side s is named by the list it stands in: its contactors or its face.
  const ContactFields fields[2] = {{"-side1", {"face2", "face2", "face2", "face2"}},
                                   {"-side2", {"face1", "face1", "face1", "face1"}}};
  std::vector<std::unique_ptr<elements::Element>> built;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const int face = pairs[i].second;
    built.push_back(makeContact(rt, tag + static_cast<int>(i), pairs[i].first, faces[face], p,
                                fields[1 - face]));
  }
  std::vector<int> added;
  try {
    for (auto& e : built) {
      const int t = e->tag();
      rt.domain.addElement(std::move(e));
      added.push_back(t);
    }
  } catch (const InputError& e) {
    for (int t : added) rt.domain.removeElement(t);
    const std::size_t i = added.size();
    throw InputError(e.field(), "(element " + std::to_string(tag + static_cast<int>(i)) +
                                    ", contactor " + std::to_string(pairs[i].first) +
                                    " against the side-" + std::to_string(pairs[i].second + 1) +
                                    " face; nothing was created) " + e.reason());
  } catch (...) {
    for (int t : added) rt.domain.removeElement(t);
    throw;
  }
  Tcl_Obj* result = Tcl_NewListObj(0, nullptr);
  for (int t : added) Tcl_ListObjAppendElement(rt.interp, result, Tcl_NewIntObj(t));
  Tcl_SetObjResult(rt.interp, result);
}

// --- contactStepping ?-maxStep h? ?-lookAhead n? ?-overshoot f? ?-perContact n? ?-eachStep script?

/// Turns event-located contact stepping of transient analyses on (with the options given; the
/// defaults are those of ContactSteppingParams) or off (-off). Without arguments it returns
/// its state as a dict: on, maxStep, lookAhead, overshoot, pairs (when on), and since the last
/// wipeAnalysis contactSteps, patternChanges (matrix patterns rebuilt as far contact pairs
/// went to sleep or woke, AnalysisModel's sleeping pairs) and redoneSteps (steps redone because a
/// sleeping pair would have carried force) and farTests (far tests of sleeping pairs made: one
/// per pair and check, none while its face's test is deferred, two at a check that wakes a pair of
/// a deferred face). The -eachStep script runs at global level after every committed step while
/// stepping is on (a script that follows peaks between analyze's output steps); an error in it
/// stops the analysis with that error. Set after `wipeAnalysis`, which turns stepping off.
void contactSteppingCmd(Runtime& rt, ArgReader& args) {
  auto& analysis = *rt.analysis;
  if (!args.hasMore()) {
    const analysis::ContactStepping* cs = analysis.contactStepping();
    std::string text = "on " + std::string(cs ? "1" : "0");
    if (cs) {
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    " maxStep %.17g lookAhead %.17g overshoot %.17g perContact %d pairs %zu",
                    cs->params().maxStep, cs->params().lookAhead, cs->params().overshoot,
                    cs->params().perContact, cs->pairs());
      text += buf;
    }
    text += " contactSteps " + std::to_string(analysis.statistics().contactSteps) +
            " patternChanges " + std::to_string(analysis.statistics().patternChanges) +
            " redoneSteps " + std::to_string(analysis.statistics().redoneSteps) + " farTests " +
            std::to_string(analysis.statistics().farTests);
    setResult(rt, text);
    return;
  }
  if (args.flag("-off")) {
    args.finish();
    analysis.setContactStepping(std::nullopt);
    analysis.afterStep = nullptr;
    return;
  }
  analysis::ContactSteppingParams p;
  p.maxStep = args.option("-maxStep", p.maxStep);
  p.lookAhead = args.option("-lookAhead", p.lookAhead);
  p.overshoot = args.option("-overshoot", p.overshoot);
  p.perContact = args.option("-perContact", p.perContact);
  const auto each = args.optionalWordOption("-eachStep");
  args.finish();
  p.validate();  // an InputError names maxStep, lookAhead or overshoot: located by the table
  analysis.setContactStepping(p);
  analysis.afterStep = nullptr;
  if (each && !each->empty()) {
    // The script object lives as long as the hook (shared by its copies).
    std::shared_ptr<Tcl_Obj> script(Tcl_NewStringObj(each->c_str(), static_cast<int>(each->size())),
                                    [](Tcl_Obj* o) { Tcl_DecrRefCount(o); });
    Tcl_IncrRefCount(script.get());
    Tcl_Interp* interp = rt.interp;
    analysis.afterStep = [interp, script]() -> int {
      if (Tcl_EvalObjEx(interp, script.get(), TCL_EVAL_GLOBAL) != TCL_OK)
        throw InputError("contactStepping -eachStep", Tcl_GetStringResult(interp));
      Tcl_ResetResult(interp);
      return 0;
    };
  }
}

constexpr const char* kContactOptions =
    "-K K | -EAL E A L ?-law kelvin|hertz|hertzdamp|jankowski? ?-n n? ?-v0 v0? ?-Kt Kt? ?-e e? "
    "?-et et? ?-mu_s mus? ?-mu_k muk? ?-masses M1 M2? ?-search dist?";

const std::string kNodeToSurfaceUsage =
    std::string("element nodeToSurface tag cNode a b c d ") + kContactOptions;
const std::string kPoundingUsage =
    std::string(
        "pounding tag -side1 {contactor nodes} {a b c d} -side2 {contactor nodes} "
        "{a b c d} ") +
    kContactOptions;

}  // namespace

std::span<const CommandEntry> contactCommands() {
  static const CommandEntry kRows[] = {
      {"pounding", kPoundingUsage, pounding},
      {"contactStepping",
       "contactStepping ?-maxStep h? ?-lookAhead n? ?-overshoot f? ?-perContact n? ?-eachStep "
       "script? | -off",
       contactSteppingCmd},
  };
  return kRows;
}

std::span<const UniaxialEntry> contactUniaxialParsers() {
  static constexpr UniaxialEntry kRows[] = {
      {"Restrainer", "uniaxialMaterial Restrainer tag k gap ?-Fy Fy -b b?", parseRestrainer},
      {"Bumper", "uniaxialMaterial Bumper tag k gap ?-Fy Fy -b b?", parseBumper},
  };
  return kRows;
}

std::span<const ElementEntry> contactElementParsers() {
  static const ElementEntry kRows[] = {{"nodeToSurface", kNodeToSurfaceUsage, parseNodeToSurface}};
  return kRows;
}

}  // namespace dabs::tcl
