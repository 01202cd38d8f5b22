// SPDX-License-Identifier: MIT
#pragma once

#include <limits>
#include <memory>

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// Parameters of a one-sided gap spring (restrainer cable or bumper), shared by RestrainerGap and
/// BumperGap. Units: force and length of the model.
struct GapSpringParams {
  double k = 0.0;                                         ///< elastic stiffness once engaged (> 0)
  double gap = 0.0;                                       ///< clearance before engagement (>= 0)
  double Fy = std::numeric_limits<double>::infinity();   ///< yield force (> 0; infinite = elastic)
  double b = 0.0;                                         ///< post-yield stiffness ratio, 0 <= b < 1
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

/// Restrainer (cable or bar joining two girder ends): no force while the opening deformation is
/// at most `gap`, then tension k (opening - gap), optionally yielding at Fy with post-yield
/// stiffness b k. It never carries compression; after yielding its slack grows by the permanent
/// elongation. Strain is the opening of the zeroLength element (positive = girders move apart),
/// stress the tensile force (>= 0). Tcl: `uniaxialMaterial Restrainer tag k gap ?-Fy Fy -b b?`.
class RestrainerGap : public StatefulUniaxial<GapSpringState> {
 public:
  RestrainerGap(int tag, const GapSpringParams& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  /// k when the clearance is zero (engaged at the first opening), else 0.
  double getInitialTangent() const override;
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;
  /// "plasticElongation": permanent elongation e_p of the restrainer.
  std::optional<double> response(std::string_view name) const override;

  const GapSpringParams& params() const noexcept { return params_; }

 protected:
  GapSpringState initialState() const override { return {}; }

 private:
  GapSpringParams params_;
};

}  // namespace dabs::materials
