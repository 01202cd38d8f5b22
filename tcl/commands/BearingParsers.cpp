// SPDX-License-Identifier: MIT
// Tcl parsers for the bi-axial rubber bearing: the new command family `biaxialMaterial`
// (no OpenSees counterpart; OpenSees' bearings take uniaxial materials per direction and cannot
// couple the two shear directions) and `element yoshidaBearing`.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "elements/link/YoshidaBearing3d.h"
#include "materials/InputError.h"
#include "materials/bearing/YoshidaBearingMaterial.h"
#include "tcl/analysis/driver/AnalysisBuilder.h"
#include "tcl/commands/BearingFailureReport.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace {

constexpr const char* kBiaxialUsage = "biaxialMaterial type tag ...";
constexpr const char* kYoshidaUsage =
    "biaxialMaterial Yoshida tag Y0 U0 n alpha0 beta q gamma ?-maxwell k eta? ?-subIncrement s?";
constexpr const char* kBearingUsage =
    "element yoshidaBearing tag iNode jNode matTag -Tr Tr -Kv Kv ?-Kt Kt? ?-Kr Kr ?Krz?? "
    "?-orient x1 x2 x3 y1 y2 y3? ?-mass m? ?-limits design failure? ?-afterFailure "
    "keep|release|stop|{drop h}? ?-seat Ks mu_s mu_k ?Kst?? ?-vertical kumar G Kbulk Di Do ts tr "
    "n? ?-tc tc? ?-kc kc? ?-phi phi? ?-ac ac? ?-cavitation 0|1? ?-buckling 0|1? ?-kvShear 0|1? "
    "?-pDelta? "
    "(-Tr and -Kv are required without -vertical, not allowed with it)";

// Seat friction when -seat is not given (steel girder end on a concrete pier cap, a round value).
constexpr double kDefaultSeatFriction = 0.5;

// biaxialMaterial Yoshida tag Y0 U0 n alpha0 beta q gamma ?-maxwell k eta? ?-subIncrement s?
// (s: largest backward-Euler sub-step of the hysteretic part, as a fraction of U0; default 0.02)
std::unique_ptr<materials::BiaxialMaterial> parseYoshida(ArgReader& args, int tag) {
  materials::YoshidaBearingMaterial::Params p;
  p.Y0 = args.real("Y0");
  p.U0 = args.real("U0");
  p.n = args.real("n");
  p.alpha0 = args.real("alpha0");
  p.beta = args.real("beta");
  p.q = args.real("q");
  p.gamma = args.real("gamma");
  if (auto maxwell = args.optionReals("-maxwell", 2)) {
    p.k = (*maxwell)[0];
    p.eta = (*maxwell)[1];
  }
  p.maxSubIncrement = args.option("-subIncrement", p.maxSubIncrement);
  args.finish();
  p.validate();
  return std::make_unique<materials::YoshidaBearingMaterial>(tag, p);
}

// biaxialMaterial type tag ...: dispatch on the type word, as `uniaxialMaterial` does.
void biaxialMaterialCommand(Runtime& rt, ArgReader& args) {
  rt.requireModel("biaxialMaterial");
  args.setUsage(kBiaxialUsage);
  const std::string type = args.word("type");
  if (type != "Yoshida")
    args.failArgument("type", "is not a known biaxialMaterial (expected Yoshida)");
  args.setUsage(kYoshidaUsage);
  args.setContext("biaxialMaterial " + type);
  const int tag = readNewTag(args, rt.builder.biaxial, "biaxialMaterial");
  auto material = parseYoshida(args, tag);
  rt.builder.biaxial[tag] = std::move(material);
  Tcl_SetObjResult(rt.interp, Tcl_NewIntObj(tag));
}

// A 0|1 switch of -vertical kumar (default 1).
bool readSwitch(ArgReader& args, std::string_view key) {
  const int v = args.option(key, 1);
  if (v != 0 && v != 1) args.failArgument(key, "expected 0 or 1");
  return v == 1;
}

