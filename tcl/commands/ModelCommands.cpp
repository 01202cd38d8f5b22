// SPDX-License-Identifier: MIT
// Model-building commands: model, node, mass, fix, fixX/Y/Z, equalDOF, rigidLink, region, and the
// type dispatchers uniaxialMaterial and element.
#include <algorithm>
#include <set>
#include <unordered_set>
#include <cmath>
#include <string>

#include "materials/InputError.h"
#include "tcl/commands/CommandTable.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

void modelCmd(Runtime& rt, ArgReader& a) {
  const std::string kind = a.word("builder");
  if (kind != "basic" && kind != "Basic" && kind != "BasicBuilder")
    a.failArgument("builder", "expected \"basic\"");
  const int ndm = a.option("-ndm", 0);
  if (ndm < 1 || ndm > 3) a.failArgument("-ndm", "must be 1, 2 or 3");
  const int defaultNdf = ndm == 1 ? 1 : ndm == 2 ? 3 : 6;
  const int ndf = a.option("-ndf", defaultNdf);
  if (ndf < 1 || ndf > 6) a.failArgument("-ndf", "must be 1 to 6");
  a.finish();
  rt.builder.ndm = ndm;
  rt.builder.ndf = ndf;
}

void nodeCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("node");
  const int tag = a.integer("tag");
  a.setContext(a.context() + " " + std::to_string(tag));
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int i = 0; i < rt.builder.ndm; ++i) x(i) = a.real(i == 0 ? "x" : i == 1 ? "y" : "z");
  const int ndf = a.option("-ndf", rt.builder.ndf);
  if (ndf < 1 || ndf > 6) a.failArgument("-ndf", "must be 1 to 6");
  const auto mass = a.optionReals("-mass", static_cast<std::size_t>(ndf));
  a.finish();
  if (mass)
    for (double m : *mass)
      if (m < 0.0)
        a.failArgument("-mass", "values must not be negative, one is " + std::to_string(m));
  domain::Node& n = rt.domain.addNode(tag, rt.builder.ndm, ndf, x);
  if (mass) {
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(ndf, ndf);
    for (int i = 0; i < ndf; ++i) m(i, i) = (*mass)[static_cast<std::size_t>(i)];
    n.setMass(m);
  }
}

void massCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("mass");
  domain::Node& n = rt.domain.node(a.integer("node"));
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n.ndf(), n.ndf());
  for (int i = 0; i < n.ndf(); ++i) {
    m(i, i) = a.real("mass");
    if (m(i, i) < 0.0) a.failArgument("mass", "must not be negative");
  }
  a.finish();
  n.setMass(m);
  rt.domain.touch();
}

// Fixes the flagged dofs of one node, all or none.
void fixNode(Runtime& rt, int tag, const std::vector<int>& flags) {
  std::vector<int> added;
  try {
    for (std::size_t d = 0; d < flags.size(); ++d) {
      if (flags[d] == 0) continue;
      rt.domain.addFix(tag, static_cast<int>(d));
      added.push_back(static_cast<int>(d));
    }
  } catch (...) {
    for (int d : added) rt.domain.removeFix(tag, d);
    throw;
  }
}

std::vector<int> readFlags(ArgReader& a, int ndf) {
  std::vector<int> flags;
  for (int i = 0; i < ndf; ++i) {
    const int f = a.integer("constraint flag");
    if (f != 0 && f != 1) a.failArgument("constraint flag", "expected 0 or 1");
    flags.push_back(f);
  }
  return flags;
}

void fixCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("fix");
  const int tag = a.integer("node");
  const domain::Node& n = rt.domain.node(tag);
  const std::vector<int> flags = readFlags(a, n.ndf());
  a.finish();
  fixNode(rt, tag, flags);
}

