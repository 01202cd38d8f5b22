// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/StaticIntegrator.h"

namespace dabs::analysis {

/// Static arc-length control (Riks 1979, Crisfield 1981): each step moves a distance s along the
/// equilibrium path, measured by the constraint
///   wU * dU.dU + wF * dLambda^2 = s^2
/// on the step's displacement increment dU and load-factor increment dLambda. The predictor goes
/// along the tangent, dLambda = +/- s / sqrt(wU dUhat.dUhat + wF) with K dUhat = phat, signed as
/// the last step's dLambda; each corrector dU_i = dUbar + dlambda_i dUhat takes the root of the
/// constraint's quadratic that keeps the step's direction (the larger dU_step.(dU_step + dU_i)).
/// The reference load phat is the unbalance at lambda + 1 with the committed state, taken when
/// the equations are built. OpenSees' two commands set the weights:
///   `integrator ArcLength s alpha`: wU = 1, wF = alpha^2 (SRC/analysis/integrator/ArcLength.cpp);
///   `integrator HSConstraint s ?psiU psiF uRef?`: wU = psiU^2/uRef^2, wF = psiF^2 phat.phat
///   (SRC/analysis/integrator/HSConstraint.cpp).
class ArcLength final : public StaticIntegrator {
 public:
  struct Params {
    double arcLength = 1.0;   ///< s, the length of a step along the path
    double wU = 1.0;          ///< weight of the displacements
    double wF = 1.0;          ///< weight of the load factor
    bool loadScaled = false;  ///< wF times phat.phat (HSConstraint)
    /// Throws InputError{field, reason} (fields arcLength, wU, wF; empty when both weights are
    /// zero).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit ArcLength(const Params& params);
  /// wU and wF as above; `loadScaled` multiplies wF by phat.phat (HSConstraint).
  ArcLength(double arcLength, double wU, double wF, bool loadScaled)
      : ArcLength(Params{arcLength, wU, wF, loadScaled}) {}
  void domainChanged(LinearSystem& system) override;
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;

 private:
  double arcLength_;
  double wU_, wF_;
  bool loadScaled_;
  double wFEffective_ = 0.0;  ///< wF, times phat.phat when load-scaled
  double lambda_ = 0.0;       ///< trial load factor
  double dLambdaStep_ = 0.0;  ///< load-factor increment of the current (or last) step
  Eigen::VectorXd phat_, dUhat_, dUstep_, dU_;
};

}  // namespace dabs::analysis
