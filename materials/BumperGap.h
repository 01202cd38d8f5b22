// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "materials/RestrainerGap.h"

namespace dabs::materials {

/// Bumper (shock absorber or stopper between girder ends): no force while the closing deformation
/// is at most `gap`, then compression k (closing - gap), optionally yielding (crushing) at Fy with
/// post-yield stiffness b k. It never carries tension; after yielding its clearance grows by the
/// permanent crush. Strain is the opening of the zeroLength element (negative = closing), stress
/// is <= 0 (compression). Tcl: `uniaxialMaterial Bumper tag k gap ?-Fy Fy -b b?`.
class BumperGap : public StatefulUniaxial<GapSpringState> {
 public:
  BumperGap(int tag, const GapSpringParams& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  /// k when the clearance is zero (engaged at the first closing), else 0.
  double getInitialTangent() const override;
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;
  /// "plasticCrush": permanent shortening e_p of the bumper.
  std::optional<double> response(std::string_view name) const override;

  const GapSpringParams& params() const noexcept { return params_; }

 protected:
  GapSpringState initialState() const override { return {}; }

 private:
  GapSpringParams params_;
};

}  // namespace dabs::materials
