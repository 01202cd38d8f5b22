// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/algorithms/SolutionAlgorithm.h"

namespace dabs::analysis {

/// Newton with a line search along each Newton direction (`algorithm NewtonLineSearch ?-type T?
/// ?-tol 0.8? ?-maxIter 10? ?-minEta 0.1? ?-maxEta 10?`). The search looks for eta where the
/// residual is orthogonal to the direction, s(eta) = -dx . R(u + eta dx) = 0, and stops when
/// |s(eta)/s(0)| <= tol (Crisfield 1991, sec. 9.3; OpenSees/OpenSees:SRC/analysis/algorithm/
/// equiSolnAlgo/InitialInterpolatedLineSearch.cpp and siblings).
class NewtonLineSearch final : public SolutionAlgorithm {
 public:
  enum class Search { InitialInterpolated, Bisection, Secant, RegulaFalsi };
  struct Params {
    Search search = Search::InitialInterpolated;
    double tol = 0.8;      ///< |s(eta)/s(0)| at which the search stops (> 0)
    int maxIter = 10;      ///< search iterations per Newton iteration (>= 1)
    double minEta = 0.1;   ///< smallest step factor, in (0, 1]
    double maxEta = 10.0;  ///< largest step factor (>= 1)
    /// Throws InputError{field, reason} (fields -tol, -maxIter, -minEta, -maxEta as in the Tcl
    /// command).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit NewtonLineSearch(const Params& params);
  NewtonLineSearch(Search search, double tol, int maxIter, double minEta, double maxEta)
      : NewtonLineSearch(Params{search, tol, maxIter, minEta, maxEta}) {}
  Status solveCurrentStep(LinearSystem& system, Integrator& integrator,
                          ConvergenceTest* test) override;

 private:
  Status lineSearch(LinearSystem& system, Integrator& integrator, const AssemblyCoefficients& c,
                    double s0, double s1);
  Search search_;
  double tol_;
  int maxIter_;
  double minEta_, maxEta_;
  Eigen::VectorXd dx_, step_;
};

}  // namespace dabs::analysis
