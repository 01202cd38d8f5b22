// SPDX-License-Identifier: MIT
#include "tcl/domain/ModelBuilder.h"

#include <string>

#include "materials/InputError.h"

namespace dabs::domain {

namespace {
template <class Map>
const auto& lookup(const Map& map, int tag, const char* kind) {
  auto it = map.find(tag);
  if (it == map.end() || !it->second)
    throw InputError(kind, std::to_string(tag) + " does not exist");
  return *it->second;
}
}  // namespace

ModelBuilder::ModelBuilder() = default;
ModelBuilder::~ModelBuilder() = default;

const materials::UniaxialMaterial& ModelBuilder::uniaxialMaterial(int tag) const {
  return lookup(uniaxial, tag, "uniaxialMaterial");
}
const materials::BiaxialMaterial& ModelBuilder::biaxialMaterial(int tag) const {
  return lookup(biaxial, tag, "biaxialMaterial");
}
const materials::section::SectionForceDeformation& ModelBuilder::section(int tag) const {
  return lookup(sections, tag, "section");
}
const elements::CrdTransf& ModelBuilder::transform(int tag) const {
  return lookup(transforms, tag, "geomTransf");
}
const elements::BeamIntegration& ModelBuilder::integration(int tag) const {
  return lookup(integrations, tag, "beamIntegration");
}
std::shared_ptr<const TimeSeries> ModelBuilder::series(int tag) const {
  auto it = timeSeries.find(tag);
  if (it == timeSeries.end())
    throw InputError("timeSeries", std::to_string(tag) + " does not exist");
  return it->second;
}

void ModelBuilder::clear() {
  ndm = ndf = 0;
  uniaxial.clear();
  biaxial.clear();
  sections.clear();
  transforms.clear();
  integrations.clear();
  timeSeries.clear();
}

}  // namespace dabs::domain
