// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/LoadControl.h"

#include <cmath>

#include "materials/InputError.h"

namespace dabs::analysis {

void LoadControl::Params::validate() const {
  if (!std::isfinite(dLambda)) throw InputError("dLambda", "must be a finite number");
  if (Jd < 1) throw InputError("Jd", "must be at least 1");
  if (!std::isfinite(minLambda)) throw InputError("minLambda", "must be a finite number");
  if (!std::isfinite(maxLambda)) throw InputError("maxLambda", "must be a finite number");
}

LoadControl::LoadControl(const Params& params)
    : StaticIntegrator(params.Jd),
      dLambda_(params.dLambda),
      minLambda_(params.minLambda),
      maxLambda_(params.maxLambda) {
  params.validate();
}

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
