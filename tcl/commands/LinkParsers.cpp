// SPDX-License-Identifier: MIT
// Parsers of the link elements: zeroLength, truss and corotTruss.
#include <cmath>
#include <limits>
#include <optional>

#include "elements/link/Truss.h"
#include "elements/link/ZeroLength.h"
#include "materials/InputError.h"
#include "materials/section/SectionAxialMaterial.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace {

std::unique_ptr<elements::Element> parseZeroLength(Runtime& rt, ArgReader& a, int tag) {
  elements::ZeroLength::Params p;
  p.nodes = {a.integer("iNode"), a.integer("jNode")};
  p.ndm = rt.builder.ndm;
  p.ndf = rt.domain.node(p.nodes[0]).ndf();
  const auto mats = a.optionIntegerList("-mat");
  if (!mats) a.fail("-mat is required");
  const auto dirs = a.optionIntegerList("-dir");
  if (!dirs) a.fail("-dir is required");
  p.dirs = *dirs;
  if (auto orient = a.optionReals("-orient", 6)) {
    p.x = Eigen::Vector3d((*orient)[0], (*orient)[1], (*orient)[2]);
    p.yp = Eigen::Vector3d((*orient)[3], (*orient)[4], (*orient)[5]);
  }
  if (a.flag("-doRayleigh")) {
    // `-doRayleigh` alone switches it on; `-doRayleigh 0|1` sets it.
    p.doRayleigh = true;
    if (a.hasPositional()) p.doRayleigh = a.integer("doRayleigh flag") != 0;
  }
  a.finish();
  p.validate(mats->size());
  std::vector<std::unique_ptr<materials::UniaxialMaterial>> clones;
  for (int m : *mats) clones.push_back(rt.builder.uniaxialMaterial(m).clone());
  return std::make_unique<elements::ZeroLength>(tag, std::move(p), std::move(clones));
}

// element truss|corotTruss tag i j A matTag <options> | tag i j secTag <options>: a single value
// after the nodes is a section tag (OpenSees tells the forms apart by the number of arguments);
// options -rho rho, -cMass 0|1, -doRayleigh 0|1.
template <bool Corotational>
std::unique_ptr<elements::Element> parseTruss(Runtime& rt, ArgReader& a, int tag) {
  elements::Truss::Params p;
  p.corotational = Corotational;
  p.nodes = {a.integer("iNode"), a.integer("jNode")};
  const double first = a.real("A | secTag");
  std::optional<int> mat;
  if (a.hasPositional()) mat = a.integer("matTag");
  p.rho = a.option("-rho", 0.0);
  if (a.flag("-cMass")) {
    // `-cMass` alone switches it on; `-cMass 0|1` sets it.
    p.consistentMass = true;
    if (a.hasPositional()) p.consistentMass = a.integer("cMass flag") != 0;
  }
  if (a.flag("-doRayleigh")) {
    p.doRayleigh = true;
    if (a.hasPositional()) p.doRayleigh = a.integer("doRayleigh flag") != 0;
  }
  a.finish();
  p.ndm = rt.builder.ndm;
  p.ndf = rt.domain.node(p.nodes[0]).ndf();
  std::unique_ptr<materials::UniaxialMaterial> material;
  if (mat) {
    p.area = first;
    material = rt.builder.uniaxialMaterial(*mat).clone();
  } else {
    // A whole number beyond int's range (-1e308) is no tag: converting it would be undefined.
    if (first != std::floor(first) || first < std::numeric_limits<int>::min() ||
        first > std::numeric_limits<int>::max())
      a.failArgument("A | secTag", "expected a section tag (or A matTag)");
    p.area = 1.0;  // the section's axial force is the truss force
    material = std::make_unique<materials::section::SectionAxialMaterial>(
        rt.builder.section(static_cast<int>(first)).clone());
  }
  p.validate();
  return std::make_unique<elements::Truss>(tag, std::move(p), std::move(material));
}

constexpr ElementEntry kParsers[] = {
    {"zeroLength",
     "element zeroLength tag iNode jNode -mat m1 .. -dir d1 .. ?-orient x1 x2 x3 yp1 yp2 yp3? "
     "?-doRayleigh 0|1?",
     parseZeroLength},
    {"truss",
     "element truss tag iNode jNode A matTag|secTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?",
     parseTruss<false>},
    {"Truss",
     "element Truss tag iNode jNode A matTag|secTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?",
     parseTruss<false>},
    {"corotTruss",
     "element corotTruss tag iNode jNode A matTag|secTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?",
     parseTruss<true>},
    {"CorotTruss",
     "element CorotTruss tag iNode jNode A matTag|secTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?",
     parseTruss<true>},
};

}  // namespace

std::span<const ElementEntry> linkElementParsers() { return kParsers; }

}  // namespace dabs::tcl
