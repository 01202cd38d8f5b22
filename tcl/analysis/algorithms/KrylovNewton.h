// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "tcl/analysis/algorithms/SolutionAlgorithm.h"

namespace dabs::analysis {

/// Accelerated modified Newton (`algorithm KrylovNewton ?-initial? ?-maxDim m?`, default m = 3):
/// each correction is improved by a least-squares combination of the previous corrections
/// (Carlson and Miller 1998, "Design and application of a 1D GWMFE code", SIAM J. Sci. Comput.;
/// OpenSees/OpenSees:SRC/analysis/algorithm/equiSolnAlgo/KrylovNewton.cpp). The tangent is formed
/// once per step and again after every m + 1 iterations.
class KrylovNewton final : public SolutionAlgorithm {
 public:
  struct Params {
    bool initial = false;  ///< the initial stiffness instead of the tangent
    int maxDim = 3;        ///< corrections kept for the acceleration (>= 1)
    /// Throws InputError{field, reason} (field -maxDim as in the Tcl command).
    void validate() const;
  };
  /// Throws InputError when Params::validate() does.
  explicit KrylovNewton(const Params& params);
  KrylovNewton(bool initial, int maxDim) : KrylovNewton(Params{initial, maxDim}) {}
  Status solveCurrentStep(LinearSystem& system, Integrator& integrator,
                          ConvergenceTest* test) override;

 private:
  bool initial_;
  int maxDim_;
  std::vector<Eigen::VectorXd> v_, Av_;
};

}  // namespace dabs::analysis
