// SPDX-License-Identifier: MIT
#include "materials/BumperGap.h"

#include <cmath>

namespace dabs::materials {

BumperGap::BumperGap(int tag, const GapSpringParams& params)
    : StatefulUniaxial(tag), params_(params) {
  revertToStart();
}

Status BumperGap::setTrialStrain(double strain, double /*strainRate*/) {
  if (!std::isfinite(strain)) return Status::NonFinite;
  // Engagement = closing beyond the clearance; the force acts in compression (negative stress).
  // d(stress)/d(strain) = d(-F)/d(-e) = dF/de, so the tangent keeps its sign.
  const auto r = detail::gapSpringResponse(-strain - params_.gap, committed_.plastic, params_);
  trial_ = {strain, -r.force, r.tangent, r.plastic};
  return Status::Ok;
}

double BumperGap::getInitialTangent() const { return params_.gap == 0.0 ? params_.k : 0.0; }

std::unique_ptr<UniaxialMaterial> BumperGap::clone() const {
  return std::make_unique<BumperGap>(*this);
}

std::optional<double> BumperGap::response(std::string_view name) const {
  if (name == "plasticCrush") return trial_.plastic;
  return std::nullopt;
}

}  // namespace dabs::materials
