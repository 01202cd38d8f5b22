// SPDX-License-Identifier: MIT
// OpenSees' uniaxial material tester: testUniaxialMaterial, setStrain, getStrain, getStress,
// getTangent, getDampTangent
// (OpenSees/OpenSees:SRC/interpreter/OpenSeesUniaxialMaterialCommands.cpp). Difference: the
// material under test is a clone of the prototype (OpenSees drives the prototype itself, so testing
// changed the state later copied into elements).

#include <string>

#include "materials/InputError.h"
#include "tcl/commands/Registry.h"

namespace dabs::tcl {

namespace {

materials::UniaxialMaterial& underTest(Runtime& rt, ArgReader& args) {
  if (!rt.testMaterial) args.fail("no material under test; use testUniaxialMaterial tag first");
  return *rt.testMaterial;
}

void testUniaxialMaterial(Runtime& rt, ArgReader& args) {
  const int tag = args.integer("tag");
  args.finish();
  try {
    rt.testMaterial = rt.builder.uniaxialMaterial(tag).clone();
  } catch (const InputError&) {
    args.failArgument("tag", "uniaxialMaterial " + std::to_string(tag) + " does not exist");
  }
  Tcl_ResetResult(rt.interp);
}

/// Sets the trial strain (and rate) and commits it, as OpenSees' setStrain does.
void setStrain(Runtime& rt, ArgReader& args) {
  const double strain = args.real("strain");
  const double rate = args.optionalReal("strainRate").value_or(0.0);
  args.finish();
  auto& m = underTest(rt, args);
  const Status status = m.setTrialStrain(strain, rate);
  if (!ok(status)) {
    m.revertToLastCommit();
    args.fail("the material failed at strain " + std::to_string(strain) + " (status " +
              std::to_string(code(status)) + ")");
  }
  m.commitState();
  Tcl_ResetResult(rt.interp);
}

template <double (materials::UniaxialMaterial::*Getter)() const>
void get(Runtime& rt, ArgReader& args) {
  args.finish();
  const auto& m = underTest(rt, args);
  Tcl_SetObjResult(rt.interp, Tcl_NewDoubleObj((m.*Getter)()));
}

constexpr CommandEntry kRows[] = {
    {"testUniaxialMaterial", "testUniaxialMaterial tag", &testUniaxialMaterial},
    {"setStrain", "setStrain strain ?strainRate?", &setStrain},
    {"getStrain", "getStrain", &get<&materials::UniaxialMaterial::getStrain>},
    {"getStress", "getStress", &get<&materials::UniaxialMaterial::getStress>},
    {"getTangent", "getTangent", &get<&materials::UniaxialMaterial::getTangent>},
    {"getDampTangent", "getDampTangent", &get<&materials::UniaxialMaterial::getDampTangent>},
};

}  // namespace

std::span<const CommandEntry> materialTestCommands() { return kRows; }

}  // namespace dabs::tcl
