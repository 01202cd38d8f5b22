// SPDX-License-Identifier: MIT
#pragma once

#include <memory>

#include "materials/UniaxialMaterial.h"
#include "tcl/analysis/algorithms/ConvergenceTest.h"

namespace dabs::analysis::testing {

/// A hardening elastic cubic spring, stress = k e + c e^3, whose Newton iterations have a known
/// sequence (the scalar iteration on k u + c u^3 = P).
class CubicSpring final : public materials::UniaxialMaterial {
 public:
  CubicSpring(double k, double c) : UniaxialMaterial(1), k_(k), c_(c) {}
  Status setTrialStrain(double e, double /*rate*/) override {
    trial_ = e;
    return Status::Ok;
  }
  double getStrain() const override { return trial_; }
  double getStress() const override { return k_ * trial_ + c_ * trial_ * trial_ * trial_; }
  double getTangent() const override { return k_ + 3.0 * c_ * trial_ * trial_; }
  double getInitialTangent() const override { return k_; }
  void commitState() override { committed_ = trial_; }
  void revertToLastCommit() override { trial_ = committed_; }
  void revertToStart() override { trial_ = committed_ = 0.0; }
  std::unique_ptr<UniaxialMaterial> clone() const override {
    return std::make_unique<CubicSpring>(*this);
  }

 private:
  double k_, c_;
  double trial_ = 0.0, committed_ = 0.0;
};

/// A NormDispIncr test.
inline std::unique_ptr<ConvergenceTest> dispTest(double tol, int maxIter) {
  return std::make_unique<ConvergenceTest>(ConvergenceTest::Kind::NormDispIncr, tol, maxIter);
}

}  // namespace dabs::analysis::testing
