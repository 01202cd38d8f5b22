// SPDX-License-Identifier: MIT
#include "tcl/analysis/LoadControl.h"

namespace dabs::analysis {

LoadControl::LoadControl(double dLambda, int Jd, double minLambda, double maxLambda)
    : StaticIntegrator(Jd), dLambda_(dLambda), minLambda_(minLambda), maxLambda_(maxLambda) {}

Status LoadControl::newStep(LinearSystem& system, double /*dt*/) {
  dLambda_ = adaptStep(dLambda_, minLambda_, maxLambda_);
  AnalysisModel& model = system.model();
  model.applyLoad(model.domain().committedTime() + dLambda_);
  return push(system);
}

Status LoadControl::update(LinearSystem& system, const Eigen::VectorXd& dx) {
  U_ += dx;
  countIteration();
  return push(system);
}

void LoadControl::setStepSize(double dLambda) {
  dLambda_ = dLambda;
  resetAdaptation();
}

}  // namespace dabs::analysis