void fixCoordinate(Runtime& rt, ArgReader& a, int axis) {
  rt.requireModel("fixX");
  if (axis >= rt.builder.ndm)
    a.fail("the model has only " + std::to_string(rt.builder.ndm) + " dimensions");
  const double value = a.real("coordinate");
  std::vector<int> flags;
  while (a.hasPositional()) {
    flags.push_back(a.integer("constraint flag"));
    if (flags.back() != 0 && flags.back() != 1)
      a.failArgument("constraint flag", "expected 0 or 1");
  }
  const double tol = a.option("-tol", 1e-10);
  if (!(tol >= 0.0) || !std::isfinite(tol))
    a.failArgument("-tol", "must be a distance, zero or positive");
  a.finish();
  if (flags.empty()) a.fail("needs constraint flags");
  std::vector<int> fixed;
  try {
    for (const auto& [tag, n] : rt.domain.nodes()) {
      if (std::abs(n.coords()(axis) - value) > tol) continue;
      if (static_cast<int>(flags.size()) != n.ndf())
        throw InputError("flags", "node " + std::to_string(tag) + " has " +
                                      std::to_string(n.ndf()) + " dofs but " +
                                      std::to_string(flags.size()) + " flags were given");
      fixNode(rt, tag, flags);
      fixed.push_back(tag);
    }
  } catch (...) {
    for (int tag : fixed)
      for (std::size_t d = 0; d < flags.size(); ++d)
        if (flags[d] != 0) rt.domain.removeFix(tag, static_cast<int>(d));
    throw;
  }
}

void fixXCmd(Runtime& rt, ArgReader& a) { fixCoordinate(rt, a, 0); }
void fixYCmd(Runtime& rt, ArgReader& a) { fixCoordinate(rt, a, 1); }
void fixZCmd(Runtime& rt, ArgReader& a) { fixCoordinate(rt, a, 2); }

void equalDofCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("equalDOF");
  domain::MPConstraint mp;
  mp.retainedNode = a.integer("rNode");
  mp.constrainedNode = a.integer("cNode");
  std::vector<int> dofs = a.integers("dof");
  a.finish();
  // Checked here, before the constraint's matrix is formed (its size is the list's squared).
  const int ndf =
      std::min(rt.domain.node(mp.retainedNode).ndf(), rt.domain.node(mp.constrainedNode).ndf());
  std::unordered_set<int> seen;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    if (dofs[i] < 1 || dofs[i] > ndf)
      a.failArgument("dof", i, "must be a dof of both nodes, 1 to " + std::to_string(ndf));
    if (!seen.insert(dofs[i]).second) a.failArgument("dof", i, "is given twice");
  }
  for (int& d : dofs) --d;
  mp.constrainedDofs = mp.retainedDofs = dofs;
  mp.Ccr = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(dofs.size()),
                                     static_cast<Eigen::Index>(dofs.size()));
  rt.domain.addMP(std::move(mp));
}

void rigidLinkCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("rigidLink");
  const std::string type = a.word("type");
  if (type != "beam" && type != "bar") a.failArgument("type", "expected beam or bar");
  domain::MPConstraint mp;
  mp.retainedNode = a.integer("rNode");
  mp.constrainedNode = a.integer("cNode");
  a.finish();
  const domain::Node& r = rt.domain.node(mp.retainedNode);
  const domain::Node& c = rt.domain.node(mp.constrainedNode);
  const int ndm = rt.builder.ndm;
  if (r.ndf() != c.ndf()) throw InputError("cNode", "must have as many dofs as rNode");
  const Eigen::Vector3d d = c.coords() - r.coords();
  if (type == "bar") {
    // Translations equal (OpenSees RigidRod).
    for (int i = 0; i < ndm; ++i) mp.constrainedDofs.push_back(i);
    mp.retainedDofs = mp.constrainedDofs;
    mp.Ccr = Eigen::MatrixXd::Identity(ndm, ndm);
  } else if (ndm == 2 && r.ndf() == 3) {
    // u_c = u_r + theta_r x d, theta_c = theta_r (OpenSees RigidBeam, small rotations).
    mp.constrainedDofs = mp.retainedDofs = {0, 1, 2};
    mp.Ccr = Eigen::MatrixXd::Identity(3, 3);
    mp.Ccr(0, 2) = -d.y();
    mp.Ccr(1, 2) = d.x();
  } else if (ndm == 3 && r.ndf() == 6) {
    mp.constrainedDofs = mp.retainedDofs = {0, 1, 2, 3, 4, 5};
    mp.Ccr = Eigen::MatrixXd::Identity(6, 6);
    // theta x d = [ty dz - tz dy, tz dx - tx dz, tx dy - ty dx]
    mp.Ccr(0, 4) = d.z();
    mp.Ccr(0, 5) = -d.y();
    mp.Ccr(1, 3) = -d.z();
    mp.Ccr(1, 5) = d.x();
    mp.Ccr(2, 3) = d.y();
    mp.Ccr(2, 4) = -d.x();
  } else {
    throw InputError("type", "beam needs nodes with 3 dofs in 2D or 6 dofs in 3D");
  }
  rt.domain.addMP(std::move(mp));
}

void regionCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("region");
  (void)a.integer("tag");
  std::vector<int> eles, nodes;
  bool elementsOnly = false;
  if (auto list = a.optionIntegerList("-ele")) eles = *list;
  if (auto list = a.optionIntegerList("-eleOnly")) {
    eles = *list;
    elementsOnly = true;
  }
  // Ranges take the existing tags in them, walking the model's ordered maps (a loop over every
  // integer of `1 2147483647` would take minutes and overflow at its end).
  if (auto range = a.optionTagRange("-eleRange"))
    for (auto it = rt.domain.elements().lower_bound(range->first);
         it != rt.domain.elements().end() && it->first <= range->second; ++it)
      eles.push_back(it->first);
  if (auto list = a.optionIntegerList("-node")) nodes = *list;
  if (auto range = a.optionTagRange("-nodeRange"))
    for (auto it = rt.domain.nodes().lower_bound(range->first);
         it != rt.domain.nodes().end() && it->first <= range->second; ++it)
      nodes.push_back(it->first);
  const auto rayleigh = a.optionReals("-rayleigh", 4);
  a.finish();
  if (rayleigh)
    for (double f : *rayleigh)
      if (f < 0.0)
        a.failArgument("-rayleigh", "factors must not be negative, one is " + std::to_string(f));
  for (int t : eles) {
    const elements::Element* e = rt.domain.findElement(t);
    if (e == nullptr) throw InputError("-ele", "element " + std::to_string(t) + " does not exist");
    if (!elementsOnly)
      for (int n : e->nodeTags()) nodes.push_back(n);
  }
  for (int t : nodes) (void)rt.domain.node(t);
  if (rayleigh) {
    domain::RayleighFactors f{(*rayleigh)[0], (*rayleigh)[1], (*rayleigh)[2], (*rayleigh)[3]};
    rt.domain.setRayleigh(f, eles, nodes);
  }
}

void uniaxialMaterialCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("uniaxialMaterial");
  const std::string type = a.word("type");
  const auto tables = {uniaxialParsers(), contactUniaxialParsers()};
  const UniaxialEntry* entry = findType<UniaxialEntry>(tables, type);
  if (entry == nullptr)
    a.fail(a.positionOf("type"), "type",
           "\"" + type + "\" is not a known material; known: " + typeNames<UniaxialEntry>(tables));
  a.setContext("uniaxialMaterial " + type);
  a.setUsage(std::string(entry->usage));
  const int tag = readNewTag(a, rt.builder.uniaxial, "uniaxialMaterial");
  auto material = entry->parse(rt, a, tag);
  a.finish();
  rt.builder.uniaxial[tag] = std::move(material);
}

void elementCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("element");
  const std::string type = a.word("type");
  const auto tables = {linkElementParsers(), beamElementParsers(), bearingElementParsers(),
                       contactElementParsers()};
  const ElementEntry* entry = findType<ElementEntry>(tables, type);
  if (entry == nullptr)
    a.fail(a.positionOf("type"), "type",
           "\"" + type + "\" is not a known element; known: " + typeNames<ElementEntry>(tables));
  a.setContext("element " + type);
  a.setUsage(std::string(entry->usage));
  const int tag = readNewTag(a, rt.domain.elements(), "element");
  auto element = entry->parse(rt, a, tag);
  a.finish();
  // An element from a node to itself has no length or deformation to work on.
  const std::vector<int>& nodes = element->nodeTags();
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (nodes[i] == nodes[j])
        a.fail("node " + std::to_string(nodes[i]) +
               " is given twice; an element connects distinct nodes");
  rt.domain.addElement(std::move(element));
}

void getNdmCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  setResult(rt, rt.builder.ndm);
}

void getNdfCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  setResult(rt, rt.builder.ndf);
}

// `rigidDiaphragm perpDirn rNode cNode..`: each constrained node moves with the retained node as a
// rigid body in the plane normal to axis perpDirn (1, 2, 3), linearised about the initial geometry
// (OpenSees/OpenSees:SRC/domain/constraints/RigidDiaphragm.cpp): in-plane translations follow
// u_c = u_r + theta_r x d, the in-plane rotation is shared. In 2D with 3 dofs, perpDirn 3 is the
// model plane; perpDirn 1 or 2 ties the translation along that axis only, as OpenSees does.
void rigidDiaphragmCmd(Runtime& rt, ArgReader& a) {
  rt.requireModel("rigidDiaphragm");
  const int perp = a.integer("perpDirn");
  const int rNode = a.integer("rNode");
  const std::vector<int> cNodes = a.integers("cNode");
  a.finish();
  if (perp < 1 || perp > 3) a.failArgument("perpDirn", "must be 1, 2 or 3");
  const domain::Node& r = rt.domain.node(rNode);
  const bool space = r.ndm() == 3 && r.ndf() == 6;
  const bool plane = r.ndm() == 2 && r.ndf() == 3;
  if (!space && !plane)
    a.failArgument("rNode", "must be a 3D node with 6 dofs or a 2D node with 3 dofs");
  std::vector<domain::MPConstraint> constraints;
  std::set<std::pair<int, int>> fixed, constrained;  // (node, dof)
  for (const auto& sp : rt.domain.fixes()) fixed.emplace(sp.node, sp.dof);
  for (const auto& other : rt.domain.mps())
    for (int dof : other.constrainedDofs) constrained.emplace(other.constrainedNode, dof);
  std::unordered_set<int> listed;
  for (std::size_t i = 0; i < cNodes.size(); ++i) {
    const int tag = cNodes[i];
    if (tag == rNode) a.failArgument("cNode", i, "the retained node cannot also be constrained");
    const domain::Node& c = rt.domain.node(tag);
    if (c.ndm() != r.ndm() || c.ndf() != r.ndf())
      a.failArgument("cNode", i,
                     "node " + std::to_string(tag) + " must have the dimension and dofs of rNode");
    const Eigen::Vector3d d = c.coords() - r.coords();
    domain::MPConstraint mp;
    mp.retainedNode = rNode;
    mp.constrainedNode = tag;
    if (plane && perp != 3) {
      mp.constrainedDofs = {perp - 1};
      mp.Ccr = Eigen::MatrixXd::Identity(1, 1);
    } else {
      mp.Ccr = Eigen::MatrixXd::Identity(3, 3);
      if (plane || perp == 3) {  // xy plane: ux, uy, rz
        mp.constrainedDofs = {0, 1, plane ? 2 : 5};
        mp.Ccr(0, 2) = -d.y();
        mp.Ccr(1, 2) = d.x();
      } else if (perp == 2) {  // xz plane: ux, uz, ry
        mp.constrainedDofs = {0, 2, 4};
        mp.Ccr(0, 2) = d.z();
        mp.Ccr(1, 2) = -d.x();
      } else {  // yz plane: uy, uz, rx
        mp.constrainedDofs = {1, 2, 3};
        mp.Ccr(0, 2) = -d.z();
        mp.Ccr(1, 2) = d.y();
      }
    }
    mp.retainedDofs = mp.constrainedDofs;
    // The checks Domain::addMP makes, made for all nodes first so that a bad one adds none
    // (against sets formed once, so that a long list of nodes costs linear time).
    if (!listed.insert(tag).second)
      a.failArgument("cNode", i, "node " + std::to_string(tag) + " is listed twice");
    for (int dof : mp.constrainedDofs) {
      const std::string which =
          "dof " + std::to_string(dof + 1) + " of node " + std::to_string(tag);
      if (fixed.count({tag, dof}) != 0) a.failArgument("cNode", i, which + " is fixed");
      if (constrained.count({tag, dof}) != 0)
        a.failArgument("cNode", i, which + " is already constrained");
    }
    constraints.push_back(std::move(mp));
  }
  for (auto& mp : constraints) rt.domain.addMP(std::move(mp));
}

