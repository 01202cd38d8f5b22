// SPDX-License-Identifier: MIT
// Query commands: node*/ele* responses, reactions, tags, print, version.
#include <fstream>
#include <sstream>
#include <string>

#include "materials/InputError.h"
#include "tcl/commands/Registry.h"
#include "tcl/commands/TclResult.h"

namespace dabs::tcl {

namespace {

// nodeDisp-like commands: `cmd node ?dof?` returns all dofs as a list or one value.
template <class Getter>
void nodeVectorQuery(Runtime& rt, ArgReader& a, Getter get) {
  const domain::Node& n = rt.domain.node(a.integer("node"));
  const auto dof = a.optionalInteger("dof");
  a.finish();
  const Eigen::VectorXd v = get(n);
  if (!dof) {
    setResult(rt, v);
    return;
  }
  if (*dof < 1 || *dof > v.size()) a.fail(2, "dof", "must be 1.." + std::to_string(v.size()));
  setResult(rt, v(*dof - 1));
}

void nodeDispCmd(Runtime& rt, ArgReader& a) { nodeVectorQuery(rt, a, [](const domain::Node& n) { return n.disp; }); }
void nodeVelCmd(Runtime& rt, ArgReader& a) { nodeVectorQuery(rt, a, [](const domain::Node& n) { return n.vel; }); }
void nodeAccelCmd(Runtime& rt, ArgReader& a) { nodeVectorQuery(rt, a, [](const domain::Node& n) { return n.accel; }); }
void nodeReactionCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a, [](const domain::Node& n) { return n.reaction; });
}
void nodeCoordCmd(Runtime& rt, ArgReader& a) {
  const int ndm = rt.builder.ndm;
  nodeVectorQuery(rt, a, [ndm](const domain::Node& n) { return Eigen::VectorXd(n.coords().head(std::max(ndm, 1))); });
}
void nodeMassCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a, [](const domain::Node& n) { return Eigen::VectorXd(n.mass().diagonal()); });
}

void nodeEigenvectorCmd(Runtime& rt, ArgReader& a) {
  const domain::Node& n = rt.domain.node(a.integer("node"));
  const int mode = a.integer("mode");
  const auto dof = a.optionalInteger("dof");
  a.finish();
  if (mode < 1 || mode > n.eigenvectors.cols())
    a.fail(2, "mode", "must be 1.." + std::to_string(n.eigenvectors.cols()) + " (run eigen first)");
  const Eigen::VectorXd v = n.eigenvectors.col(mode - 1);
  if (!dof) {
    setResult(rt, v);
    return;
  }
  if (*dof < 1 || *dof > v.size()) a.fail(3, "dof", "must be 1.." + std::to_string(v.size()));
  setResult(rt, v(*dof - 1));
}

void reactionsCmd(Runtime& rt, ArgReader& a) {
  const bool dynamic = a.flag("-dynamic");
  (void)a.flag("-rayleigh");
  a.finish();
  rt.domain.calculateNodalReactions(dynamic);
}

void eleResponseCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  std::vector<std::string> args;
  while (a.hasMore()) args.push_back(a.word("response"));
  const elements::Element* e = rt.domain.findElement(tag);
  if (e == nullptr) a.fail(1, "eleTag", "element " + std::to_string(tag) + " does not exist");
  if (args.empty()) a.fail("needs a response name");
  const auto r = rt.domain.elementResponse(tag, args);
  if (!r) {
    std::string what;
    for (const auto& w : args) what += (what.empty() ? "" : " ") + w;
    a.fail(2, "response", "\"" + what + "\" is not a response of element " + std::to_string(tag) +
                              " (" + std::string(e->typeName()) + ")");
  }
  setResult(rt, *r);
}

void eleForceCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  const auto dof = a.optionalInteger("dof");
  a.finish();
  const elements::Element* e = rt.domain.findElement(tag);
  if (e == nullptr) a.fail(1, "eleTag", "element " + std::to_string(tag) + " does not exist");
  const Eigen::VectorXd f = e->resistingForce();
  if (!dof) {
    setResult(rt, f);
    return;
  }
  if (*dof < 1 || *dof > f.size()) a.fail(2, "dof", "must be 1.." + std::to_string(f.size()));
  setResult(rt, f(*dof - 1));
}

void eleNodesCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  a.finish();
  const elements::Element* e = rt.domain.findElement(tag);
  if (e == nullptr) a.fail(1, "eleTag", "element " + std::to_string(tag) + " does not exist");
  setResult(rt, e->nodeTags());
}

void getNodeTagsCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  std::vector<int> tags;
  for (const auto& [tag, n] : rt.domain.nodes()) tags.push_back(tag);
  setResult(rt, tags);
}

void getEleTagsCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  std::vector<int> tags;
  for (const auto& [tag, e] : rt.domain.elements()) tags.push_back(tag);
  setResult(rt, tags);
}

std::string describeNode(const domain::Node& n) {
  std::ostringstream out;
  out << "Node " << n.tag() << " ndf " << n.ndf() << " coords";
  for (int i = 0; i < n.ndm(); ++i) out << " " << n.coords()(i);
  out << " disp";
  for (Eigen::Index i = 0; i < n.disp.size(); ++i) out << " " << n.disp(i);
  if (!n.mass().isZero(0.0)) {
    out << " mass";
    for (Eigen::Index i = 0; i < n.mass().rows(); ++i) out << " " << n.mass()(i, i);
  }
  return out.str();
}

void printCmd(Runtime& rt, ArgReader& a) {
  const auto nodes = a.optionIntegerList("-node");
  const auto eles = a.optionIntegerList("-ele");
  const auto file = a.optionalWordOption("-file");
  std::optional<std::string> target = file;
  if (!target && a.hasPositional()) target = a.word("fileName");
  a.finish();
  std::ostringstream out;
  const bool all = !nodes && !eles;
  if (all) {
    out << "Domain: " << rt.domain.nodes().size() << " nodes, " << rt.domain.elements().size()
        << " elements, time " << rt.domain.committedTime() << "\n";
    for (const auto& [tag, n] : rt.domain.nodes()) out << describeNode(n) << "\n";
    for (const auto& [tag, e] : rt.domain.elements()) out << e->describe() << "\n";
  } else {
    if (nodes)
      for (int t : *nodes) out << describeNode(rt.domain.node(t)) << "\n";
    if (eles)
      for (int t : *eles) {
        const elements::Element* e = rt.domain.findElement(t);
        if (e == nullptr) throw InputError("-ele", "element " + std::to_string(t) + " does not exist");
        out << e->describe() << "\n";
      }
  }
  const std::string text = out.str();
  if (target) {
    std::ofstream f(*target, std::ios::app);
    if (!f) throw InputError("fileName", "cannot write \"" + *target + "\"");
    f << text;
    return;
  }
  Tcl_Channel chan = Tcl_GetStdChannel(TCL_STDOUT);
  if (chan != nullptr) Tcl_WriteChars(chan, text.c_str(), static_cast<int>(text.size()));
}

void versionCmd(Runtime& rt, ArgReader& a) {
  a.finish();
  setResult(rt, std::string("dabs 0.1.0"));
}

constexpr CommandEntry kCommands[] = {
    {"nodeDisp", "nodeDisp node ?dof?", nodeDispCmd},
    {"nodeVel", "nodeVel node ?dof?", nodeVelCmd},
    {"nodeAccel", "nodeAccel node ?dof?", nodeAccelCmd},
    {"nodeReaction", "nodeReaction node ?dof? (after `reactions`)", nodeReactionCmd},
    {"nodeCoord", "nodeCoord node ?dim?", nodeCoordCmd},
    {"nodeMass", "nodeMass node ?dof?", nodeMassCmd},
    {"nodeEigenvector", "nodeEigenvector node mode ?dof?", nodeEigenvectorCmd},
    {"reactions", "reactions ?-dynamic?", reactionsCmd},
    {"eleResponse", "eleResponse eleTag response ?args...?", eleResponseCmd},
    {"eleForce", "eleForce eleTag ?dof?", eleForceCmd},
    {"eleNodes", "eleNodes eleTag", eleNodesCmd},
    {"getNodeTags", "getNodeTags", getNodeTagsCmd},
    {"getEleTags", "getEleTags", getEleTagsCmd},
    {"print", "print ?-node tags? ?-ele tags? ?fileName?", printCmd},
    {"printModel", "printModel ?-node tags? ?-ele tags? ?fileName?", printCmd},
    {"version", "version", versionCmd},
};

}  // namespace

std::span<const CommandEntry> queryCommands() { return kCommands; }

}  // namespace dabs::tcl