// -vertical kumar G Kbulk Di Do ts tr n and its options (Kumar et al. 2014; see KumarVertical.h).
void readVertical(ArgReader& args, elements::YoshidaBearing3d::Params& p) {
  static constexpr std::array<const char*, 7> kOptions{"-tc",         "-kc",       "-phi",    "-ac",
                                                       "-cavitation", "-buckling", "-kvShear"};
  const auto law = args.optionalWordOption("-vertical");
  if (!law) {
    for (const char* key : kOptions)
      if (args.optionalOption(key)) args.failArgument(key, "needs -vertical kumar");
    return;
  }
  if (*law != "kumar") args.failArgument("-vertical", "expected kumar");
  const std::vector<double> v =
      args.realsAfterOption("-vertical", {"G", "Kbulk", "Di", "Do", "ts", "tr", "n"});
  elements::KumarVertical::Params k;
  k.G = v[0];
  k.Kbulk = v[1];
  k.Di = v[2];
  k.Do = v[3];
  k.ts = v[4];
  k.tr = v[5];
  k.n = v[6];
  k.tc = args.option("-tc", k.tc);
  k.kc = args.option("-kc", k.kc);
  k.phi = args.option("-phi", k.phi);
  k.ac = args.option("-ac", k.ac);
  k.cavitation = readSwitch(args, "-cavitation");
  k.buckling = readSwitch(args, "-buckling");
  k.kvShear = readSwitch(args, "-kvShear");
  p.vertical = k;
}

