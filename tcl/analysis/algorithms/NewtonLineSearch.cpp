// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/NewtonLineSearch.h"

#include <algorithm>
#include <cmath>

#include "materials/InputError.h"

namespace dabs::analysis {

void NewtonLineSearch::Params::validate() const {
  if (!(tol > 0.0)) throw InputError("-tol", "must be positive");
  if (maxIter < 1) throw InputError("-maxIter", "must be at least 1");
  if (!(minEta > 0.0 && minEta <= 1.0)) throw InputError("-minEta", "must be in (0, 1]");
  if (!(maxEta >= 1.0) || !std::isfinite(maxEta)) throw InputError("-maxEta", "must be at least 1");
}

NewtonLineSearch::NewtonLineSearch(const Params& params)
    : search_(params.search),
      tol_(params.tol),
      maxIter_(params.maxIter),
      minEta_(params.minEta),
      maxEta_(params.maxEta) {
  params.validate();
}

Status NewtonLineSearch::solveCurrentStep(LinearSystem& system, Integrator& integrator,
                                          ConvergenceTest* test) {
  if (test == nullptr) return Status::Failed;
  iterations_ = 0;
  const AssemblyCoefficients c = integrator.coefficients(StiffnessKind::Current);
  system.formResidual(c);
  test->start();
  for (;;) {
    Status s = system.formTangent(c);
    if (!ok(s)) return s;
    s = system.solve();
    if (!ok(s)) return s;
    dx_ = system.X;
    const double s0 = -dx_.dot(system.B);
    s = integrator.update(system, dx_);
    if (!ok(s)) return s;
    system.formResidual(c);
    const double s1 = -dx_.dot(system.B);
    if (s0 != 0.0 && std::abs(s1 / s0) > tol_) {
      s = lineSearch(system, integrator, c, s0, s1);
      if (!ok(s)) return s;
    }
    countIteration();
    switch (afterTest(test->test(system.X, system.B), system, c)) {
      case Next::Converged: return Status::Ok;
      case Next::Failed: return Status::NotConverged;
      case Next::Switched:
      case Next::IterateOn: break;
    }
  }
}

Status NewtonLineSearch::lineSearch(LinearSystem& system, Integrator& integrator,
                                    const AssemblyCoefficients& c, double s0, double s1) {
  const double r0 = std::abs(s1 / s0);
  double eta = 1.0, etaPrev = 1.0, s = s1, r = r0;
  double etaLow = 0.0, sLow = s0, etaHigh = 1.0, sHigh = s1;  // bracket for bisection/regula falsi
  for (int count = 0; r > tol_ && count < maxIter_; ++count) {
    switch (search_) {
      case Search::InitialInterpolated:
        // Linear interpolation of s between eta = 0 and the current eta.
        eta = eta * s0 / (s0 - s);
        break;
      case Search::Secant: eta = etaPrev - s * (etaPrev - etaLow) / (s - sLow); break;
      case Search::Bisection: eta = 0.5 * (etaLow + etaHigh); break;
      case Search::RegulaFalsi: eta = etaHigh - sHigh * (etaHigh - etaLow) / (sHigh - sLow); break;
    }
    if (!std::isfinite(eta)) eta = 1.0;
    eta = std::min(eta, maxEta_);
    if (r > r0) eta = 1.0;
    eta = std::max(eta, minEta_);
    if (eta == etaPrev) break;
    step_ = (eta - etaPrev) * dx_;
    Status st = integrator.update(system, step_);
    if (!ok(st)) return st;
    system.formResidual(c);
    const double sNew = -dx_.dot(system.B);
    if (search_ == Search::Secant) {
      etaLow = etaPrev;
      sLow = s;
    } else if (sNew * s0 > 0.0) {  // same sign as at eta = 0: the root lies above eta
      etaLow = eta;
      sLow = sNew;
    } else {
      etaHigh = eta;
      sHigh = sNew;
    }
    s = sNew;
    r = std::abs(s / s0);
    etaPrev = eta;
  }
  system.X = etaPrev * dx_;  // tests see the scaled step, as in OpenSees
  return Status::Ok;
}

}  // namespace dabs::analysis
