// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/StaticIntegrator.h"

namespace dabs::analysis {

/// Static load control (`integrator LoadControl dLambda ?Jd minLambda maxLambda?`): the pseudo
/// time (load factor) grows by dLambda per step, scaled by Jd / (iterations of the last step) and
/// kept in [minLambda, maxLambda] (OpenSees/OpenSees:SRC/analysis/integrator/LoadControl.cpp).
class LoadControl final : public StaticIntegrator {
 public:
  LoadControl(double dLambda, int Jd, double minLambda, double maxLambda);
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  void setStepSize(double dLambda) override;

 private:
  double dLambda_;
  double minLambda_, maxLambda_;
};

}  // namespace dabs::analysis
