// SPDX-License-Identifier: MIT
// `uniaxialMaterial TYPE tag ...` for the uniaxial material library, with OpenSees' argument
// order and defaults (OpenSees/OpenSees:SRC/material/uniaxial/*.cpp, the OPS_* parsers).

#include "tcl/commands/UniaxialParsers.h"

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "materials/Concrete01.h"
#include "materials/Concrete02.h"
#include "materials/ENT.h"
#include "materials/Elastic.h"
#include "materials/ElasticPP.h"
#include "materials/ElasticPPGap.h"
#include "materials/Fatigue.h"
#include "materials/InputError.h"
#include "materials/Parallel.h"
#include "materials/Series.h"
#include "materials/Steel01.h"
#include "materials/Steel02.h"
#include "materials/Viscous.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace uniaxial {
namespace {

using namespace dabs::materials;

/// Either all of `names` follow (as numbers) or none does; true when they did.
bool optionalGroup(ArgReader& args, std::initializer_list<double*> out,
                   std::initializer_list<const char*> names) {
  if (!args.hasPositional()) return false;
  auto value = out.begin();
  for (const char* name : names) **value++ = args.real(name);
  return true;
}

/// Reads the component tags of Parallel/Series and looks each prototype up.
std::vector<const UniaxialMaterial*> readComponents(ArgReader& args,
                                                    const domain::ModelBuilder& builder,
                                                    std::size_t atLeast) {
  const std::vector<int> tags = args.integers("matTag", atLeast);
  std::vector<const UniaxialMaterial*> out;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    try {
      out.push_back(&builder.uniaxialMaterial(tags[i]));
    } catch (const InputError&) {
      args.failArgument("matTag", i,
                        "uniaxialMaterial " + std::to_string(tags[i]) + " does not exist");
    }
  }
  return out;
}

}  // namespace

MaterialPtr parseElastic(ArgReader& args, int tag) {
  Elastic::Params p;
  p.E = args.real("E");
  p.eta = args.optionalReal("eta").value_or(0.0);
  p.Eneg = args.optionalReal("Eneg");
  args.finish();
  p.validate();
  return std::make_unique<Elastic>(tag, p);
}

MaterialPtr parseElasticPP(ArgReader& args, int tag) {
  ElasticPP::Params p;
  p.E = args.real("E");
  p.epsyP = args.real("epsyP");
  p.epsyN = args.optionalReal("epsyN");
  p.eps0 = args.optionalReal("eps0").value_or(0.0);
  args.finish();
  p.validate();
  return std::make_unique<ElasticPP>(tag, p);
}

MaterialPtr parseElasticPPGap(ArgReader& args, int tag) {
  ElasticPPGap::Params p;
  p.E = args.real("E");
  p.Fy = args.real("Fy");
  p.gap = args.real("gap");
  auto isDamage = [&] { return args.peek() == "damage" || args.peek() == "Damage"; };
  if (!isDamage()) p.eta = args.optionalReal("eta").value_or(0.0);
  if (isDamage()) {
    args.word("damage");
    p.damage = true;
  }
  args.finish();
  p.validate();
  return std::make_unique<ElasticPPGap>(tag, p);
}

MaterialPtr parseSteel01(ArgReader& args, int tag) {
  Steel01::Params p;
  p.Fy = args.real("Fy");
  p.E0 = args.real("E0");
  p.b = args.real("b");
  optionalGroup(args, {&p.a1, &p.a2, &p.a3, &p.a4}, {"a1", "a2", "a3", "a4"});
  args.finish();
  p.validate();
  return std::make_unique<Steel01>(tag, p);
}

MaterialPtr parseSteel02(ArgReader& args, int tag) {
  Steel02::Params p;
  p.Fy = args.real("Fy");
  p.E = args.real("E");
  p.b = args.real("b");
  if (optionalGroup(args, {&p.R0, &p.cR1, &p.cR2}, {"R0", "cR1", "cR2"})) {
    if (optionalGroup(args, {&p.a1, &p.a2, &p.a3, &p.a4}, {"a1", "a2", "a3", "a4"}))
      p.sigInit = args.optionalReal("sigInit").value_or(0.0);
  }
  args.finish();
  p.validate();
  return std::make_unique<Steel02>(tag, p);
}

MaterialPtr parseConcrete01(ArgReader& args, int tag) {
  Concrete01::Params p;
  p.fpc = args.real("fpc");
  p.epsc0 = args.real("epsc0");
  p.fpcu = args.real("fpcu");
  p.epsU = args.real("epsU");
  args.finish();
  p.validate();
  return std::make_unique<Concrete01>(tag, p);
}

MaterialPtr parseConcrete02(ArgReader& args, int tag) {
  const double fpc = args.real("fpc");
  const double epsc0 = args.real("epsc0");
  const double fpcu = args.real("fpcu");
  const double epsU = args.real("epsU");
  auto p = Concrete02::Params::withDefaults(fpc, epsc0, fpcu, epsU);
  optionalGroup(args, {&p.lambda, &p.ft, &p.Ets}, {"lambda", "ft", "Ets"});
  args.finish();
  p.validate();
  return std::make_unique<Concrete02>(tag, p);
}

