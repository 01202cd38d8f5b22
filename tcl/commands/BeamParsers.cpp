// SPDX-License-Identifier: MIT
// Tcl parsers for beam-columns and what they are built from besides sections: `geomTransf`,
// `beamIntegration`, and the elements elasticBeamColumn, forceBeamColumn (nonlinearBeamColumn),
// dispBeamColumn and zeroLengthSection. Syntax follows OpenSees (OpenSees/OpenSees:SRC/
// coordTransformation/TclGeomTransfCommand.cpp, SRC/element/elasticBeamColumn/
// TclElasticBeamCommand.cpp, SRC/element/forceBeamColumn/TclForceBeamColumnCommand.cpp).
#include <algorithm>
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
#include "elements/transform/LinearTransf.h"
#include "elements/transform/PDeltaTransf.h"
#include "materials/InputError.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace {

using elements::CrdTransf;
using elements::CrdTransf2d;
using elements::CrdTransf3d;
using Rule = elements::QuadratureIntegration::Rule;

/// The quadrature rules by name (`beamIntegration`, inline integration, `-integration`).
constexpr std::array<std::pair<std::string_view, Rule>, 4> kQuadratureRules{{
    {"Lobatto", Rule::Lobatto},
    {"Legendre", Rule::Legendre},
    {"Radau", Rule::Radau},
    {"NewtonCotes", Rule::NewtonCotes},
}};
constexpr const char* kQuadratureRuleNames = "Lobatto, Legendre, Radau, NewtonCotes";

std::optional<Rule> quadratureRule(std::string_view name) {
  for (const auto& [ruleName, rule] : kQuadratureRules)
    if (ruleName == name) return rule;
  return std::nullopt;
}

// beamIntegration Lobatto|Legendre|Radau|NewtonCotes tag secTag N |
// beamIntegration HingeRadau tag secI lpI secJ lpJ secE
void beamIntegrationCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("beamIntegration");
  const std::string type = args.word("type");
  args.setContext("beamIntegration " + type);
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
    const std::optional<Rule> r = quadratureRule(type);
    if (!r)
      args.fail(args.lastPosition(), "type",
                "unknown rule \"" + type + "\" (" + kQuadratureRuleNames + ", HingeRadau)");
    args.setUsage("beamIntegration " + type + " tag secTag N");
    const int tag = readNewTag(args, rt.builder.integrations, "beamIntegration");
    const int sec = args.integer("secTag");
    const int n = args.integer("N");
    args.finish();
    (void)rt.builder.section(sec);
    rule = std::make_unique<elements::QuadratureIntegration>(tag, *r, sec, n);
  }
  const int tag = rule->tag();
  rt.builder.integrations[tag] = std::move(rule);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

constexpr const char* kGeomTransfUsage2d = "geomTransf Linear|PDelta|Corotational tag";
constexpr const char* kGeomTransfUsage3d =
    "geomTransf Linear|PDelta|Corotational tag vecxzX vecxzY vecxzZ";

/// A transformation type: its 2D and 3D constructors.
struct TransfType {
  std::string_view name;
  std::unique_ptr<CrdTransf> (*make2d)(int tag);
  std::unique_ptr<CrdTransf> (*make3d)(int tag, const Eigen::Vector3d& vecxz);
};

template <template <int> class T>
constexpr TransfType transfType(std::string_view name) {
  return {name, [](int tag) -> std::unique_ptr<CrdTransf> { return std::make_unique<T<2>>(tag); },
          [](int tag, const Eigen::Vector3d& v) -> std::unique_ptr<CrdTransf> {
            return std::make_unique<T<3>>(tag, v);
          }};
}

const std::array kTransfTypes{
    transfType<elements::LinearTransf>("Linear"),
    transfType<elements::PDeltaTransf>("PDelta"),
    transfType<elements::CorotationalTransf>("Corotational"),
};

