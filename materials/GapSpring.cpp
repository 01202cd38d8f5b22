// SPDX-License-Identifier: MIT
#include "materials/GapSpring.h"

#include <cmath>

#include "materials/InputError.h"

namespace dabs::materials {

void GapSpringParams::validate() const {
  if (!(k > 0.0) || !std::isfinite(k)) throw InputError("k", "must be positive and finite");
  if (!(gap >= 0.0) || !std::isfinite(gap)) throw InputError("gap", "must be zero or positive");
  if (!(Fy > 0.0)) throw InputError("Fy", "must be positive");
  if (!(b >= 0.0 && b < 1.0)) throw InputError("b", "must be in [0, 1)");
}

namespace detail {
GapSpringResult gapSpringResponse(double e, double plastic, const GapSpringParams& p) noexcept {
  const double elastic = p.k * (e - plastic);
  if (elastic <= 0.0) return {0.0, 0.0, plastic};  // slack: clearance (plus permanent shift) open
  if (!std::isfinite(p.Fy)) return {elastic, p.k, plastic};
  // Envelope of the monotonic bilinear law: F = Fy + b k (e - Fy/k) beyond the yield point.
  const double envelope = p.Fy + p.b * p.k * (e - p.Fy / p.k);
  if (elastic <= envelope) return {elastic, p.k, plastic};
  return {envelope, p.b * p.k, e - envelope / p.k};
}
}  // namespace detail

GapSpring::GapSpring(int tag, const GapSpringParams& params, Engages engages)
    : StatefulUniaxial(tag), params_(params), engages_(engages) {
  revertToStart();
}

Status GapSpring::setTrialStrain(double strain, double /*strainRate*/) {
  if (!std::isfinite(strain)) return Status::NonFinite;
  // Engagement = deformation in the engaging direction beyond the clearance. The force acts in
  // that direction too: stress = s F with s = +1 (opening) or -1 (closing), so
  // d(stress)/d(strain) = s^2 dF/de = dF/de and the tangent keeps its sign.
  const double s = engages_ == Engages::Opening ? 1.0 : -1.0;
  const auto r = detail::gapSpringResponse(s * strain - params_.gap, committed_.plastic, params_);
  trial_ = {strain, s * r.force, r.tangent, r.plastic};
  return Status::Ok;
}

double GapSpring::getInitialTangent() const { return params_.gap == 0.0 ? params_.k : 0.0; }

std::optional<double> GapSpring::response(std::string_view name) const {
  const std::string_view own = engages_ == Engages::Opening ? "plasticElongation" : "plasticCrush";
  if (name == own) return trial_.plastic;
  return std::nullopt;
}

}  // namespace dabs::materials
