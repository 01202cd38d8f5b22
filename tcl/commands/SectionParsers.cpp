// SPDX-License-Identifier: MIT
// Tcl parsers for cross-sections: `section Fiber` with its `fiber`, `patch` and `layer` body
// commands, `section Elastic`, `section Aggregator` and `section Uniaxial`. Syntax follows
// OpenSees (OpenSees/OpenSees:SRC/material/section/TclModelBuilderSectionCommand.cpp).
#include <algorithm>
#include <array>
#include <string>

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
    args.fail("would give the section " +
              std::to_string(count + static_cast<long long>(s.fibers.size())) +
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
                                     const FiberSectionUnderConstruction& under, double gj,
                                     bool aboutCentroid) {
  std::vector<typename S::Fiber> fibers;
  for (const auto& f : under.fibers)
    fibers.push_back({f.y, f.z, f.area, &rt.builder.uniaxialMaterial(f.materialTag)});
  return std::make_unique<S>(tag, fibers, gj, aboutCentroid);
}

constexpr const char* kElasticSectionUsage2d = "section Elastic tag E A Iz ?G alphaY?";
constexpr const char* kElasticSectionUsage3d = "section Elastic tag E A Iz Iy G J ?alphaY alphaZ?";
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
  const std::optional<std::vector<int>> base = args.optionIntegerList("-section");
  if (base && base->size() != 1) args.failArgument("-section", "takes one section tag");
  std::vector<materials::section::SectionAggregator::Part> parts;
  while (args.hasPositional()) {
    const int mat = args.integer("matTag");
    const materials::section::SectionCode code = sectionCode(args);
    if (rt.builder.ndm == 2 &&
        (code == materials::section::SectionCode::My ||
         code == materials::section::SectionCode::Vz || code == materials::section::SectionCode::T))
      args.fail(args.lastPosition(), "code", "My, Vz and T are not available in a 2D model");
    parts.push_back({&rt.builder.uniaxialMaterial(mat), code});
  }
  args.finish();
  const materials::section::SectionForceDeformation* baseSection = nullptr;
  if (base) baseSection = &rt.builder.section(base->front());
  if (parts.empty() && baseSection == nullptr)
    args.fail("needs at least one matTag code pair or -section secTag");
  return std::make_unique<materials::section::SectionAggregator>(tag, parts, baseSection);
}

using SectionPtr = std::unique_ptr<materials::section::SectionForceDeformation>;

// section Uniaxial tag matTag code: one resultant carried by one material (OpenSees'
// SectionAggregator with a single material, as its own Uniaxial section).
SectionPtr parseUniaxialSection(Runtime& rt, ArgReader& args, int tag) {
  const int mat = args.integer("matTag");
  const materials::section::SectionCode code = sectionCode(args);
  args.finish();
  if (rt.builder.ndm == 2 &&
      (code == materials::section::SectionCode::My || code == materials::section::SectionCode::Vz ||
       code == materials::section::SectionCode::T))
    args.fail(args.lastPosition(), "code", "My, Vz and T are not available in a 2D model");
  return std::make_unique<materials::section::SectionAggregator>(
      tag,
      std::vector<materials::section::SectionAggregator::Part>{
          {&rt.builder.uniaxialMaterial(mat), code}},
      nullptr);
}

// section Fiber tag ?-GJ GJ? ?-noCentroid? { fiber ...; patch ...; layer ... }
SectionPtr parseFiberSection(Runtime& rt, ArgReader& args, int tag) {
  const int ndm = rt.builder.ndm;
  if (rt.currentFiberSection != nullptr) args.fail("section Fiber bodies cannot be nested");
  const std::optional<double> gj = args.optionalOption("-GJ");
  // OpenSees takes strains about the fibers' area centroid unless -noCentroid.
  const bool aboutCentroid = !args.flag("-noCentroid");
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
    throw ArgError(args.context() +
                   ": error in the section body: " + Tcl_GetStringResult(rt.interp));
  if (ndm == 2)
    return buildFiberSection<materials::section::FiberSection2d>(rt, tag, under, 0.0,
                                                                 aboutCentroid);
  return buildFiberSection<materials::section::FiberSection3d>(rt, tag, under, *gj, aboutCentroid);
}

/// A section type: its usage lines (2D, 3D) and its parser (arguments after the tag).
struct SectionType {
  std::string_view name;
  const char* usage2d;
  const char* usage3d;
  SectionPtr (*parse)(Runtime&, ArgReader&, int tag);
};

constexpr const char* kFiberSectionUsage =
    "section Fiber tag ?-GJ GJ? ?-noCentroid? { fiber ...; patch ...; layer ... }";
constexpr const char* kUniaxialSectionUsage =
    "section Uniaxial tag matTag code (code P, Mz, Vy, My, Vz or T)";

constexpr std::array kSectionTypes{
    SectionType{"Fiber", kFiberSectionUsage, kFiberSectionUsage, parseFiberSection},
    SectionType{"fiberSec", kFiberSectionUsage, kFiberSectionUsage, parseFiberSection},
    SectionType{"Elastic", kElasticSectionUsage2d, kElasticSectionUsage3d, parseElasticSection},
    SectionType{"Aggregator", kAggregatorUsage, kAggregatorUsage, parseAggregator},
    SectionType{"Uniaxial", kUniaxialSectionUsage, kUniaxialSectionUsage, parseUniaxialSection},
};

// section Fiber|Elastic|Aggregator|Uniaxial tag ...
void sectionCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("section");
  const std::string type = args.word("type");
  const auto found = std::find_if(kSectionTypes.begin(), kSectionTypes.end(),
                                  [&](const SectionType& t) { return t.name == type; });
  if (found == kSectionTypes.end())
    args.fail(args.lastPosition(), "type",
              "unknown section \"" + type + "\" (available: Fiber, Elastic, Aggregator, Uniaxial)");
  args.setContext("section " + type);
  args.setUsage(rt.builder.ndm == 3 ? found->usage3d : found->usage2d);
  const int tag = readNewTag(args, rt.builder.sections, "section");
  SectionPtr section = found->parse(rt, args, tag);
  rt.builder.sections[tag] = std::move(section);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

constexpr std::array kSectionCommands{
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
};

}  // namespace

std::span<const CommandEntry> sectionCommands() { return kSectionCommands; }

}  // namespace dabs::tcl