// geomTransf Linear|PDelta|Corotational tag ?vecxz(3D)?
void geomTransfCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("geomTransf");
  const int ndm = rt.builder.ndm;
  args.setUsage(ndm == 2 ? kGeomTransfUsage2d : kGeomTransfUsage3d);
  const std::string type = args.word("type");
  const auto found = std::find_if(kTransfTypes.begin(), kTransfTypes.end(),
                                  [&](const TransfType& t) { return t.name == type; });
  if (found == kTransfTypes.end())
    args.fail(args.lastPosition(), "type",
              "unknown transformation \"" + type + "\" (expected Linear, PDelta or Corotational)");
  args.setContext("geomTransf " + type);
  const int tag = readNewTag(args, rt.builder.transforms, "geomTransf");
  if (ndm != 2 && ndm != 3) args.fail("needs a 2D or 3D model (model basic -ndm 2|3)");

  std::unique_ptr<CrdTransf> transf;
  if (ndm == 2) {
    if (args.optionRealList("-jntOffset")) args.fail("-jntOffset (joint offsets) is not supported");
    args.finish();
    transf = found->make2d(tag);
  } else {
    const std::vector<double> v = args.reals("vecxz", 3, true);
    const Eigen::Vector3d vecxz(v[0], v[1], v[2]);
    if (args.optionRealList("-jntOffset")) args.fail("-jntOffset (joint offsets) is not supported");
    args.finish();
    if (!(vecxz.norm() > 0.0)) throw InputError("vecxz", "must be a nonzero vector");
    transf = found->make3d(tag, vecxz);
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
  // What follows the section properties in both dimensions; returns transfTag.
  const auto readRest = [&args](auto& p) {
    const int transfTag = args.integer("transfTag");
    p.massPerLength = args.option("-mass", 0.0);
    p.consistentMass = args.flag("-cMass");
    if (args.flag("-lMass")) p.consistentMass = false;  // lumped, the default
    args.finish();
    p.validate();
    return transfTag;
  };
  if (ndm == 3) {
    elements::ElasticBeam3d::Params p;
    p.area = args.real("A");
    p.modulus = args.real("E");
    p.shearModulus = args.real("G");
    p.torsion = args.real("J");
    p.inertiaY = args.real("Iy");
    p.inertiaZ = args.real("Iz");
    const int transfTag = readRest(p);
    return std::make_unique<elements::ElasticBeam3d>(tag, iNode, jNode, p,
                                                     transformFor<CrdTransf3d>(rt, transfTag));
  }
  if (ndm != 2) args.fail("needs a 2D or 3D model (model basic -ndm 2|3)");
  elements::ElasticBeam2d::Params p;
  p.area = args.real("A");
  p.modulus = args.real("E");
  p.inertiaZ = args.real("Iz");
  const int transfTag = readRest(p);
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
    // A blank word is a list of no words: no rule to index.
    if (words.empty())
      args.fail(args.lastPosition(), "integration",
                "expected a rule (Lobatto secTag N, ..., HingeRadau secI lpI secJ lpJ secE), got "
                "a blank word");
  } else {
    words.push_back(first);
    const std::size_t more = first == "HingeRadau" ? 5 : 2;
    for (std::size_t k = 0; k < more && args.hasPositional(); ++k)
      words.push_back(args.word("integration"));
  }
  const std::string& type = words[0];
  // Word k of the rule as a number (an integer when `whole`), or an error naming it.
  auto number = [&](std::size_t k, const char* name, bool whole = false) {
    const char* w = k < words.size() ? words[k].c_str() : "";
    int i = 0;
    double v = 0.0;
    if (whole ? Tcl_GetInt(nullptr, w, &i) != TCL_OK : Tcl_GetDouble(nullptr, w, &v) != TCL_OK)
      args.fail(args.lastPosition(), name,
                std::string("expected ") + (whole ? "an integer" : "a number") +
                    " in the integration \"" + type + " ...\", got \"" + w + "\"");
    return whole ? i : v;
  };
  auto integer = [&](std::size_t k, const char* name) {
    return static_cast<int>(number(k, name, true));
  };
  if (type == "HingeRadau") {
    if (words.size() != 6)
      args.fail(args.lastPosition(), "integration", "HingeRadau needs secI lpI secJ lpJ secE");
    const int secI = integer(1, "secI"), secJ = integer(3, "secJ"), secE = integer(5, "secE");
    for (int sec : {secI, secJ, secE}) (void)rt.builder.section(sec);
    return std::make_unique<elements::HingeRadauIntegration>(0, secI, number(2, "lpI"), secJ,
                                                             number(4, "lpJ"), secE);
  }
  const std::optional<Rule> r = quadratureRule(type);
  if (!r)
    args.fail(
        args.lastPosition(), "integration",
        std::string("expected ") + kQuadratureRuleNames + " or HingeRadau, got \"" + type + "\"");
  if (words.size() != 3) args.fail(args.lastPosition(), "integration", type + " needs secTag N");
  const int sec = integer(1, "secTag");
  (void)rt.builder.section(sec);
  return std::make_unique<elements::QuadratureIntegration>(0, *r, sec, integer(2, "N"));
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
      args.failArgument(
          "-iter", 0,
          "maxIter must be an integer from 1 to " + std::to_string(kMaxElementIterations));
    maxIter = static_cast<int>((*it)[0]);
    tol = (*it)[1];
    if (!(tol >= kMinElementTolerance))
      args.failArgument("-iter", 1,
                        "tol must be at least 1e-15: the element's work is compared relative to "
                        "its size, and round-off of doubles (about 1e-16) decides below that");
  }
  const double mass = args.option("-mass", 0.0);
  const bool consistentMass = args.flag("-cMass");
  const bool lumpedMass = args.flag("-lMass");  // lumped is the default anyway
  if (consistentMass && lumpedMass) args.fail("takes -cMass or -lMass, not both");
  const std::string integrationType =
      args.option("-integration", std::string(Force ? "Lobatto" : "Legendre"));
  args.finish();
  if (!(mass >= 0.0)) throw InputError("-mass", "must be zero or positive");
  const double length = (rt.domain.node(jNode).coords() - rt.domain.node(iNode).coords()).norm();
  if (!(length > 0.0)) throw InputError("element", "nodes coincide (zero length)");

  const elements::BeamIntegration* rule = owned.get();
  int transfTag = ints[0];
  if (ints.size() == 2) {
    rule = &rt.builder.integration(ints[1]);
  } else if (ints.size() == 3) {
    transfTag = ints[2];
    const std::optional<Rule> r = quadratureRule(integrationType);
    if (!r) throw InputError("-integration", std::string("must be one of ") + kQuadratureRuleNames);
    owned = std::make_unique<elements::QuadratureIntegration>(0, *r, ints[1], ints[0]);
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
      return withMass(std::make_unique<elements::DispBeamColumn3d>(
          tag, iNode, jNode, std::move(pts), std::move(t), mass));
  }
  auto t = transformFor<CrdTransf2d>(rt, transfTag);
  if constexpr (Force)
    return withMass(std::make_unique<elements::ForceBeamColumn2d>(
        tag, iNode, jNode, std::move(pts), std::move(t), mass, maxIter, tol));
  else
    return withMass(std::make_unique<elements::DispBeamColumn2d>(tag, iNode, jNode, std::move(pts),
                                                                 std::move(t), mass));
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
    return std::make_unique<elements::ZeroLengthSection3d>(tag, iNode, jNode, std::move(section), x,
                                                           yp);
  return std::make_unique<elements::ZeroLengthSection2d>(tag, iNode, jNode, std::move(section), x,
                                                         yp);
}

constexpr std::array kBeamCommands{
    CommandEntry{"geomTransf", "geomTransf Linear|PDelta|Corotational tag ?vecxzX vecxzY vecxzZ?",
                 geomTransfCommand},
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
    ElementEntry{
        "dispBeamColumn",
        "element dispBeamColumn tag iNode jNode transfTag integrationTag|\"Type secTag N\" "
        "?-mass m? ?-cMass|-lMass? | tag iNode jNode nIP secTag transfTag ?-mass m? "
        "?-cMass|-lMass? ?-integration Legendre|Lobatto|Radau|NewtonCotes?",
        parseSectionBeam<false>},
};

}  // namespace

std::span<const CommandEntry> beamCommands() { return kBeamCommands; }
std::span<const ElementEntry> beamElementParsers() { return kBeamElements; }

}  // namespace dabs::tcl