MaterialPtr parseViscous(ArgReader& args, int tag) {
  Viscous::Params p;
  p.C = args.real("C");
  p.alpha = args.real("alpha");
  p.minVel = args.optionalReal("minVel").value_or(p.minVel);
  args.finish();
  p.validate();
  return std::make_unique<Viscous>(tag, p);
}

MaterialPtr parseENT(ArgReader& args, int tag) {
  ENT::Params p;
  p.E = args.real("E");
  args.finish();
  p.validate();
  return std::make_unique<ENT>(tag, p);
}

MaterialPtr parseParallel(ArgReader& args, int tag, const domain::ModelBuilder& builder) {
  Parallel::Params p;
  p.components = readComponents(args, builder, 1);
  if (auto f = args.optionRealList("-factors")) p.factors = std::move(*f);
  args.finish();
  p.validate();
  return std::make_unique<Parallel>(tag, p);
}

MaterialPtr parseSeries(ArgReader& args, int tag, const domain::ModelBuilder& builder) {
  Series::Params p;
  p.components = readComponents(args, builder, 2);
  args.finish();
  p.validate();
  return std::make_unique<Series>(tag, p);
}

MaterialPtr parseFatigue(ArgReader& args, int tag, const domain::ModelBuilder& builder) {
  Fatigue::Params p;
  const int matTag = args.integer("matTag");
  try {
    p.material = &builder.uniaxialMaterial(matTag);
  } catch (const InputError&) {
    args.failArgument("matTag", "uniaxialMaterial " + std::to_string(matTag) + " does not exist");
  }
  // OpenSees' option names and defaults (OpenSees/OpenSees:SRC/material/uniaxial/
  // FatigueMaterial.cpp, OPS_FatigueMaterial); unknown options are refused, not skipped.
  p.E0 = args.option("-E0", p.E0);
  p.m = args.option("-m", p.m);
  p.minStrain = args.option("-min", p.minStrain);
  p.maxStrain = args.option("-max", p.maxStrain);
  p.Dmax = args.option("-Dmax", p.Dmax);
  args.finish();
  p.validate();
  return std::make_unique<Fatigue>(tag, p);
}

}  // namespace uniaxial

namespace {

template <uniaxial::MaterialPtr (*Parse)(ArgReader&, int)>
uniaxial::MaterialPtr plain(Runtime& /*rt*/, ArgReader& args, int tag) {
  return Parse(args, tag);
}
template <uniaxial::MaterialPtr (*Parse)(ArgReader&, int, const domain::ModelBuilder&)>
uniaxial::MaterialPtr composite(Runtime& rt, ArgReader& args, int tag) {
  return Parse(args, tag, rt.builder);
}

constexpr UniaxialEntry kRows[] = {
    {"Elastic", "uniaxialMaterial Elastic tag E ?eta? ?Eneg?", &plain<uniaxial::parseElastic>},
    {"ElasticPP", "uniaxialMaterial ElasticPP tag E epsyP ?epsyN? ?eps0?",
     &plain<uniaxial::parseElasticPP>},
    {"ElasticPPGap", "uniaxialMaterial ElasticPPGap tag E Fy gap ?eta? ?damage?",
     &plain<uniaxial::parseElasticPPGap>},
    {"Steel01", "uniaxialMaterial Steel01 tag Fy E0 b ?a1 a2 a3 a4?",
     &plain<uniaxial::parseSteel01>},
    {"Steel02", "uniaxialMaterial Steel02 tag Fy E b ?R0 cR1 cR2? ?a1 a2 a3 a4? ?sigInit?",
     &plain<uniaxial::parseSteel02>},
    {"Concrete01", "uniaxialMaterial Concrete01 tag fpc epsc0 fpcu epsU",
     &plain<uniaxial::parseConcrete01>},
    {"Concrete02", "uniaxialMaterial Concrete02 tag fpc epsc0 fpcu epsU ?lambda ft Ets?",
     &plain<uniaxial::parseConcrete02>},
    {"Viscous", "uniaxialMaterial Viscous tag C alpha ?minVel?", &plain<uniaxial::parseViscous>},
    {"ENT", "uniaxialMaterial ENT tag E", &plain<uniaxial::parseENT>},
    {"Parallel", "uniaxialMaterial Parallel tag matTag1 matTag2 ... ?-factors f1 f2 ...?",
     &composite<uniaxial::parseParallel>},
    {"Series", "uniaxialMaterial Series tag matTag1 matTag2 ...",
     &composite<uniaxial::parseSeries>},
    {"Fatigue",
     "uniaxialMaterial Fatigue tag matTag ?-E0 E0? ?-m m? ?-min min? ?-max max? ?-Dmax D?",
     &composite<uniaxial::parseFatigue>},
};

}  // namespace

std::span<const UniaxialEntry> uniaxialParsers() { return kRows; }

}  // namespace dabs::tcl
