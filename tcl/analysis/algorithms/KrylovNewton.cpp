// SPDX-License-Identifier: MIT
#include "tcl/analysis/algorithms/KrylovNewton.h"

#include <Eigen/QR>

#include "materials/InputError.h"

namespace dabs::analysis {

void KrylovNewton::Params::validate() const {
  if (maxDim < 1) throw InputError("-maxDim", "must be at least 1");
}

KrylovNewton::KrylovNewton(const Params& params)
    : initial_(params.initial), maxDim_(params.maxDim) {
  params.validate();
}

Status KrylovNewton::solveCurrentStep(LinearSystem& system, Integrator& integrator,
                                      ConvergenceTest* test) {
  if (test == nullptr) return Status::Failed;
  iterations_ = 0;
  const StiffnessKind kind = initial_ ? StiffnessKind::Initial : StiffnessKind::Current;
  const AssemblyCoefficients c = integrator.coefficients(kind);
  system.formResidual(c);
  test->start();
  Status s = system.formTangent(c, initial_);
  if (!ok(s)) return s;
  v_.assign(static_cast<std::size_t>(maxDim_ + 1), Eigen::VectorXd());
  Av_.assign(static_cast<std::size_t>(maxDim_ + 1), Eigen::VectorXd());
  int dim = 0;
  Eigen::VectorXd update;
  for (;;) {
    if (dim > maxDim_) {
      dim = 0;
      s = system.formTangent(c, initial_);
      if (!ok(s)) return s;
    }
    s = system.solve();
    if (!ok(s)) return s;
    const Eigen::VectorXd& r = system.X;
    const auto k = static_cast<std::size_t>(dim);
    v_[k] = r;
    Av_[k] = r;
    if (dim > 0) {
      // Columns are differences of successive corrections, r_{j} - r_{j+1}.
      Av_[k - 1] -= r;
      Eigen::MatrixXd A(r.size(), dim);
      for (int j = 0; j < dim; ++j) A.col(j) = Av_[static_cast<std::size_t>(j)];
      const Eigen::VectorXd coef = A.colPivHouseholderQr().solve(r);
      for (int j = 0; j < dim; ++j)
        v_[k] += coef(j) * (v_[static_cast<std::size_t>(j)] - Av_[static_cast<std::size_t>(j)]);
    }
    update = v_[k];
    s = integrator.update(system, update);
    if (!ok(s)) return s;
    system.formResidual(c);
    ++dim;
    countIteration();
    switch (afterTest(test->test(system.X, system.B), system, c)) {
      case Next::Converged: return Status::Ok;
      case Next::Failed: return Status::NotConverged;
      // The corrections so far belong to the former statuses: start anew.
      case Next::Switched: dim = maxDim_ + 1; break;
      case Next::IterateOn: break;
    }
  }
}

}  // namespace dabs::analysis
