// SPDX-License-Identifier: MIT
#pragma once

// Parsers behind the `uniaxialMaterial` rows of UniaxialParsers.cpp, exposed so that unit tests
// can call them with a bare ModelBuilder (no Runtime, no dispatcher). Each reads the arguments
// after the tag, calls args.finish() and validates the Params; a validation InputError propagates
// and is reported at the argument read under its field (ArgReader::failInput).

#include <memory>

#include "materials/UniaxialMaterial.h"
#include "tcl/commands/ArgReader.h"
#include "tcl/domain/ModelBuilder.h"

namespace dabs::tcl::uniaxial {

using MaterialPtr = std::unique_ptr<materials::UniaxialMaterial>;

MaterialPtr parseElastic(ArgReader& args, int tag);
MaterialPtr parseElasticPP(ArgReader& args, int tag);
MaterialPtr parseElasticPPGap(ArgReader& args, int tag);
MaterialPtr parseSteel01(ArgReader& args, int tag);
MaterialPtr parseSteel02(ArgReader& args, int tag);
MaterialPtr parseConcrete01(ArgReader& args, int tag);
MaterialPtr parseConcrete02(ArgReader& args, int tag);
MaterialPtr parseViscous(ArgReader& args, int tag);
MaterialPtr parseENT(ArgReader& args, int tag);
/// Components are looked up in `builder` and cloned.
MaterialPtr parseParallel(ArgReader& args, int tag, const domain::ModelBuilder& builder);
MaterialPtr parseSeries(ArgReader& args, int tag, const domain::ModelBuilder& builder);
MaterialPtr parseFatigue(ArgReader& args, int tag, const domain::ModelBuilder& builder);

}  // namespace dabs::tcl::uniaxial
