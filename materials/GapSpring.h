// SPDX-License-Identifier: MIT
#pragma once

#include <limits>
#include <memory>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// Parameters of a one-sided gap spring (restrainer cable or bumper). Units: force and length of
/// the model.
struct GapSpringParams {
  double k = 0.0;                                       ///< elastic stiffness once engaged (> 0)
  double gap = 0.0;                                     ///< clearance before engagement (>= 0)
  double Fy = std::numeric_limits<double>::infinity();  ///< yield force (> 0; infinite = elastic)
  double b = 0.0;                                       ///< post-yield stiffness ratio, 0 <= b < 1
  /// Throws InputError{field, reason} for k <= 0, gap < 0, Fy <= 0 or b outside [0, 1).
  void validate() const;
};

/// History of a one-sided gap spring. The engagement e is the deformation beyond the clearance in
/// the engaging direction (e > 0 engaged); `plastic` is its permanent shift e_p (non-decreasing: a
/// yielded restrainer comes back with more slack, a crushed bumper with more clearance).
struct GapSpringState {
  double strain = 0.0;   ///< trial deformation of the material (opening positive)
  double stress = 0.0;   ///< force, sign of the material convention
  double tangent = 0.0;  ///< d(stress)/d(strain)
  double plastic = 0.0;  ///< permanent shift of the engagement point e_p (>= 0)
};

/// One-sided bilinear gap spring between two girder ends. In its engaging direction (opening for
/// a restrainer, closing for a bumper) it carries no force while the deformation is at most `gap`,
/// then k (e - e_p), optionally yielding at Fy with post-yield stiffness b k; it never carries
/// force the other way. After yielding the clearance grows by the permanent deformation e_p.
///  - Restrainer (cable or bar joining the ends): engages on opening, tension (stress >= 0).
///    Tcl: `uniaxialMaterial Restrainer tag k gap ?-Fy Fy -b b?`; response "plasticElongation".
///  - Bumper (shock absorber or stopper): engages on closing, compression (stress <= 0).
///    Tcl: `uniaxialMaterial Bumper tag k gap ?-Fy Fy -b b?`; response "plasticCrush".
/// Strain is the opening of the zeroLength element (positive = girders move apart).
class GapSpring final : public StatefulUniaxial<GapSpring, GapSpringState> {
 public:
  /// Which deformation engages the spring: +1 opening (restrainer), -1 closing (bumper).
  enum class Engages { Opening = 1, Closing = -1 };

  GapSpring(int tag, const GapSpringParams& params, Engages engages);
  static GapSpring restrainer(int tag, const GapSpringParams& params) {
    return GapSpring(tag, params, Engages::Opening);
  }
  static GapSpring bumper(int tag, const GapSpringParams& params) {
    return GapSpring(tag, params, Engages::Closing);
  }

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  /// k when the clearance is zero (engaged at the first movement in the engaging direction), else
  /// 0.
  double getInitialTangent() const override;
  /// "plasticElongation" (restrainer) or "plasticCrush" (bumper): the permanent deformation e_p.
  std::optional<double> response(std::string_view name) const override;

  const GapSpringParams& params() const noexcept { return params_; }
  Engages engages() const noexcept { return engages_; }

 protected:
  GapSpringState initialState() const override { return {}; }

 private:
  GapSpringParams params_;
  Engages engages_;
};

namespace detail {
/// One-sided bilinear gap spring in its engaging direction: e is the deformation beyond the
/// clearance (e > 0 engaged). Force F = k (e - e_p) clipped to [0, envelope], where the envelope
/// is F_env(e) = Fy + b k (e - Fy/k) (elastic-perfectly/linearly hardening). On the envelope the
/// new plastic shift is e - F/k. Returns (force, tangent, new plastic shift).
struct GapSpringResult {
  double force, tangent, plastic;
};
GapSpringResult gapSpringResponse(double e, double plastic, const GapSpringParams& p) noexcept;
}  // namespace detail

}  // namespace dabs::materials
