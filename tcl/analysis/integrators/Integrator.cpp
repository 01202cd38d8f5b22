// SPDX-License-Identifier: MIT
#include "tcl/analysis/integrators/Integrator.h"

namespace dabs::analysis {

void Integrator::domainChanged(LinearSystem& system) {
  system.model().getResponse(U_, V_, A_, /*committed=*/true);
}

Status Integrator::push(LinearSystem& system) {
  if (!U_.allFinite() || !V_.allFinite() || !A_.allFinite()) return Status::NonFinite;
  system.model().setResponse(U_, V_, A_);
  return system.model().updateElements();
}

Status Integrator::commit(LinearSystem& system) {
  system.model().domain().commit();
  return Status::Ok;
}

}  // namespace dabs::analysis
