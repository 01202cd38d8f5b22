// SPDX-License-Identifier: MIT
// Tcl parsers for beam-columns and what they are built from: `geomTransf`, `element
// elasticBeamColumn`. Syntax follows OpenSees (OpenSees/OpenSees:SRC/coordTransformation/
// TclGeomTransfCommand.cpp, SRC/element/elasticBeamColumn/TclElasticBeamCommand.cpp).
#include <array>
#include <cmath>
#include <string>

#include "elements/beam/DispBeamColumn.h"
#include "elements/beam/ElasticBeam2d.h"
#include "elements/beam/ForceBeamColumn.h"
#include "elements/beam/QuadratureIntegration.h"
#include "elements/beam/ElasticBeam3d.h"
#include "elements/beam/ZeroLengthSection.h"
#include "elements/transform/CorotationalTransf2d.h"
#include "elements/transform/CorotationalTransf3d.h"
#include "elements/transform/LinearTransf2d.h"
#include "elements/transform/LinearTransf3d.h"
#include "elements/transform/PDeltaTransf2d.h"
#include "elements/transform/PDeltaTransf3d.h"
#include "materials/InputError.h"
#include "materials/section/ElasticSection.h"
#include "materials/section/FiberSection.h"
#include "materials/section/SectionAggregator.h"
#include "materials/section/geometry/CircPatch.h"
#include "materials/section/geometry/QuadPatch.h"
#include "materials/section/geometry/StraightLayer.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

/// Fibers collected while a `section Fiber` body runs.
struct FiberSectionUnderConstruction {
  int ndm = 2;
  materials::section::FiberList fibers;
};

namespace {

using elements::CrdTransf;
using elements::CrdTransf2d;
using elements::CrdTransf3d;
using materials::section::FiberList;

/// Sets rt.currentFiberSection for the lifetime of the guard (cleared on every exit path).
class FiberSectionGuard {
 public:
  FiberSectionGuard(Runtime& rt, FiberSectionUnderConstruction* s) : rt_(rt) {
    rt_.currentFiberSection = s;
  }
  ~FiberSectionGuard() { rt_.currentFiberSection = nullptr; }
  FiberSectionGuard(const FiberSectionGuard&) = delete;
  FiberSectionGuard& operator=(const FiberSectionGuard&) = delete;

