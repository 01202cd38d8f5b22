// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/Integrator.h"

namespace dabs::analysis {

/// Generalized-alpha time stepping (Chung and Hulbert 1993) in OpenSees' convention, where the
/// alphas weight the NEW state: M a_{n+alphaM} + C v_{n+alphaF} + R(u_{n+alphaF}) = P(t_n + alphaF
/// dt) with Newmark's update for u, v, a. Newmark is alphaM = alphaF = 1; HHT (Hilber, Hughes and
/// Taylor 1977) is alphaM = 1, alphaF = alpha (OpenSees/OpenSees:SRC/analysis/integrator/
/// Newmark.cpp, HHT.cpp, GeneralizedAlpha.cpp). The unknown is the displacement increment.
class GeneralizedAlpha final : public Integrator {
 public:
  /// Parameters in OpenSees' convention (Newmark: alphaM = alphaF = 1).
  struct Params {
    double alphaM = 1.0;  ///< weight of the new state in the inertia term
    double alphaF = 1.0;  ///< weight of the new state in the other terms
    double gamma = 0.5;   ///< Newmark's gamma
    double beta = 0.25;   ///< Newmark's beta
    /// Throws InputError{field, reason} (fields alphaM, alphaF, gamma, beta): finite values,
    /// gamma and beta positive; Newmark needs gamma >= 1/2 (below it every mode grows; the
    /// conditionally stable choices, such as linear acceleration, are the caller's); otherwise
    /// the unconditional stability conditions of Chung and Hulbert (1993, eq. 25).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit GeneralizedAlpha(const Params& params);
  GeneralizedAlpha(double alphaM, double alphaF, double gamma, double beta)
      : GeneralizedAlpha(Params{alphaM, alphaF, gamma, beta}) {}

  bool transient() const override { return true; }
  void domainChanged(LinearSystem& system) override;
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  bool additiveUpdate() const override { return true; }
  AssemblyCoefficients coefficients(StiffnessKind k) const override;
  Status commit(LinearSystem& system) override;
  void revertToLastStep() override;
  /// The nodes hold (1 - alphaF) U_n + alphaF U_n+1 during the step.
  bool checksCommittedDisplacements() const override { return alphaF_ == 1.0; }

 private:
  Status pushWeighted(LinearSystem& system);
  double alphaM_, alphaF_, gamma_, beta_;
  double c2_ = 0.0, c3_ = 0.0, dt_ = 0.0, tn_ = 0.0;
  Eigen::VectorXd Ut_, Vt_, At_;
  Eigen::VectorXd Ua_, Va_, Aa_;  // weighted state pushed to the nodes
};

}  // namespace dabs::analysis
