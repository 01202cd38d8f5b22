// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/Integrator.h"

namespace dabs::analysis {

/// Explicit central differences (`integrator CentralDifference`), for use with `algorithm Linear`:
/// (M/dt^2 + C/(2dt)) u_{n+1} = P_n - R(u_n) + (2M/dt^2) u_n - (M/dt^2 - C/(2dt)) u_{n-1}
/// (Chopra, Dynamics of Structures, sec. 5.3; OpenSees/OpenSees:SRC/analysis/integrator/
/// CentralDifference.cpp, which also takes u_{-1} = u_0 on the first step). The unknown solved for
/// is the total displacement u_{n+1}.
class CentralDifference final : public Integrator {
 public:
  bool transient() const override { return true; }
  void domainChanged(LinearSystem& system) override;
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  AssemblyCoefficients coefficients(StiffnessKind k) const override;
  Status commit(LinearSystem& system) override;
  void revertToLastStep() override;

 private:
  double dt_ = 0.0;
  int updates_ = 0;
  Eigen::VectorXd Uprev_, Un_, Vn_, An_;  // u_{n-1}, u_n and the committed v_n, a_n
  Eigen::VectorXd UprevSaved_, UnSaved_, VnSaved_, AnSaved_;
};

}  // namespace dabs::analysis
