// SPDX-License-Identifier: MIT
#include "contact/CoulombFriction.h"

#include "contact/NormalLaw.h"
#include "materials/InputError.h"

namespace dabs::contact {

void CoulombFriction::Params::validate() const {
  if (!(Kt > 0.0) || !std::isfinite(Kt)) throw InputError("Kt", "must be positive and finite");
  if (!(et >= 0.0 && et <= 1.0)) throw InputError("et", "must be in [0, 1]");
  if (!(muS >= 0.0) || !std::isfinite(muS)) throw InputError("mu_s", "must be zero or positive");
  if (!(muK >= 0.0) || !std::isfinite(muK)) throw InputError("mu_k", "must be zero or positive");
  if (muK > muS) throw InputError("mu_k", "must not exceed mu_s");
  if (et < 1.0) {
    if (!(M1 > 0.0) || !std::isfinite(M1))
      throw InputError("M1", "must be positive when et < 1 (-masses M1 M2)");
    if (!(M2 > 0.0) || !std::isfinite(M2))
      throw InputError("M2", "must be positive when et < 1 (-masses M1 M2)");
  }
}

CoulombFriction::CoulombFriction(const Params& p) : cone_{p.Kt, 0.0, p.muS, p.muK} {
  // Same restitution-to-damping relation as the normal dashpot (Zhu, Abe and Fujino 2002).
  if (p.et < 1.0) {
    const double mass = p.M1 * p.M2 / (p.M1 + p.M2);
    cone_.Ct = 2.0 * NormalLaw::dampingRatio(p.et) * std::sqrt(p.Kt * mass);
  }
}

}  // namespace dabs::contact