// `pset name ?value?`: OpenSees' parameter-recording variant of Tcl's `set` (it also lists the
// pair in its simulation information, which dabs does not keep); reads or sets the variable.
void psetCmd(Runtime& rt, ArgReader& a) {
  Tcl_Obj* name = a.object("name");
  Tcl_Obj* value = a.hasMore() ? a.object("value") : nullptr;
  a.finish();
  Tcl_Obj* result = value != nullptr
                        ? Tcl_ObjSetVar2(rt.interp, name, nullptr, value, TCL_LEAVE_ERR_MSG)
                        : Tcl_ObjGetVar2(rt.interp, name, nullptr, TCL_LEAVE_ERR_MSG);
  if (result == nullptr) throw InputError("name", std::string(Tcl_GetStringResult(rt.interp)));
  Tcl_SetObjResult(rt.interp, result);
}

constexpr CommandEntry kCommands[] = {
    {"model", "model basic -ndm ndm ?-ndf ndf?", modelCmd},
    {"node", "node tag x ?y? ?z? ?-mass m1 .. mndf? ?-ndf ndf?", nodeCmd},
    {"mass", "mass node m1 .. mndf", massCmd},
    {"fix", "fix node c1 .. cndf (1 = fixed, 0 = free)", fixCmd},
    {"fixX", "fixX x c1 .. cndf ?-tol tol?", fixXCmd},
    {"fixY", "fixY y c1 .. cndf ?-tol tol?", fixYCmd},
    {"fixZ", "fixZ z c1 .. cndf ?-tol tol?", fixZCmd},
    {"equalDOF", "equalDOF rNode cNode dof1 ?dof2 ...?", equalDofCmd},
    {"rigidLink", "rigidLink beam|bar rNode cNode", rigidLinkCmd},
    {"rigidDiaphragm", "rigidDiaphragm perpDirn rNode cNode1 ?cNode2 ...?", rigidDiaphragmCmd},
    {"region",
     "region tag ?-ele tags? ?-eleOnly tags? ?-eleRange a b? ?-node tags? ?-nodeRange a b? "
     "?-rayleigh aM bK bKinit bKcomm?",
     regionCmd},
    {"uniaxialMaterial", "uniaxialMaterial type tag args...", uniaxialMaterialCmd},
    {"element", "element type tag nodes... args...", elementCmd},
    {"getNDM", "getNDM", getNdmCmd},
    {"getNDF", "getNDF", getNdfCmd},
    {"pset", "pset name ?value?", psetCmd},
};

}  // namespace

std::span<const CommandEntry> modelCommands() { return kCommands; }

}  // namespace dabs::tcl
