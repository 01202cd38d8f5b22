// SPDX-License-Identifier: MIT
// `uniaxialMaterial TYPE tag ...` for the uniaxial material library, with OpenSees' argument
// order and defaults (OpenSees/OpenSees:SRC/material/uniaxial/*.cpp, the OPS_* parsers).

#include "tcl/commands/UniaxialParsers.h"

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

/// Reads values while remembering where each named value stood, so that an InputError from
/// Params::validate() is reported at the argument the user typed.
class Tracker {
 public:
  explicit Tracker(ArgReader& args) : args_(args) {}

  double real(const char* name) {
    const double v = args_.real(name);
    positions_.emplace_back(name, args_.lastPosition());
    return v;
  }
  std::optional<double> optionalReal(const char* name) {
    auto v = args_.optionalReal(name);
    if (v) positions_.emplace_back(name, args_.lastPosition());
    return v;
  }
  /// Either all of `names` follow (as numbers) or none does.
  bool optionalGroup(std::initializer_list<double*> out, std::initializer_list<const char*> names) {
    if (!args_.hasPositional()) return false;
    auto value = out.begin();
    for (const char* name : names) **value++ = real(name);
    return true;
  }
  /// Validates `p`; an InputError becomes an ArgError at the offending argument.
  template <class P>
  void validate(const P& p) {
    try {
      p.validate();
    } catch (const InputError& e) {
      for (const auto& [name, pos] : positions_)
        if (name == e.field()) args_.fail(pos, name, e.reason());
      args_.fail(e.what());
    }
  }

 private:
  ArgReader& args_;
  std::vector<std::pair<std::string, std::size_t>> positions_;
};

/// Reads the component tags of Parallel/Series and looks each prototype up.
std::vector<const UniaxialMaterial*> readComponents(ArgReader& args,
                                                    const domain::ModelBuilder& builder,
                                                    std::size_t atLeast) {
  const std::vector<int> tags = args.integers("matTag", atLeast);
  const std::size_t first = args.lastPosition() + 1 - tags.size();
  std::vector<const UniaxialMaterial*> out;
  for (std::size_t i = 0; i < tags.size(); ++i) {
    try {
      out.push_back(&builder.uniaxialMaterial(tags[i]));
    } catch (const InputError&) {
      args.fail(first + i, "matTag", "uniaxialMaterial " + std::to_string(tags[i]) + " does not exist");
    }
  }
  return out;
}

}  // namespace

MaterialPtr parseElastic(ArgReader& args, int tag) {
  Tracker t(args);
  Elastic::Params p;
  p.E = t.real("E");
  p.eta = t.optionalReal("eta").value_or(0.0);
  p.Eneg = t.optionalReal("Eneg");
  args.finish();
  t.validate(p);
  return std::make_unique<Elastic>(tag, p);
}

MaterialPtr parseElasticPP(ArgReader& args, int tag) {
  Tracker t(args);
  ElasticPP::Params p;
  p.E = t.real("E");
  p.epsyP = t.real("epsyP");
  p.epsyN = t.optionalReal("epsyN");
  p.eps0 = t.optionalReal("eps0").value_or(0.0);
  args.finish();
  t.validate(p);
  return std::make_unique<ElasticPP>(tag, p);
}

MaterialPtr parseElasticPPGap(ArgReader& args, int tag) {
  Tracker t(args);
  ElasticPPGap::Params p;
  p.E = t.real("E");
  p.Fy = t.real("Fy");
  p.gap = t.real("gap");
  auto isDamage = [&] { return args.peek() == "damage" || args.peek() == "Damage"; };
  if (!isDamage()) p.eta = t.optionalReal("eta").value_or(0.0);
  if (isDamage()) {
    args.word("damage");
    p.damage = true;
  }
  args.finish();
  t.validate(p);
  return std::make_unique<ElasticPPGap>(tag, p);
}

MaterialPtr parseSteel01(ArgReader& args, int tag) {
  Tracker t(args);
  Steel01::Params p;
  p.Fy = t.real("Fy");
  p.E0 = t.real("E0");
  p.b = t.real("b");
  t.optionalGroup({&p.a1, &p.a2, &p.a3, &p.a4}, {"a1", "a2", "a3", "a4"});
  args.finish();
  t.validate(p);
  return std::make_unique<Steel01>(tag, p);
}

MaterialPtr parseSteel02(ArgReader& args, int tag) {
  Tracker t(args);
  Steel02::Params p;
  p.Fy = t.real("Fy");
  p.E = t.real("E");
  p.b = t.real("b");
  if (t.optionalGroup({&p.R0, &p.cR1, &p.cR2}, {"R0", "cR1", "cR2"})) {
    if (t.optionalGroup({&p.a1, &p.a2, &p.a3, &p.a4}, {"a1", "a2", "a3", "a4"}))
      p.sigInit = t.optionalReal("sigInit").value_or(0.0);
  }
  args.finish();
  t.validate(p);
  return std::make_unique<Steel02>(tag, p);
}

MaterialPtr parseConcrete01(ArgReader& args, int tag) {
  Tracker t(args);
  Concrete01::Params p;
  p.fpc = t.real("fpc");
  p.epsc0 = t.real("epsc0");
  p.fpcu = t.real("fpcu");
  p.epsU = t.real("epsU");
  args.finish();
  t.validate(p);
  return std::make_unique<Concrete01>(tag, p);
}

MaterialPtr parseConcrete02(ArgReader& args, int tag) {
  Tracker t(args);
  const double fpc = t.real("fpc");
  const double epsc0 = t.real("epsc0");
  const double fpcu = t.real("fpcu");
  const double epsU = t.real("epsU");
  auto p = Concrete02::Params::withDefaults(fpc, epsc0, fpcu, epsU);
  t.optionalGroup({&p.lambda, &p.ft, &p.Ets}, {"lambda", "ft", "Ets"});
  args.finish();
  t.validate(p);
  return std::make_unique<Concrete02>(tag, p);
}

MaterialPtr parseViscous(ArgReader& args, int tag) {
  Tracker t(args);
  Viscous::Params p;
  p.C = t.real("C");
  p.alpha = t.real("alpha");
  p.minVel = t.optionalReal("minVel").value_or(p.minVel);
  args.finish();
  t.validate(p);
  return std::make_unique<Viscous>(tag, p);
}

MaterialPtr parseENT(ArgReader& args, int tag) {
  Tracker t(args);
  ENT::Params p;
  p.E = t.real("E");
  args.finish();
  t.validate(p);
  return std::make_unique<ENT>(tag, p);
}

MaterialPtr parseParallel(ArgReader& args, int tag, const domain::ModelBuilder& builder) {
  Parallel::Params p;
  p.components = readComponents(args, builder, 1);
  if (auto f = args.optionRealList("-factors")) p.factors = std::move(*f);
  args.finish();
  try {
    p.validate();
  } catch (const InputError& e) {
    args.fail(e.what());
  }
  return std::make_unique<Parallel>(tag, p);
}

MaterialPtr parseSeries(ArgReader& args, int tag, const domain::ModelBuilder& builder) {
  Series::Params p;
  p.components = readComponents(args, builder, 2);
  args.finish();
  try {
    p.validate();
  } catch (const InputError& e) {
    args.fail(e.what());
  }
  return std::make_unique<Series>(tag, p);
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
    {"Series", "uniaxialMaterial Series tag matTag1 matTag2 ...", &composite<uniaxial::parseSeries>},
};

}  // namespace

std::span<const UniaxialEntry> uniaxialParsers() { return kRows; }

}  // namespace dabs::tcl