 private:
  Runtime& rt_;
};

FiberSectionUnderConstruction& currentSection(Runtime& rt, ArgReader& args) {
  if (rt.currentFiberSection == nullptr) args.fail("is only valid inside a section Fiber body");
  return *rt.currentFiberSection;
}

int existingMaterial(Runtime& rt, ArgReader& args) {
  const int tag = args.integer("matTag");
  (void)rt.builder.uniaxialMaterial(tag);  // throws InputError when absent
  return tag;
}

// fiber y z A matTag   (in 2D OpenSees also writes `fiber y z A matTag`; z is ignored)
void fiberCommand(Runtime& rt, ArgReader& args) {
  args.setContext("fiber");
  FiberSectionUnderConstruction& s = currentSection(rt, args);
  const double y = args.real("y"), z = args.real("z"), a = args.real("A");
  const int mat = existingMaterial(rt, args);
  args.finish();
  if (!(a > 0.0)) throw InputError("A", "must be positive");
  s.fibers.push_back({y, z, a, mat});
}

// patch rect matTag nY nZ yI zI yJ zJ | quad matTag nIJ nJK yI zI yJ zJ yK zK yL zL |
// circ matTag nCirc nRad yC zC rInt rExt ?startAng endAng?
// A bridge pier section has hundreds of fibers, a very fine one some tens of thousands; a count
// beyond this limit is a typing error that would take the memory of the machine.
constexpr long long kMaxSectionFibers = 1000000;

// Checks that adding `count` fibers (a product of subdivision counts) keeps the section in limits.
void checkFiberCount(const FiberSectionUnderConstruction& s, ArgReader& args, long long count) {
  if (count > kMaxSectionFibers - static_cast<long long>(s.fibers.size()))
    args.fail("would give the section " + std::to_string(count + static_cast<long long>(s.fibers.size())) +
              " fibers; at most " + std::to_string(kMaxSectionFibers) + " are allowed");
}

void patchCommand(Runtime& rt, ArgReader& args) {
  FiberSectionUnderConstruction& s = currentSection(rt, args);
  const std::string type = args.word("type");
  args.setContext("patch " + type);
  FiberList out;
  if (type == "rect" || type == "quad" || type == "quadr") {
    const int mat = existingMaterial(rt, args);
    const int n1 = args.integer(type == "rect" ? "numSubdivY" : "numSubdivIJ");
    const int n2 = args.integer(type == "rect" ? "numSubdivZ" : "numSubdivJK");
    const std::vector<double> c = args.reals("coordinates", type == "rect" ? 4 : 8, true);
    args.finish();
    materials::section::QuadPatch q;
    if (type == "rect") {
      q = materials::section::QuadPatch::rect(mat, n1, n2, c[0], c[1], c[2], c[3]);
    } else {
      q.materialTag = mat;
      q.divIJ = n1;
      q.divJK = n2;
      for (int k = 0; k < 4; ++k) {
        q.y[k] = c[2 * k];
        q.z[k] = c[2 * k + 1];
      }
    }
    q.validate();
    checkFiberCount(s, args, static_cast<long long>(q.divIJ) * q.divJK);
    q.discretize(out);
  } else if (type == "circ") {
    materials::section::CircPatch c;
    c.materialTag = existingMaterial(rt, args);
    c.divCirc = args.integer("numSubdivCirc");
    c.divRad = args.integer("numSubdivRad");
    c.yCenter = args.real("yCenter");
    c.zCenter = args.real("zCenter");
    c.rInt = args.real("intRad");
    c.rExt = args.real("extRad");
    if (auto a = args.optionalReal("startAng")) {
      c.startAngle = *a;
      c.endAngle = args.real("endAng");
    }
    args.finish();
    c.validate();
    checkFiberCount(s, args, static_cast<long long>(c.divCirc) * c.divRad);
    c.discretize(out);
  } else {
    args.fail(args.lastPosition(), "type", "unknown patch \"" + type + "\" (rect, quad, circ)");
  }
  s.fibers.insert(s.fibers.end(), out.begin(), out.end());
}

// layer straight matTag numBars areaBar yStart zStart yEnd zEnd |
// layer circ matTag numBars areaBar yC zC radius ?startAng endAng?
void layerCommand(Runtime& rt, ArgReader& args) {
  FiberSectionUnderConstruction& s = currentSection(rt, args);
  const std::string type = args.word("type");
  args.setContext("layer " + type);
  FiberList out;
  if (type == "straight") {
    materials::section::StraightLayer l;
    l.materialTag = existingMaterial(rt, args);
    l.numBars = args.integer("numBars");
    l.barArea = args.real("areaBar");
    const std::vector<double> c = args.reals("coordinates", 4, true);
    args.finish();
    l.yStart = c[0];
    l.zStart = c[1];
    l.yEnd = c[2];
    l.zEnd = c[3];
    l.validate();
    checkFiberCount(s, args, l.numBars);
    l.discretize(out);
  } else if (type == "circ") {
    materials::section::CircLayer l;
    l.materialTag = existingMaterial(rt, args);
    l.numBars = args.integer("numBars");
    l.barArea = args.real("areaBar");
    l.yCenter = args.real("yCenter");
    l.zCenter = args.real("zCenter");
    l.radius = args.real("radius");
    if (auto a = args.optionalReal("startAng")) {
      l.startAngle = *a;
      l.endAngle = args.real("endAng");
    }
    args.finish();
    l.validate();
    checkFiberCount(s, args, l.numBars);
    l.discretize(out);
  } else {
    args.fail(args.lastPosition(), "type", "unknown layer \"" + type + "\" (straight, circ)");
  }
  s.fibers.insert(s.fibers.end(), out.begin(), out.end());
}

template <class S>
std::unique_ptr<S> buildFiberSection(const Runtime& rt, int tag,
                                     const FiberSectionUnderConstruction& under, double gj) {
  std::vector<typename S::Fiber> fibers;
  for (const auto& f : under.fibers)
    fibers.push_back({f.y, f.z, f.area, &rt.builder.uniaxialMaterial(f.materialTag)});
  return std::make_unique<S>(tag, fibers, gj);
}

constexpr const char* kElasticSectionUsage2d = "section Elastic tag E A Iz ?G alphaY?";
constexpr const char* kElasticSectionUsage3d =
    "section Elastic tag E A Iz Iy G J ?alphaY alphaZ?";
constexpr const char* kAggregatorUsage =
    "section Aggregator tag matTag1 code1 ?matTag2 code2 ...? ?-section secTag? (codes P Mz Vy My "
    "Vz T)";

// section Elastic tag E A Iz ?G alphaY? (2D) | tag E A Iz Iy G J ?alphaY alphaZ? (3D)
std::unique_ptr<materials::section::SectionForceDeformation> parseElasticSection(Runtime& rt,
                                                                                 ArgReader& args,
                                                                                 int tag) {
  materials::section::ElasticSectionParams p;
  p.ndm = rt.builder.ndm;
  p.modulus = args.real("E");
  p.area = args.real("A");
  p.inertiaZ = args.real("Iz");
  if (p.ndm == 3) {
    p.inertiaY = args.real("Iy");
    p.shearModulus = args.real("G");
    p.torsion = args.real("J");
    if (auto a = args.optionalReal("alphaY")) {
      p.alphaY = *a;
      p.alphaZ = args.real("alphaZ");
    }
  } else if (auto g = args.optionalReal("G")) {
    p.shearModulus = *g;
    p.alphaY = args.real("alphaY");
    if (!(p.alphaY > 0.0)) throw InputError("alphaY", "must be positive");
  }
  args.finish();
  p.validate();
  return std::make_unique<materials::section::ElasticSection>(tag, p);
}

materials::section::SectionCode sectionCode(ArgReader& args) {
  using materials::section::SectionCode;
  const std::string c = args.word("code");
  if (c == "P") return SectionCode::P;
  if (c == "Mz") return SectionCode::Mz;
  if (c == "Vy") return SectionCode::Vy;
  if (c == "My") return SectionCode::My;
  if (c == "Vz") return SectionCode::Vz;
  if (c == "T") return SectionCode::T;
  args.fail(args.lastPosition(), "code", "unknown resultant \"" + c + "\" (P, Mz, Vy, My, Vz, T)");
}

// section Aggregator tag matTag1 code1 ... ?-section secTag?
std::unique_ptr<materials::section::SectionForceDeformation> parseAggregator(Runtime& rt,
                                                                             ArgReader& args,
                                                                             int tag) {
  const std::optional<std::string> base = args.optionalWordOption("-section");
  std::vector<materials::section::SectionAggregator::Part> parts;
  while (args.hasPositional()) {
    const int mat = args.integer("matTag");
    const materials::section::SectionCode code = sectionCode(args);
    if (rt.builder.ndm == 2 && (code == materials::section::SectionCode::My ||
                                code == materials::section::SectionCode::Vz ||
                                code == materials::section::SectionCode::T))
      args.fail(args.lastPosition(), "code", "My, Vz and T are not available in a 2D model");
    parts.push_back({&rt.builder.uniaxialMaterial(mat), code});
  }
  args.finish();
  const materials::section::SectionForceDeformation* baseSection = nullptr;
  if (base) {
    int secTag = 0;
    try {
      std::size_t used = 0;
      secTag = std::stoi(*base, &used);
      if (used != base->size()) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
      throw InputError("-section", "expected a section tag, got \"" + *base + "\"");
    }
    baseSection = &rt.builder.section(secTag);
  }
  if (parts.empty() && baseSection == nullptr)
    args.fail("needs at least one matTag code pair or -section secTag");
  return std::make_unique<materials::section::SectionAggregator>(tag, parts, baseSection);
}

// section Fiber tag ?-GJ GJ? {body} | Elastic ... | Aggregator ...
void sectionCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("section");
  const int ndm = rt.builder.ndm;
  const std::string type = args.word("type");
  if (type == "Uniaxial") {
    // section Uniaxial tag matTag code: one resultant carried by one material (OpenSees'
    // SectionAggregator with a single material, as its own Uniaxial section).
    args.setContext("section Uniaxial");
    args.setUsage("section Uniaxial tag matTag code (code P, Mz, Vy, My, Vz or T)");
    const int tag = readNewTag(args, rt.builder.sections, "section");
    const int mat = args.integer("matTag");
    const materials::section::SectionCode code = sectionCode(args);
    args.finish();
    if (ndm == 2 && (code == materials::section::SectionCode::My ||
                     code == materials::section::SectionCode::Vz ||
                     code == materials::section::SectionCode::T))
      args.fail(args.lastPosition(), "code", "My, Vz and T are not available in a 2D model");
    rt.builder.sections[tag] = std::make_unique<materials::section::SectionAggregator>(
        tag, std::vector<materials::section::SectionAggregator::Part>{{&rt.builder.uniaxialMaterial(mat), code}},
        nullptr);
    Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
    return;
  }
  if (type == "Elastic" || type == "Aggregator") {
    args.setContext("section " + type);
    args.setUsage(type == "Aggregator" ? kAggregatorUsage
                  : ndm == 3           ? kElasticSectionUsage3d
                                       : kElasticSectionUsage2d);
    const int tag = readNewTag(args, rt.builder.sections, "section");
    auto section =
        type == "Elastic" ? parseElasticSection(rt, args, tag) : parseAggregator(rt, args, tag);
    rt.builder.sections[tag] = std::move(section);
    Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
    return;
  }
  if (type != "Fiber" && type != "fiberSec")
    args.fail(args.lastPosition(), "type",
              "unknown section \"" + type + "\" (available: Fiber, Elastic, Aggregator, Uniaxial)");
  args.setContext("section " + type);
  args.setUsage("section Fiber tag ?-GJ GJ? { fiber ...; patch ...; layer ... }");
  const int tag = readNewTag(args, rt.builder.sections, "section");
  if (rt.currentFiberSection != nullptr) args.fail("section Fiber bodies cannot be nested");
  const std::optional<double> gj = args.optionalOption("-GJ");
  Tcl_Obj* body = args.object("body");
  args.finish();
  if (ndm == 3 && !gj) args.fail("a 3D fiber section needs -GJ GJ (torsional stiffness)");
  FiberSectionUnderConstruction under{ndm, {}};
  int code = TCL_OK;
  {
    FiberSectionGuard guard(rt, &under);
    Tcl_IncrRefCount(body);
    code = Tcl_EvalObjEx(rt.interp, body, 0);
    Tcl_DecrRefCount(body);
  }
  if (code != TCL_OK)
    throw ArgError(args.context() + ": error in the section body: " +
                   Tcl_GetStringResult(rt.interp));
  std::unique_ptr<materials::section::SectionForceDeformation> section;
  if (ndm == 2)
    section = buildFiberSection<materials::section::FiberSection2d>(rt, tag, under, 0.0);
  else
    section = buildFiberSection<materials::section::FiberSection3d>(rt, tag, under, *gj);
  rt.builder.sections[tag] = std::move(section);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

// beamIntegration Lobatto|Legendre|Radau|NewtonCotes tag secTag N |
// beamIntegration HingeRadau tag secI lpI secJ lpJ secE
void beamIntegrationCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("beamIntegration");
  const std::string type = args.word("type");
  args.setContext("beamIntegration " + type);
  using Rule = elements::QuadratureIntegration::Rule;
  std::unique_ptr<elements::BeamIntegration> rule;
  if (type == "HingeRadau") {
    args.setUsage("beamIntegration HingeRadau tag secI lpI secJ lpJ secE");
    const int tag = readNewTag(args, rt.builder.integrations, "beamIntegration");
    const int secI = args.integer("secI");
    const double lpI = args.real("lpI");
    const int secJ = args.integer("secJ");
    const double lpJ = args.real("lpJ");
    const int secE = args.integer("secE");
    args.finish();
    for (int s : {secI, secJ, secE}) (void)rt.builder.section(s);
    rule = std::make_unique<elements::HingeRadauIntegration>(tag, secI, lpI, secJ, lpJ, secE);
  } else {
    Rule r;
    if (type == "Lobatto") r = Rule::Lobatto;
    else if (type == "Legendre") r = Rule::Legendre;
    else if (type == "Radau") r = Rule::Radau;
    else if (type == "NewtonCotes") r = Rule::NewtonCotes;
    else
      args.fail(args.lastPosition(), "type",
                "unknown rule \"" + type + "\" (Lobatto, Legendre, Radau, NewtonCotes, HingeRadau)");
    args.setUsage("beamIntegration " + type + " tag secTag N");
    const int tag = readNewTag(args, rt.builder.integrations, "beamIntegration");
    const int sec = args.integer("secTag");
    const int n = args.integer("N");
    args.finish();
    (void)rt.builder.section(sec);
    rule = std::make_unique<elements::QuadratureIntegration>(tag, r, sec, n);
  }
  const int tag = rule->tag();
  rt.builder.integrations[tag] = std::move(rule);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

constexpr const char* kGeomTransfUsage2d = "geomTransf Linear|PDelta|Corotational tag";
constexpr const char* kGeomTransfUsage3d =
    "geomTransf Linear|PDelta|Corotational tag vecxzX vecxzY vecxzZ";

// geomTransf Linear|PDelta|Corotational tag ?vecxz(3D)?
void geomTransfCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("geomTransf");
  const int ndm = rt.builder.ndm;
  args.setUsage(ndm == 2 ? kGeomTransfUsage2d : kGeomTransfUsage3d);
  const std::string type = args.word("type");
  if (type != "Linear" && type != "PDelta" && type != "Corotational")
    args.fail(args.lastPosition(), "type", "unknown transformation \"" + type +
                                               "\" (expected Linear, PDelta or Corotational)");
  args.setContext("geomTransf " + type);
  const int tag = readNewTag(args, rt.builder.transforms, "geomTransf");
  if (ndm != 2 && ndm != 3) args.fail("needs a 2D or 3D model (model basic -ndm 2|3)");

