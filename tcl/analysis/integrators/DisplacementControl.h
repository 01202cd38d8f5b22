// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/integrators/StaticIntegrator.h"

namespace dabs::analysis {

/// Static displacement control (`integrator DisplacementControl node dof incr ?Jd dUmin dUmax?
/// ?-initial?`): each step moves one dof by `incr` and finds the load factor from the constraint
/// (Batoz and Dhatt 1979, as OpenSees/OpenSees:SRC/analysis/integrator/DisplacementControl.cpp).
/// The reference load is the unbalance at lambda + 1 with the committed displacements, taken when
/// the equations are built.
class DisplacementControl final : public StaticIntegrator {
 public:
  struct Params {
    int node = 0;                 ///< tag of the controlled node
    int dof = 0;                  ///< controlled dof, from 0 (the Tcl command counts from 1)
    double incr = 0.0;            ///< displacement increment of a step
    int Jd = 1;                   ///< iterations the adapted increment aims at (>= 1)
    double dUmin = 0.0;           ///< smallest adapted increment
    double dUmax = 0.0;           ///< largest adapted increment
    bool initialTangent = false;  ///< reference displacements from the initial stiffness
    /// Throws InputError{field, reason} (fields dof, incr, Jd, dUmin, dUmax). Whether the node
    /// exists and has the dof is for the analysis to find (the domain may change).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit DisplacementControl(const Params& params);
  DisplacementControl(int node, int dof, double incr, int Jd, double dUmin, double dUmax,
                      bool initialTangent)
      : DisplacementControl(Params{node, dof, incr, Jd, dUmin, dUmax, initialTangent}) {}
  void domainChanged(LinearSystem& system) override;
  Status newStep(LinearSystem& system, double dt) override;
  Status update(LinearSystem& system, const Eigen::VectorXd& dx) override;
  void setStepSize(double incr) override;

 private:
  int node_, dof_;
  double incr_;
  double dUmin_, dUmax_;
  bool initialTangent_;
  int equation_ = -1;
  double lambda_ = 0.0;
  double dUahat_ = 0.0;
  Eigen::VectorXd phat_, dUhat_, deltaU_;
};

}  // namespace dabs::analysis