// element yoshidaBearing tag iNode jNode matTag -Tr Tr -Kv Kv ?-Kt Kt? ?-Kr Kr ?Krz??
//   ?-orient x1 x2 x3 y1 y2 y3? ?-mass m? ?-limits design failure? ?-afterFailure
//   keep|release|stop|drop?
// with drop: -afterFailure drop h ?-seat Ks mu_s mu_k ?Kst?? (h the bearing's height; seat
// defaults Ks = Kv, mu_s = mu_k = 0.5, Kst = Ks)
// and -vertical kumar G Kbulk Di Do ts tr n ?-tc tc? ?-kc kc? ?-phi phi? ?-ac ac?
//   ?-cavitation 0|1? ?-buckling 0|1? ?-kvShear 0|1? (the arguments in the order and with the
//   names of OpenSees' ElastomericX; Tr = n tr and Kv0 follow from them) and ?-pDelta?
std::unique_ptr<elements::Element> parseYoshidaBearing(Runtime& rt, ArgReader& args, int tag) {
  using elements::YoshidaBearing3d;
  if (rt.builder.ndm != 3)
    args.fail("needs a 3D model with 6 dofs per node (model basic -ndm 3 -ndf 6)");
  const int iNode = args.integer("iNode");
  const int jNode = args.integer("jNode");
  const int matTag = args.integer("matTag");
  YoshidaBearing3d::Params p;
  const auto tr = args.optionalOption("-Tr");
  const auto kv = args.optionalOption("-Kv");
  p.Kt = args.option("-Kt", 0.0);
  // -Kr Kr: the same rocking stiffness about local y and z; -Kr Kry Krz: one per axis (a pair
  // of bearings under a girder end resists roll far more than the end's bending rotation).
  if (auto kr = args.optionRealList("-Kr")) {
    if (kr->size() > 2)
      args.failArgument(
          "-Kr", 2, "is a third value: -Kr takes one value (both axes) or two (local y, local z)");
    p.Kry = kr->front();
    p.Krz = kr->back();
  }
  if (auto orient = args.optionReals("-orient", 6)) {
    const auto& v = *orient;
    p.orientX = Eigen::Vector3d(v[0], v[1], v[2]);
    p.orientY = Eigen::Vector3d(v[3], v[4], v[5]);
  }
  p.mass = args.option("-mass", 0.0);
  if (auto limits = args.optionReals("-limits", 2)) {
    p.designLimit = (*limits)[0];
    p.failureLimit = (*limits)[1];
  }
  if (auto after = args.optionalWordOption("-afterFailure")) {
    if (*after == "keep")
      p.afterFailure = YoshidaBearing3d::AfterFailure::Keep;
    else if (*after == "release")
      p.afterFailure = YoshidaBearing3d::AfterFailure::Release;
    else if (*after == "stop")
      p.afterFailure = YoshidaBearing3d::AfterFailure::Stop;
    else if (*after == "drop") {
      p.afterFailure = YoshidaBearing3d::AfterFailure::Drop;
      p.seat.h = args.realAfterOption("-afterFailure", "h");
    } else
      args.failArgument("-afterFailure", "expected keep, release, stop or drop");
  }
  const auto seat = args.optionRealList("-seat");
  if (seat) {
    if (p.afterFailure != YoshidaBearing3d::AfterFailure::Drop)
      args.failArgument("-seat", "needs -afterFailure drop h");
    if (seat->size() < 3)
      args.failArgument("-seat", "expected 3 or 4 numbers after -seat (Ks mu_s mu_k ?Kst?)");
    if (seat->size() > 4)
      args.failArgument("-seat", 4,
                        "is a fifth value: -seat takes Ks mu_s mu_k and optionally Kst");
  }
  readVertical(args, p);
  // -pDelta: the P-Delta end moments of the axial force, as OpenSees' ElastomericX adds them.
  p.pDelta = args.flag("-pDelta");
  args.finish();
  if (p.vertical) {
    // One source for Tr and Kv: the geometry of -vertical kumar.
    if (tr) args.failArgument("-Tr", "is not allowed with -vertical kumar (Tr = n tr)");
    if (kv)
      args.failArgument("-Kv",
                        "is not allowed with -vertical kumar (Kv0 = Ec A / Tr from G, Kbulk "
                        "and the geometry)");
    // The law's Tr and Kv0 (the element takes the same), so defaults that follow Kv (the seat's
    // Ks) follow Kv0.
    p.vertical->validate();
    const elements::KumarVertical law(*p.vertical);
    p.Tr = law.Tr();
    p.Kv = law.Kv0();
  } else {
    if (!tr) args.fail("-Tr (total rubber thickness) is required");
    if (!kv) args.fail("-Kv (axial stiffness) is required");
    p.Tr = *tr;
    p.Kv = *kv;
  }
  if (p.afterFailure == YoshidaBearing3d::AfterFailure::Drop) {
    p.seat.Ks = seat ? (*seat)[0] : p.Kv;
    p.seat.muS = seat ? (*seat)[1] : kDefaultSeatFriction;
    p.seat.muK = seat ? (*seat)[2] : kDefaultSeatFriction;
    p.seat.Kst = seat && seat->size() == 4 ? (*seat)[3] : p.seat.Ks;
  }
  try {
    p.validate();
  } catch (const InputError& e) {
    // The seat's fields share -seat: point at the value the error is about.
    static constexpr std::array<const char*, 4> kSeatFields{"Ks", "mu_s", "mu_k", "Kst"};
    for (std::size_t k = 0; k < kSeatFields.size(); ++k)
      if (seat && k < seat->size() && e.field() == kSeatFields[k])
        args.failArgument("-seat", k, e.what());
    throw;
  }
  const materials::BiaxialMaterial& material = rt.builder.biaxialMaterial(matTag);
  auto bearing = std::make_unique<YoshidaBearing3d>(tag, iNode, jNode, material, p);
  // The analysis knows no bearing: the rupture report is a step observer, one per interpreter
  // (it finds every bearing of the domain), kept through wipe like the analysis' observers.
  if (rt.bearingFailureReport == nullptr)
    rt.bearingFailureReport =
        &rt.analysis->addStepObserver(std::make_unique<BearingFailureReport>());
  return bearing;
}

constexpr std::array kBearingCommands{
    CommandEntry{"biaxialMaterial", kYoshidaUsage, biaxialMaterialCommand},
};

constexpr std::array kBearingElements{
    ElementEntry{"yoshidaBearing", kBearingUsage, parseYoshidaBearing},
};

}  // namespace

std::span<const CommandEntry> bearingCommands() { return kBearingCommands; }
std::span<const ElementEntry> bearingElementParsers() { return kBearingElements; }

}  // namespace dabs::tcl
