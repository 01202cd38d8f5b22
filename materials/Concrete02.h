// SPDX-License-Identifier: MIT
#pragma once

#include "materials/StatefulUniaxial.h"

namespace dabs::materials {

/// History of Concrete02.
struct Concrete02State {
  double strain = 0.0;   ///< strain (compression negative)
  double stress = 0.0;   ///< stress (compression negative)
  double tangent = 0.0;  ///< d(stress)/d(strain)
  double ecmin = 0.0;    ///< most compressive strain reached
  double dept = 0.0;     ///< largest tensile strain beyond the zero-stress strain ept
  // Functions of ecmin alone, formed when ecmin changes rather than at every update:
  double sigMin = 0.0;   ///< envelope stress at ecmin
  double Er = 0.0;       ///< reloading slope (EERC report eq. 2.35)
  double ept = 0.0;      ///< zero-stress strain of the reloading line (eq. 2.36)
};

/// Concrete with linear tension softening (Yassin 1994; FEDEAS Concr2 by Sze & Filippou):
/// Kent-Scott-Park compression envelope (parabola to (epsc0, fpc), linear to (epsU, fpcu), then
/// flat), unloading with slope lambda-dependent damage (EERC report eqs. 2.31-2.36), and in
/// tension a linear branch Ec0*eps up to ft followed by linear softening with slope -Ets.
/// OpenSees: `uniaxialMaterial Concrete02 tag fpc epsc0 fpcu epsU ?lambda ft Ets?`
/// (OpenSees/OpenSees:SRC/material/uniaxial/Concrete02.cpp); defaults lambda = 0.1,
/// ft = 0.1*|fpc|, Ets = 0.1*fpc/epsc0. Compression values must be negative.
class Concrete02 final : public StatefulUniaxial<Concrete02State> {
 public:
  using State = Concrete02State;

  struct Params {
    double fpc = 0.0;     ///< compressive strength (< 0)
    double epsc0 = 0.0;   ///< strain at fpc (< 0)
    double fpcu = 0.0;    ///< crushing strength (<= 0, |fpcu| <= |fpc|)
    double epsU = 0.0;    ///< strain at fpcu (< epsc0)
    double lambda = 0.1;  ///< ratio of unloading slope at epsU to the initial slope, in [0, 1)
    double ft = 0.0;      ///< tensile strength (>= 0)
    double Ets = 0.0;     ///< tension softening stiffness (> 0)
    /// Params with the OpenSees defaults for lambda, ft and Ets.
    static Params withDefaults(double fpc, double epsc0, double fpcu, double epsU);
    /// Throws InputError naming the offending parameter.
    void validate() const;
  };

  Concrete02(int tag, const Params& params);

  [[nodiscard]] Status setTrialStrain(double strain, double strainRate = 0.0) override;
  double getStrain() const override { return trial_.strain; }
  double getStress() const override { return trial_.stress; }
  double getTangent() const override { return trial_.tangent; }
  double getInitialTangent() const override { return Ec0_; }
  [[nodiscard]] std::unique_ptr<UniaxialMaterial> clone() const override;
  const Params& params() const noexcept { return params_; }

  /// Compression envelope at `eps`: stress and tangent.
  void compressionEnvelope(double eps, double& stress, double& tangent) const;
  /// Tension envelope at `eps` measured from the zero-stress strain: stress and tangent.
  void tensionEnvelope(double eps, double& stress, double& tangent) const;

 private:
  State initialState() const override;
  /// Sets ecmin (envelope stress sigMin there) and the reloading data that follow from it.
  void setMinimumStrain(State& s, double ecmin, double sigMin) const;
  Params params_;
  // Constants of the parameters (formed once; divisions are the cost of this law's update):
  double Ec0_ = 0.0;       ///< initial tangent 2 fpc / epsc0
  double epsR_ = 0.0;      ///< strain of point R fixing the reloading slope (eqs. 2.31, 2.32)
  double sigR_ = 0.0;      ///< stress of point R
  double epsCrack_ = 0.0;  ///< cracking strain ft / Ec0
  double epsZero_ = 0.0;   ///< strain where tension softening reaches zero stress
};

}  // namespace dabs::materials
