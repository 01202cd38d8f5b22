// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>

namespace dabs::analysis {

/// Convergence test of an iteration (`test NormDispIncr|NormUnbalance|EnergyIncr tol maxIter
/// ?pFlag? ?nType?`), evaluated after each update on the increment just applied (x) and the new
/// residual (b), as OpenSees does (OpenSees/OpenSees:SRC/convergenceTest/CTestNormDispIncr.cpp
/// etc.).
class ConvergenceTest {
 public:
  enum class Kind { NormDispIncr, NormUnbalance, EnergyIncr };
  /// Result of one test: converged, keep iterating, or failed (maxIter reached).
  enum class Result { Converged, Continue, Failed };

  struct Params {
    Kind kind = Kind::NormUnbalance;
    double tol = 1e-6;  ///< tolerance of the norm (> 0)
    int maxIter = 25;   ///< iterations before the step fails (>= 1)
    int printFlag = 0;  ///< OpenSees' pFlag (what to print per iteration)
    int normType = 2;   ///< p of the norm, 0 the max norm
    /// Throws InputError{field, reason} (fields tol, maxIter, nType as in the Tcl command).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit ConvergenceTest(const Params& params);
  ConvergenceTest(Kind kind, double tol, int maxIter, int printFlag = 0, int normType = 2)
      : ConvergenceTest(Params{kind, tol, maxIter, printFlag, normType}) {}

  /// Starts the iterations of a step.
  void start() noexcept { iteration_ = 0; }
  /// Tests the increment x and the residual b. Non-finite norms fail at once.
  Result test(const Eigen::VectorXd& x, const Eigen::VectorXd& b);
  /// Norm of the last test.
  double lastNorm() const noexcept { return lastNorm_; }
  /// Iterations done in the current step.
  int iterations() const noexcept { return iteration_; }
  int maxIterations() const noexcept { return maxIter_; }
  /// Where pFlag output goes (the Tcl layer writes it to stderr); none by default.
  std::function<void(const std::string&)> log;

 private:
  double norm(const Eigen::VectorXd& v) const;
  Kind kind_;
  double tol_;
  int maxIter_;
  int printFlag_;
  int normType_;
  int iteration_ = 0;
  double lastNorm_ = 0.0;
};

}  // namespace dabs::analysis
