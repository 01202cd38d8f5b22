// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/ConvergenceTest.h"

#include <cmath>
#include <sstream>

#include "materials/InputError.h"

namespace dabs::analysis {

void ConvergenceTest::Params::validate() const {
  if (!(tol > 0.0)) throw InputError("tol", "must be positive");
  if (maxIter < 1) throw InputError("maxIter", "must be at least 1");
  if (normType < 0) throw InputError("nType", "must be 0 (max norm) or a positive p");
}

ConvergenceTest::ConvergenceTest(const Params& params)
    : kind_(params.kind),
      tol_(params.tol),
      maxIter_(params.maxIter),
      printFlag_(params.printFlag),
      normType_(params.normType) {
  params.validate();
}

double ConvergenceTest::norm(const Eigen::VectorXd& v) const {
  // OpenSees Vector::pNorm: p = 0 is the max norm, otherwise the p-norm.
  if (v.size() == 0) return 0.0;
  if (normType_ == 0) return v.lpNorm<Eigen::Infinity>();
  if (normType_ == 1) return v.lpNorm<1>();
  if (normType_ == 2) return v.norm();
  double sum = 0.0;
  for (double x : v) sum += std::pow(std::abs(x), normType_);
  return std::pow(sum, 1.0 / normType_);
}

ConvergenceTest::Result ConvergenceTest::test(const Eigen::VectorXd& x, const Eigen::VectorXd& b) {
  ++iteration_;
  switch (kind_) {
    case Kind::NormDispIncr: lastNorm_ = norm(x); break;
    case Kind::NormUnbalance: lastNorm_ = norm(b); break;
    case Kind::EnergyIncr: lastNorm_ = 0.5 * std::abs(x.dot(b)); break;
  }
  const bool finite = std::isfinite(lastNorm_);
  if (log && (printFlag_ == 1 || printFlag_ == 4)) {
    std::ostringstream out;
    out << "  iteration " << iteration_ << ": norm " << lastNorm_ << " (tol " << tol_ << ")";
    log(out.str());
  }
  if (finite && lastNorm_ <= tol_) {
    if (log && (printFlag_ == 2 || printFlag_ == 6)) {
      std::ostringstream out;
      out << "  converged in " << iteration_ << " iterations: norm " << lastNorm_;
      log(out.str());
    }
    return Result::Converged;
  }
  if (!finite) return Result::Failed;
  if (iteration_ >= maxIter_) {
    // pFlag 5 and 6 accept the step anyway (OpenSees CTest*::test).
    if (printFlag_ == 5 || printFlag_ == 6) return Result::Converged;
    if (log) {
      std::ostringstream out;
      out << "WARNING: test failed to converge after " << iteration_ << " iterations, norm "
          << lastNorm_ << " > tol " << tol_;
      log(out.str());
    }
    return Result::Failed;
  }
  return Result::Continue;
}

}  // namespace dabs::analysis
