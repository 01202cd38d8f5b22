// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/StaticIntegrator.h"

namespace dabs::analysis {

/// Static load control (`integrator LoadControl dLambda ?Jd minLambda maxLambda?`): the pseudo
/// time (load factor) grows by dLambda per step, scaled by Jd / (iterations of the last step) and
/// kept in [minLambda, maxLambda] (OpenSees/OpenSees:SRC/analysis/integrator/LoadControl.cpp).
class LoadControl final : public StaticIntegrator {
 public:
  struct Params {
    double dLambda = 1.0;    ///< load-factor increment of a step
    int Jd = 1;              ///< iterations the adapted increment aims at (>= 1)
    double minLambda = 1.0;  ///< smallest adapted increment
    double maxLambda = 1.0;  ///< largest adapted increment
    /// Throws InputError{field, reason} (fields dLambda, Jd, minLambda, maxLambda).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit LoadControl(const Params& params);
  LoadControl(double dLambda, int Jd, double minLambda, double maxLambda)
      : LoadControl(Params{dLambda, Jd, minLambda, maxLambda}) {}
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  void setStepSize(double dLambda) override;

 private:
  double dLambda_;
  double minLambda_, maxLambda_;
};

}  // namespace dabs::analysis
