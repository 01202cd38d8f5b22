// SPDX-License-Identifier: MIT
#pragma once

#include <map>
#include <memory>

#include "elements/beam/BeamIntegration.h"
#include "elements/transform/CrdTransf.h"
#include "materials/BiaxialMaterial.h"
#include "materials/UniaxialMaterial.h"
#include "materials/section/SectionForceDeformation.h"
#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// Prototypes a model is built from (materials, sections, transformations, integration rules,
/// time series) and the current `model basic` dimensions. Elements own clones of prototypes.
class ModelBuilder {
 public:
  ModelBuilder();
  ~ModelBuilder();

  int ndm = 0;  ///< model dimension (0 until `model basic`)
  int ndf = 0;  ///< dofs per node for new nodes
  bool defined() const noexcept { return ndm > 0; }

  std::map<int, std::unique_ptr<materials::UniaxialMaterial>> uniaxial;
  std::map<int, std::unique_ptr<materials::BiaxialMaterial>> biaxial;
  std::map<int, std::unique_ptr<materials::section::SectionForceDeformation>> sections;
  std::map<int, std::unique_ptr<elements::CrdTransf>> transforms;
  std::map<int, std::unique_ptr<elements::BeamIntegration>> integrations;
  std::map<int, std::shared_ptr<const TimeSeries>> timeSeries;

  /// Prototype lookups; each throws InputError naming the kind and tag when absent.
  const materials::UniaxialMaterial& uniaxialMaterial(int tag) const;
  const materials::BiaxialMaterial& biaxialMaterial(int tag) const;
  const materials::section::SectionForceDeformation& section(int tag) const;
  const elements::CrdTransf& transform(int tag) const;
  const elements::BeamIntegration& integration(int tag) const;
  std::shared_ptr<const TimeSeries> series(int tag) const;

  /// Forgets every prototype and the model dimensions (wipe).
  void clear();
};

}  // namespace dabs::domain
