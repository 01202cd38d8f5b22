// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/Integrator.h"

namespace dabs::analysis {

/// Static load control (`integrator LoadControl dLambda ?Jd minLambda maxLambda?`): the pseudo
/// time (load factor) grows by dLambda per step, scaled by Jd / (iterations of the last step) and
/// kept in [minLambda, maxLambda] (OpenSees/OpenSees:SRC/analysis/integrator/LoadControl.cpp).
class LoadControl final : public Integrator {
 public:
  LoadControl(double dLambda, int Jd, double minLambda, double maxLambda);
  bool transient() const override { return false; }
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  AssemblyCoefficients coefficients(StiffnessKind k) const override;
  void revertToLastStep() override { U_ = Ucommitted_; }
  Status commit(LinearSystem& system) override;
  void setStepSize(double dLambda) override;
  void domainChanged(LinearSystem& system) override;

 private:
  double dLambda_;
  int Jd_;
  double minLambda_, maxLambda_;
  int iterationsLastStep_;
  Eigen::VectorXd Ucommitted_;
};

}  // namespace dabs::analysis
