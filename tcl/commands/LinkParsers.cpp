// SPDX-License-Identifier: MIT
// Parsers of the link elements: zeroLength and truss.
#include "elements/link/Truss.h"
#include "elements/link/ZeroLength.h"
#include "materials/InputError.h"
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

std::unique_ptr<elements::Element> parseTruss(Runtime& rt, ArgReader& a, int tag) {
  elements::Truss::Params p;
  p.nodes = {a.integer("iNode"), a.integer("jNode")};
  p.area = a.real("A");
  const int mat = a.integer("matTag");
  p.rho = a.option("-rho", 0.0);
  p.consistentMass = a.option("-cMass", 0) != 0;
  if (a.flag("-doRayleigh")) {
    p.doRayleigh = true;
    if (a.hasPositional()) p.doRayleigh = a.integer("doRayleigh flag") != 0;
  }
  a.finish();
  p.ndm = rt.builder.ndm;
  p.ndf = rt.domain.node(p.nodes[0]).ndf();
  p.validate();
  return std::make_unique<elements::Truss>(tag, std::move(p), rt.builder.uniaxialMaterial(mat).clone());
}

constexpr ElementEntry kParsers[] = {
    {"zeroLength",
     "element zeroLength tag iNode jNode -mat m1 .. -dir d1 .. ?-orient x1 x2 x3 yp1 yp2 yp3? ?-doRayleigh 0|1?",
     parseZeroLength},
    {"truss", "element truss tag iNode jNode A matTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?", parseTruss},
    {"Truss", "element Truss tag iNode jNode A matTag ?-rho rho? ?-cMass 0|1? ?-doRayleigh 0|1?", parseTruss},
};

}  // namespace

std::span<const ElementEntry> linkElementParsers() { return kParsers; }

}  // namespace dabs::tcl
