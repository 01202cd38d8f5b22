// SPDX-License-Identifier: MIT
#pragma once

#include <tcl.h>

#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"
#include "tcl/analysis/driver/HugePageHeap.h"
#include "tcl/domain/Domain.h"
#include "tcl/domain/ModelBuilder.h"

namespace dabs::analysis {
class AnalysisBuilder;
class StepObserver;
}  // namespace dabs::analysis

namespace dabs::tcl {

/// State of a `section Fiber` body while it is being evaluated; defined by the section parsers.
struct FiberSectionUnderConstruction;

/// Everything one interpreter's commands share (style.md section 5): created in Dabs_Init, passed
/// as ClientData to every command and deleted with the interpreter. No global state.
struct Runtime {
  explicit Runtime(Tcl_Interp* interp);
  ~Runtime();
  Runtime(const Runtime&) = delete;
  Runtime& operator=(const Runtime&) = delete;

  Tcl_Interp* interp;
  /// Set up first, so that the model's blocks land on the heap it prepares.
  analysis::HugePageHeap heap;
  domain::Domain domain;
  domain::ModelBuilder builder;
  std::unique_ptr<analysis::AnalysisBuilder> analysis;
  /// Material under test by testUniaxialMaterial/setStrain/getStress (OpenSees' material tester).
  std::unique_ptr<materials::UniaxialMaterial> testMaterial;
  /// Set while a `section Fiber` body runs (an RAII guard clears it); null otherwise.
  FiberSectionUnderConstruction* currentFiberSection = nullptr;
  /// Pattern that `load`, `sp`, `groundMotion` and `imposedMotion` add to (the last one defined,
  /// as in OpenSees); -1 when none.
  int currentPattern = -1;
  /// The yoshidaBearing rupture report, registered with the analysis by the first `element
  /// yoshidaBearing` command (owned by the analysis); null before.
  analysis::StepObserver* bearingFailureReport = nullptr;
  /// Bindings handed to Tcl as ClientData, owned here.
  std::vector<std::unique_ptr<struct CommandBinding>> bindings;

  /// Throws ArgError-like InputError when no `model basic` has been given.
  void requireModel(const char* command) const;
};

}  // namespace dabs::tcl
