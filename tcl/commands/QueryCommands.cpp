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
  // A reference when the getter returns one (disp, vel, accel, reaction: no copy a call).
  decltype(auto) v = get(n);
  // OpenSees returns the whole vector for a dof below 1 (SRC/tcl/commands.cpp nodeDisp: dof -1).
  if (!dof || *dof < 1) {
    setResult(rt, v);
    return;
  }
  if (*dof > v.size())
    a.failArgument("dof", "must be 1.." + std::to_string(v.size()) + " (or 0 for all)");
  setResult(rt, v(*dof - 1));
}

void nodeDispCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a, [](const domain::Node& n) -> const Eigen::VectorXd& { return n.disp; });
}
void nodeVelCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a, [](const domain::Node& n) -> const Eigen::VectorXd& { return n.vel; });
}
void nodeAccelCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a, [](const domain::Node& n) -> const Eigen::VectorXd& { return n.accel; });
}
void nodeReactionCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a,
                  [](const domain::Node& n) -> const Eigen::VectorXd& { return n.reaction; });
}
void nodeCoordCmd(Runtime& rt, ArgReader& a) {
  const int ndm = rt.builder.ndm;
  nodeVectorQuery(rt, a, [ndm](const domain::Node& n) {
    return Eigen::VectorXd(n.coords().head(std::max(ndm, 1)));
  });
}
void nodeMassCmd(Runtime& rt, ArgReader& a) {
  nodeVectorQuery(rt, a,
                  [](const domain::Node& n) { return Eigen::VectorXd(n.mass().diagonal()); });
}

void nodeEigenvectorCmd(Runtime& rt, ArgReader& a) {
  const domain::Node& n = rt.domain.node(a.integer("node"));
  const int mode = a.integer("mode");
  const auto dof = a.optionalInteger("dof");
  a.finish();
  if (mode < 1 || mode > n.eigenvectors.cols())
    a.failArgument("mode",
                   "must be 1.." + std::to_string(n.eigenvectors.cols()) + " (run eigen first)");
  const Eigen::VectorXd v = n.eigenvectors.col(mode - 1);
  if (!dof) {
    setResult(rt, v);
    return;
  }
  if (*dof < 1 || *dof > v.size()) a.failArgument("dof", "must be 1.." + std::to_string(v.size()));
  setResult(rt, v(*dof - 1));
}

void reactionsCmd(Runtime& rt, ArgReader& a) {
  const bool dynamic = a.flag("-dynamic");
  // OpenSees' -rayleigh adds the damping forces without the inertia forces; the domain computes
  // reactions with both (-dynamic) or neither, so the option is refused rather than ignored.
  if (a.flag("-rayleigh"))
    a.fail(
        "-rayleigh (damping forces without inertia) is not supported; use -dynamic for reactions "
        "with inertia and damping forces");
  a.finish();
  rt.domain.calculateNodalReactions(dynamic);
}

void eleResponseCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  std::vector<std::string> args;
  while (a.hasMore()) args.push_back(a.word("response"));
  const elements::Element* e = rt.domain.findElement(tag);
  if (e == nullptr) a.failArgument("eleTag", "element " + std::to_string(tag) + " does not exist");
  if (args.empty()) a.fail("needs a response name");
  const auto r = rt.domain.elementResponse(tag, args);
  if (!r) {
    std::string what;
    for (const auto& w : args) what += (what.empty() ? "" : " ") + w;
    a.failArgument("response", "\"" + what + "\" is not a response of element " +
                                   std::to_string(tag) + " (" + std::string(e->typeName()) + ")");
  }
  setResult(rt, *r);
}

void eleForceCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  const auto dof = a.optionalInteger("dof");
  a.finish();
  if (rt.domain.findElement(tag) == nullptr)
    a.failArgument("eleTag", "element " + std::to_string(tag) + " does not exist");
  const Eigen::VectorXd f = rt.domain.elementForce(tag);
  if (!dof) {
    setResult(rt, f);
    return;
  }
  if (*dof < 1 || *dof > f.size()) a.failArgument("dof", "must be 1.." + std::to_string(f.size()));
  setResult(rt, f(*dof - 1));
}