  std::unique_ptr<CrdTransf> transf;
  if (ndm == 2) {
    if (args.optionRealList("-jntOffset")) args.fail("-jntOffset (joint offsets) is not supported");
    args.finish();
    if (type == "Linear")
      transf = std::make_unique<elements::LinearTransf2d>(tag);
    else if (type == "PDelta")
      transf = std::make_unique<elements::PDeltaTransf2d>(tag);
    else
      transf = std::make_unique<elements::CorotationalTransf2d>(tag);
  } else {
    const std::vector<double> v = args.reals("vecxz", 3, true);
    const Eigen::Vector3d vecxz(v[0], v[1], v[2]);
    if (args.optionRealList("-jntOffset")) args.fail("-jntOffset (joint offsets) is not supported");
    args.finish();
    if (!(vecxz.norm() > 0.0)) throw InputError("vecxz", "must be a nonzero vector");
    if (type == "Linear")
      transf = std::make_unique<elements::LinearTransf3d>(tag, vecxz);
    else if (type == "PDelta")
      transf = std::make_unique<elements::PDeltaTransf3d>(tag, vecxz);
    else
      transf = std::make_unique<elements::CorotationalTransf3d>(tag, vecxz);
  }
  rt.builder.transforms[tag] = std::move(transf);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

/// Clone of transformation `tag` with the element's dimension; throws InputError otherwise.
template <class T>
std::unique_ptr<T> transformFor(const Runtime& rt, int tag) {
  const CrdTransf& proto = rt.builder.transform(tag);
  std::unique_ptr<CrdTransf> copy = proto.clone();
  if (auto* typed = dynamic_cast<T*>(copy.get())) {
    copy.release();
    return std::unique_ptr<T>(typed);
  }
  throw InputError("transfTag", "geomTransf " + std::to_string(tag) + " was defined for a " +
                                    std::to_string(proto.dimension()) + "D model");
}

constexpr const char* kElasticUsage2d =
    "element elasticBeamColumn tag iNode jNode A E Iz transfTag ?-mass m? ?-cMass|-lMass?";
constexpr const char* kElasticUsage3d =
    "element elasticBeamColumn tag iNode jNode A E G J Iy Iz transfTag ?-mass m? ?-cMass|-lMass?";

// element elasticBeamColumn tag i j A E Iz transfTag ?-mass m? ?-cMass?          (2D)
// element elasticBeamColumn tag i j A E G J Iy Iz transfTag ?-mass m? ?-cMass?   (3D)
std::unique_ptr<elements::Element> parseElasticBeam(Runtime& rt, ArgReader& args, int tag) {
  const int ndm = rt.builder.ndm;
  args.setUsage(ndm == 3 ? kElasticUsage3d : kElasticUsage2d);
  const int iNode = args.integer("iNode");
  const int jNode = args.integer("jNode");
  if (ndm == 3) {
    elements::ElasticBeam3d::Params p;
    p.area = args.real("A");
    p.modulus = args.real("E");
    p.shearModulus = args.real("G");
    p.torsion = args.real("J");
    p.inertiaY = args.real("Iy");
    p.inertiaZ = args.real("Iz");
    const int transfTag = args.integer("transfTag");
    p.massPerLength = args.option("-mass", 0.0);
    p.consistentMass = args.flag("-cMass");
  if (args.flag("-lMass")) p.consistentMass = false;  // lumped, the default
    args.finish();
    p.validate();
    return std::make_unique<elements::ElasticBeam3d>(tag, iNode, jNode, p,
                                                     transformFor<CrdTransf3d>(rt, transfTag));
  }
  if (ndm != 2) args.fail("needs a 2D or 3D model (model basic -ndm 2|3)");
  elements::ElasticBeam2d::Params p;
  p.area = args.real("A");
  p.modulus = args.real("E");
  p.inertiaZ = args.real("Iz");
  const int transfTag = args.integer("transfTag");
  p.massPerLength = args.option("-mass", 0.0);
  p.consistentMass = args.flag("-cMass");
  if (args.flag("-lMass")) p.consistentMass = false;  // lumped, the default
  args.finish();
  p.validate();
  return std::make_unique<elements::ElasticBeam2d>(tag, iNode, jNode, p,
                                                   transformFor<CrdTransf2d>(rt, transfTag));
}

// Element iterations of a force-based beam: OpenSees' default is 10; thousands never help.
constexpr int kMaxElementIterations = 1000;
constexpr double kMinElementTolerance = 1e-15;

// An integration rule written in the element command, as OpenSees' TclForceBeamColumnCommand
// takes it after the transformation tag: `Lobatto|Legendre|Radau|NewtonCotes secTag N` or
// `HingeRadau secI lpI secJ lpJ secE`, as separate words or as one list ("Lobatto 1 5").
std::unique_ptr<elements::BeamIntegration> inlineIntegration(Runtime& rt, ArgReader& args) {
  std::vector<std::string> words;
  const std::string first = args.word("integration");
  if (first.find_first_of(" \t\n") != std::string::npos) {
    int n = 0;
    const char** list = nullptr;
    if (Tcl_SplitList(nullptr, first.c_str(), &n, &list) != TCL_OK)
      args.fail(args.lastPosition(), "integration", "is not a list: \"" + first + "\"");
    for (int k = 0; k < n; ++k) words.emplace_back(list[k]);
    Tcl_Free(reinterpret_cast<char*>(list));
  } else {
    words.push_back(first);
    const std::size_t more = first == "HingeRadau" ? 5 : 2;
    for (std::size_t k = 0; k < more && args.hasPositional(); ++k) words.push_back(args.word("integration"));
  }
  const std::string& type = words[0];
  auto number = [&](std::size_t k, const char* name) {
    double v = 0.0;
    if (k >= words.size() || Tcl_GetDouble(nullptr, words[k].c_str(), &v) != TCL_OK)
      args.fail(args.lastPosition(), name,
                "expected a number in the integration \"" + type + " ...\", got \"" +
                    (k < words.size() ? words[k] : std::string()) + "\"");
    return v;
  };
  auto integer = [&](std::size_t k, const char* name) {
    int v = 0;
    if (k >= words.size() || Tcl_GetInt(nullptr, words[k].c_str(), &v) != TCL_OK)
      args.fail(args.lastPosition(), name,
                "expected an integer in the integration \"" + type + " ...\", got \"" +
                    (k < words.size() ? words[k] : std::string()) + "\"");
    return v;
  };
  if (type == "HingeRadau") {
    if (words.size() != 6) args.fail(args.lastPosition(), "integration", "HingeRadau needs secI lpI secJ lpJ secE");
    const int secI = integer(1, "secI"), secJ = integer(3, "secJ"), secE = integer(5, "secE");
    for (int sec : {secI, secJ, secE}) (void)rt.builder.section(sec);
    return std::make_unique<elements::HingeRadauIntegration>(0, secI, number(2, "lpI"), secJ,
                                                             number(4, "lpJ"), secE);
  }
  using Rule = elements::QuadratureIntegration::Rule;
  Rule r = Rule::Lobatto;
  if (type == "Legendre") r = Rule::Legendre;
  else if (type == "Radau") r = Rule::Radau;
  else if (type == "NewtonCotes") r = Rule::NewtonCotes;
  else if (type != "Lobatto")
    args.fail(args.lastPosition(), "integration",
              "expected Lobatto, Legendre, Radau, NewtonCotes or HingeRadau, got \"" + type + "\"");
  if (words.size() != 3) args.fail(args.lastPosition(), "integration", type + " needs secTag N");
  const int sec = integer(1, "secTag");
  (void)rt.builder.section(sec);
  return std::make_unique<elements::QuadratureIntegration>(0, r, sec, integer(2, "N"));
}

// element forceBeamColumn|nonlinearBeamColumn|dispBeamColumn tag i j transfTag integrationTag
//   ?-iter maxIter tol? ?-mass m? ?-cMass|-lMass?, the older tag i j nIP secTag transfTag ?...?
//   ?-integration type? (forceBeamColumn: Lobatto, dispBeamColumn: Legendre, as OpenSees), or
//   tag i j transfTag "Type secTag N" | Type secTag N (inline integration, see above).
template <bool Force>
std::unique_ptr<elements::Element> parseSectionBeam(Runtime& rt, ArgReader& args, int tag) {
  const int ndm = rt.builder.ndm;
  const int iNode = args.integer("iNode");
  const int jNode = args.integer("jNode");
  const std::vector<int> ints = args.integers("transfTag integrationTag | nIP secTag transfTag", 1);
  if (ints.size() > 3) args.fail("too many integer arguments");
  std::unique_ptr<elements::BeamIntegration> owned;
  if (ints.size() == 1) {
    if (!args.hasPositional()) args.fail("needs an integration after transfTag");
    owned = inlineIntegration(rt, args);
  }
  int maxIter = 10;
  double tol = 1e-12;
  if (auto it = args.optionReals("-iter", 2)) {
    // maxIter is checked as a real before the cast, so 1e308 cannot overflow an int.
    if (!((*it)[0] >= 1.0 && (*it)[0] <= kMaxElementIterations && (*it)[0] == std::floor((*it)[0])))
      throw InputError("-iter maxIter", "must be an integer from 1 to " + std::to_string(kMaxElementIterations));
    maxIter = static_cast<int>((*it)[0]);
    tol = (*it)[1];
    if (tol < kMinElementTolerance)
      throw InputError("-iter tol", "must be at least 1e-15: the element's work is compared relative to its "
                                    "size, and round-off of doubles (about 1e-16) decides below that");
  }
  const double mass = args.option("-mass", 0.0);
  const bool consistentMass = args.flag("-cMass");
  const bool lumpedMass = args.flag("-lMass");  // lumped is the default anyway
  if (consistentMass && lumpedMass) args.fail("takes -cMass or -lMass, not both");
  const std::string integrationType =
      args.option("-integration", std::string(Force ? "Lobatto" : "Legendre"));
  args.finish();
  if (maxIter < 1) throw InputError("-iter maxIter", "must be at least 1");
  if (!(tol > 0.0)) throw InputError("-iter tol", "must be positive");
  if (!(mass >= 0.0)) throw InputError("-mass", "must be zero or positive");
  const double length = (rt.domain.node(jNode).coords() - rt.domain.node(iNode).coords()).norm();
  if (!(length > 0.0)) throw InputError("element", "nodes coincide (zero length)");

  const elements::BeamIntegration* rule = owned.get();
  int transfTag = ints[0];
  if (ints.size() == 2) {
    rule = &rt.builder.integration(ints[1]);
  } else if (ints.size() == 3) {
    transfTag = ints[2];
    using Rule = elements::QuadratureIntegration::Rule;
    Rule r = Rule::Lobatto;
    if (integrationType == "Legendre") r = Rule::Legendre;
    else if (integrationType == "Radau") r = Rule::Radau;
    else if (integrationType == "NewtonCotes") r = Rule::NewtonCotes;
    else if (integrationType != "Lobatto")
      throw InputError("-integration", "must be Lobatto, Legendre, Radau or NewtonCotes");
    owned = std::make_unique<elements::QuadratureIntegration>(0, r, ints[1], ints[0]);
    rule = owned.get();
  }
  const std::vector<int> secs = rule->sectionTags();
  const std::vector<double> xi = rule->locations(length), w = rule->weights(length);
  std::vector<elements::BeamIntegrationPoint> pts;
  for (std::size_t k = 0; k < secs.size(); ++k)
    pts.push_back({rt.builder.section(secs[k]).clone(), xi[k], w[k]});
  auto withMass = [consistentMass](auto element) {
    element->setConsistentMass(consistentMass);
    return std::unique_ptr<elements::Element>(std::move(element));
  };
  if (ndm == 3) {
    auto t = transformFor<CrdTransf3d>(rt, transfTag);
    if constexpr (Force)
      return withMass(std::make_unique<elements::ForceBeamColumn3d>(
          tag, iNode, jNode, std::move(pts), std::move(t), mass, maxIter, tol));
    else
      return withMass(std::make_unique<elements::DispBeamColumn3d>(tag, iNode, jNode,
                                                                   std::move(pts), std::move(t),
                                                                   mass));
  }
  auto t = transformFor<CrdTransf2d>(rt, transfTag);
  if constexpr (Force)
    return withMass(std::make_unique<elements::ForceBeamColumn2d>(
        tag, iNode, jNode, std::move(pts), std::move(t), mass, maxIter, tol));
  else
    return withMass(std::make_unique<elements::DispBeamColumn2d>(tag, iNode, jNode,
                                                                 std::move(pts), std::move(t),
                                                                 mass));
}

constexpr const char* kZeroLengthSectionUsage =
    "element zeroLengthSection tag iNode jNode secTag ?-orient x1 x2 x3 yp1 yp2 yp3?";

// element zeroLengthSection tag i j secTag ?-orient x1 x2 x3 yp1 yp2 yp3?
std::unique_ptr<elements::Element> parseZeroLengthSection(Runtime& rt, ArgReader& args, int tag) {
  args.setUsage(kZeroLengthSectionUsage);
  const int iNode = args.integer("iNode");
  const int jNode = args.integer("jNode");
  const int secTag = args.integer("secTag");
  Eigen::Vector3d x = Eigen::Vector3d::UnitX(), yp = Eigen::Vector3d::UnitY();
  if (auto o = args.optionReals("-orient", 6)) {
    x << (*o)[0], (*o)[1], (*o)[2];
    yp << (*o)[3], (*o)[4], (*o)[5];
  }
  args.finish();
  const int ndm = rt.builder.ndm;
  if (ndm != 2 && ndm != 3) args.fail("needs a 2D or 3D model (model basic -ndm 2|3)");
  auto section = rt.builder.section(secTag).clone();
  if (ndm == 3)
    return std::make_unique<elements::ZeroLengthSection3d>(tag, iNode, jNode, std::move(section),
                                                           x, yp);
  return std::make_unique<elements::ZeroLengthSection2d>(tag, iNode, jNode, std::move(section), x,
                                                         yp);
}

constexpr std::array kSectionCommands{
    CommandEntry{"geomTransf", "geomTransf Linear|PDelta|Corotational tag ?vecxzX vecxzY vecxzZ?",
                 geomTransfCommand},
    CommandEntry{"section",
                 "section Fiber tag ?-GJ GJ? {body} | Elastic tag E A Iz ... | Aggregator tag "
                 "matTag code ... ?-section secTag? | Uniaxial tag matTag code",
                 sectionCommand},
    CommandEntry{"fiber", "fiber y z A matTag", fiberCommand},
    CommandEntry{"patch",
                 "patch rect matTag nY nZ yI zI yJ zJ | quad matTag nIJ nJK yI zI yJ zJ yK zK yL zL"
                 " | circ matTag nCirc nRad yC zC rInt rExt ?startAng endAng?",
                 patchCommand},
    CommandEntry{"layer",
                 "layer straight matTag numBars areaBar yStart zStart yEnd zEnd | circ matTag "
                 "numBars areaBar yC zC radius ?startAng endAng?",
                 layerCommand},
    CommandEntry{"beamIntegration",
                 "beamIntegration Lobatto|Legendre|Radau|NewtonCotes tag secTag N | HingeRadau tag "
                 "secI lpI secJ lpJ secE",
                 beamIntegrationCommand},
};

constexpr std::array kBeamElements{
    ElementEntry{"zeroLengthSection", kZeroLengthSectionUsage, parseZeroLengthSection},
    ElementEntry{"elasticBeamColumn",
                 "element elasticBeamColumn tag iNode jNode A E Iz transfTag ?-mass m? ?-cMass? "
                 "(2D) | tag iNode jNode A E G J Iy Iz transfTag ?-mass m? ?-cMass? (3D)",
                 parseElasticBeam},
    ElementEntry{"forceBeamColumn",
                 "element forceBeamColumn tag iNode jNode transfTag integrationTag|\"Type secTag "
                 "N\" ?-iter maxIter tol? ?-mass m? ?-cMass|-lMass? | tag iNode jNode nIP secTag "
                 "transfTag ?-iter maxIter tol? ?-mass m? ?-cMass|-lMass? ?-integration "
                 "Lobatto|Legendre|Radau|NewtonCotes?",
                 parseSectionBeam<true>},
    ElementEntry{"nonlinearBeamColumn",
                 "element nonlinearBeamColumn tag iNode jNode nIP secTag transfTag ?-iter maxIter "
                 "tol? ?-mass m? ?-cMass|-lMass?",
                 parseSectionBeam<true>},
    ElementEntry{"dispBeamColumn",
                 "element dispBeamColumn tag iNode jNode transfTag integrationTag|\"Type secTag N\" "
                 "?-mass m? ?-cMass|-lMass? | tag iNode jNode nIP secTag transfTag ?-mass m? "
                 "?-cMass|-lMass? ?-integration Legendre|Lobatto|Radau|NewtonCotes?",
                 parseSectionBeam<false>},
};

}  // namespace

std::span<const CommandEntry> sectionCommands() { return kSectionCommands; }
std::span<const ElementEntry> beamElementParsers() { return kBeamElements; }

}  // namespace dabs::tcl
