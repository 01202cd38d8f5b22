// SPDX-License-Identifier: MIT
// Uses the installed material library: an elastic-perfectly-plastic material yields at Fy.
#include <cmath>
#include <cstdio>

#include "materials/ElasticPP.h"

int main() {
  dabs::materials::ElasticPP::Params p;
  p.E = 200.0;
  p.epsyP = 0.01;
  p.epsyN = -0.01;
  p.validate();
  dabs::materials::ElasticPP m(1, p);
  if (!dabs::ok(m.setTrialStrain(0.02))) return 1;
  const double expected = 200.0 * 0.01;  // Fy = E epsy
  std::printf("stress %g (expected %g)\n", m.getStress(), expected);
  return std::abs(m.getStress() - expected) < 1e-12 ? 0 : 1;
}
