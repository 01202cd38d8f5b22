// SPDX-License-Identifier: MIT
// Tcl parsers for beam-columns and what they are built from: `geomTransf`, `element
// elasticBeamColumn`. Syntax follows OpenSees (OpenSees/OpenSees:SRC/coordTransformation/
// TclGeomTransfCommand.cpp, SRC/element/elasticBeamColumn/TclElasticBeamCommand.cpp).
#include <array>
#include <string>

#include "elements/beam/ElasticBeam2d.h"
#include "elements/beam/ElasticBeam3d.h"
#include "elements/transform/CorotationalTransf2d.h"
#include "elements/transform/LinearTransf2d.h"
#include "elements/transform/LinearTransf3d.h"
#include "elements/transform/PDeltaTransf2d.h"
#include "elements/transform/PDeltaTransf3d.h"
#include "materials/InputError.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace {

using elements::CrdTransf;
using elements::CrdTransf2d;
using elements::CrdTransf3d;

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
      args.fail("Corotational is not yet available in 3D");
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
    "element elasticBeamColumn tag iNode jNode A E Iz transfTag ?-mass m? ?-cMass?";
constexpr const char* kElasticUsage3d =
    "element elasticBeamColumn tag iNode jNode A E G J Iy Iz transfTag ?-mass m? ?-cMass?";

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
  args.finish();
  p.validate();
  return std::make_unique<elements::ElasticBeam2d>(tag, iNode, jNode, p,
                                                   transformFor<CrdTransf2d>(rt, transfTag));
}

constexpr std::array kSectionCommands{
    CommandEntry{"geomTransf", "geomTransf Linear|PDelta|Corotational tag ?vecxzX vecxzY vecxzZ?",
                 geomTransfCommand},
};

constexpr std::array kBeamElements{
    ElementEntry{"elasticBeamColumn",
                 "element elasticBeamColumn tag iNode jNode A E Iz transfTag ?-mass m? ?-cMass? "
                 "(2D) | tag iNode jNode A E G J Iy Iz transfTag ?-mass m? ?-cMass? (3D)",
                 parseElasticBeam},
};

}  // namespace

std::span<const CommandEntry> sectionCommands() { return kSectionCommands; }
std::span<const ElementEntry> beamElementParsers() { return kBeamElements; }

}  // namespace dabs::tcl
