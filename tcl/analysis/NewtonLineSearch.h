// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/analysis/SolutionAlgorithm.h"

namespace dabs::analysis {

/// Newton with a line search along each Newton direction (`algorithm NewtonLineSearch ?-type T?
/// ?-tol 0.8? ?-maxIter 10? ?-minEta 0.1? ?-maxEta 10?`). The search looks for eta where the
/// residual is orthogonal to the direction, s(eta) = -dx . R(u + eta dx) = 0, and stops when
/// |s(eta)/s(0)| <= tol (Crisfield 1991, sec. 9.3; OpenSees/OpenSees:SRC/analysis/algorithm/
/// equiSolnAlgo/InitialInterpolatedLineSearch.cpp and siblings).
class NewtonLineSearch final : public SolutionAlgorithm {
 public:
  enum class Search { InitialInterpolated, Bisection, Secant, RegulaFalsi };
  NewtonLineSearch(Search search, double tol, int maxIter, double minEta, double maxEta)
      : search_(search), tol_(tol), maxIter_(maxIter), minEta_(minEta), maxEta_(maxEta) {}
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