void eleNodesCmd(Runtime& rt, ArgReader& a) {
  const int tag = a.integer("eleTag");
  a.finish();
  const elements::Element* e = rt.domain.findElement(tag);
  if (e == nullptr) a.failArgument("eleTag", "element " + std::to_string(tag) + " does not exist");
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

// A vector as OpenSees' streams write it: each value followed by a space, then a newline.
void writeVector(std::ostream& out, const Eigen::Ref<const Eigen::VectorXd>& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) out << v(i) << " ";
  out << "\n";
}

// One node in the layout of OpenSees' Node::Print (6 significant digits), so scripts and people
// that read `print node` output find the same lines: coordinates, displacements, velocities and
// accelerations once a transient analysis ran, and the mass matrix when the node has mass.
void describeNode(std::ostream& out, const domain::Node& n) {
  out << "\n Node: " << n.tag() << "\n\tCoordinates  : ";
  writeVector(out, n.coords().head(n.ndm()));
  out << "\tDisps: ";
  writeVector(out, n.disp);
  if (!n.vel.isZero(0.0) || !n.accel.isZero(0.0)) {
    out << "\tVelocities   : ";
    writeVector(out, n.vel);
    out << "\tcommitAccels: ";
    writeVector(out, n.accel);
  }
  if (!n.mass().isZero(0.0)) {
    out << "\tMass : \n";
    for (Eigen::Index i = 0; i < n.mass().rows(); ++i)
      writeVector(out, n.mass().row(i).transpose());
    out << "\n";
  }
  out << "\n";
}

// Tags after `node`/`ele` in `print`: an optional `flag n`, then tags; none means all. dabs has
// one layout, OpenSees' default (flag 0); another flag asks for output it cannot give.
std::vector<int> printTags(ArgReader& a, std::string_view what) {
  if (a.hasMore() && (a.peek() == "flag" || a.peek() == "-flag")) {
    (void)a.word("flag word");
    if (a.integer("flag") != 0)
      a.failArgument("flag", "is not supported: only OpenSees' default layout (flag 0)");
  }
  std::vector<int> tags;
  while (a.hasMore()) tags.push_back(a.integer(what));
  return tags;
}

// OpenSees' grammar (SRC/tcl/commands.cpp printModel): `print` prints the whole domain;
// `?-file? fileName` redirects (appending) and alone prints the whole domain to the file;
// `node|-node ?tags?` and `ele|-ele ?tags?` take every following word as a tag.
void printCmd(Runtime& rt, ArgReader& a) {
  std::optional<std::string> target;
  std::optional<std::vector<int>> nodes, eles;
  while (a.hasMore() && !nodes && !eles) {
    const std::string word = a.word("what");
    if (word == "node" || word == "-node")
      nodes = printTags(a, "nodeTag");
    else if (word == "ele" || word == "-ele")
      eles = printTags(a, "eleTag");
    else if (word == "integrator" || word == "-integrator" || word == "algorithm" ||
             word == "-algorithm")
      a.failArgument("what", "is not supported: dabs does not describe its analysis strategies");
    else if (word == "-JSON")
      a.fail("-JSON output is not supported");
    else if (word == "file" || word == "-file")
      target = a.word("fileName");
    else
      target = word;
  }
  a.finish();
  std::ostringstream out;
  if (!nodes && !eles) {
    out << "Domain: " << rt.domain.nodes().size() << " nodes, " << rt.domain.elements().size()
        << " elements, time " << rt.domain.committedTime() << "\n";
    for (const auto& [tag, n] : rt.domain.nodes()) describeNode(out, n);
    for (const auto& [tag, e] : rt.domain.elements()) out << e->describe() << "\n";
  } else if (nodes) {
    if (nodes->empty())
      for (const auto& [tag, n] : rt.domain.nodes()) describeNode(out, n);
    for (int t : *nodes) describeNode(out, rt.domain.node(t));
  } else {
    if (eles->empty())
      for (const auto& [tag, e] : rt.domain.elements()) out << e->describe() << "\n";
    for (int t : *eles) {
      const elements::Element* e = rt.domain.findElement(t);
      if (e == nullptr) a.fail("element " + std::to_string(t) + " does not exist");
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
    {"print", "print ?-file fileName? ?node|-node ?tags..?? ?ele|-ele ?tags..??", printCmd},
    {"printModel", "printModel ?-file fileName? ?node|-node ?tags..?? ?ele|-ele ?tags..??",
     printCmd},
    {"version", "version", versionCmd},
};

}  // namespace

std::span<const CommandEntry> queryCommands() { return kCommands; }

}  // namespace dabs::tcl
