// SPDX-License-Identifier: MIT
#pragma once

namespace dabs::elements {

/// Axial (vertical) force-deformation law of a circular elastomeric bearing after Kumar,
/// Whittaker and Constantinou (2014), "An advanced numerical model of elastomeric seismic isolation
/// bearings", Earthquake Engng Struct Dyn 43:1955-1974, and their report MCEER-15-0008 (2015);
/// the same law as OpenSees' ElastomericX/LeadRubberX vertical direction, with the differences
/// listed below. Used by `element yoshidaBearing ... -vertical kumar`.
///
/// Sign: u is the axial deformation (extension positive), N the axial force (tension positive).
/// uh = |U| is the horizontal (shear) displacement of the two ends, which reduces the compression
/// stiffness and the critical buckling load through the overlap of the top and bottom bonded areas.
///
/// Properties from the geometry (Kumar et al. 2014, section 2; Constantinou et al. for F):
///   A   = pi/4 ((Do + tc)^2 - Di^2)    bonded area (tc: rubber cover, as ElastomericX)
///   I   = pi/64 ((Do + tc)^4 - Di^4),  r = sqrt(I / A) its radius of gyration
///   S   = (Do - Di) / (4 tr)           shape factor of one layer (annular)
///   F   = (a^2 + 1)/(a - 1)^2 + (1 + a)/((1 - a) ln a), a = Do/Di (F = 1 without a hole)
///   Ec  = 1 / (1/(6 G S^2 F) + 4/(3 K))  compression modulus with bulk compressibility
///   Tr  = n tr, h = Tr + (n - 1) ts    rubber and total height
///   Kv0 = Ec A / Tr                    axial stiffness at zero shear
///   Fc  = 3 G A                        cavitation force (Gent's 3G tensile stress)
///   Pcr0 = sqrt(Pe G As), Pe = pi^2 (Ec/3) (I h/Tr) / h^2, As = A h/Tr  (Koh and Kelly)
///
/// The law (the papers' equation numbers are not cited: the formulas are the published model as
/// ElastomericX implements it, read from its source, the paper not being at hand):
///   Kv(uh) = Kv0 / (1 + 3/pi^2 (uh/r)^2)            (Kumar et al. 2014, after Warn et al. 2007)
///   uc = Fc / Kv(uh)                                 cavitation deformation
///   envelope for u > uc:  N = Fc (1 + (1 - exp(-kc (u - uc))) / (kc Tr))
///     (post-cavitation: initial slope Fc/Tr = 3GA/Tr, decaying at rate kc, 1/length)
///   damage: once u reached umax > uc, Fcn = Fc (1 - phi (1 - exp(-ac (umax - uc)/uc)))
///   unloading/reloading after cavitation: straight from (umax, N(umax)) to (ucn, Fcn),
///     ucn = Fcn / Kv, then N = Kv u through the origin (the elastic part)
///   buckling (overlap-area reduction of Buckle and Liu 1994, as Kumar et al. use it):
///     Pcr(uh) = Pcr0 Ar/A with Ar = ((Do + tc)^2 - Di^2)/4 (d - sin d),
///     d = 2 acos(uh/Do), not less than 0.2 Pcr0 (the cut-off ElastomericX applies;
///     0.2 Pcr0 too for uh >= Do); for u <= -Pcr/Kv: N = -Pcr + Kpb (u + Pcr/Kv), Kpb = Kv0/1e4
///     (a small positive stiffness past the critical load, as ElastomericX).
/// Each of the three effects can be switched off (Params::kvShear, cavitation, buckling).
///
/// Differences from ElastomericX, on purpose: (1) Kv, uc and Pcr follow the trial uh (ElastomericX
/// updates them when a step is committed, one step late), so the tangent holds dN/duh and is
/// consistent; (2) the damage is updated from the largest tension on the post-cavitation curve
/// only, and never heals; (3) the critical load follows the current overlap area (ElastomericX
/// keeps the least one reached but starts the buckled branch at the current one, so its force
/// jumps when the shear comes back). At a held shear offset the two give the same numbers
/// (verification/opensees/elastomericx-vertical.tcl).
class KumarVertical {
 public:
  /// Geometry, rubber and law parameters (lengths and forces in the model's units).
  struct Params {
    double G = 0.0;      ///< shear modulus of the rubber (force/length^2), > 0
    double Kbulk = 0.0;  ///< bulk modulus of the rubber (force/length^2), > 0
    double Di = 0.0;     ///< inner (hole) diameter (length), 0 <= Di < Do
    double Do = 0.0;     ///< outer diameter of the bonded rubber (length), > 0
    double ts = 0.0;     ///< thickness of one steel shim (length), >= 0
    double tr = 0.0;     ///< thickness of one rubber layer (length), > 0
    double n = 0.0;      ///< number of rubber layers, >= 1
    double tc = 0.0;     ///< rubber cover thickness added to Do in A and I (length), >= 0
    double kc = 10.0;  ///< cavitation parameter: decay rate of the post-cavitation slope (1/length)
    double phi = 0.5;  ///< largest damage of the cavitation strength, 0 <= phi < 1
    double ac = 1.0;   ///< rate of the cavitation damage, > 0
    bool cavitation = true;  ///< tension law with cavitation and damage (else N = Kv u)
    bool buckling = true;    ///< compression limited by Pcr(uh)
    bool kvShear = true;     ///< Kv falls with uh (else Kv = Kv0)

    /// Throws InputError{field, reason} (fields named as the Tcl arguments).
    void validate() const;
  };

  /// History of the law (one value, committed and reverted with the element's State).
  struct State {
    double umax = 0.0;             ///< largest tensile deformation past cavitation (0: none yet)
    double cavitationRatio = 1.0;  ///< Fcn / Fc, the cavitation strength left after damage
    int branch = 0;  ///< 0 elastic, 1 post-cavitation envelope, 2 after cavitation, 3 buckled
  };

  /// Force, its derivatives and the trial history at (u, uh).
  struct Response {
    double N = 0.0;      ///< axial force (tension positive)
    double dNdu = 0.0;   ///< dN/du
    double dNduh = 0.0;  ///< dN/duh (zero at uh = 0, where the derivative has no direction)
    State state;
  };

  /// `p` must be valid.
  explicit KumarVertical(const Params& p);

  /// The axial force at deformation u and shear displacement uh from the committed history.
  Response evaluate(double u, double uh, const State& committed) const;

  /// Axial stiffness Kv(uh) (force/length; Kv0 when kvShear is off).
  double stiffness(double uh) const;
  /// Critical load Pcr(uh) > 0 (the magnitude of the compression limit).
  double criticalLoad(double uh) const;
  /// Post-cavitation envelope N(u) for u >= uc (independent of damage).
  double envelope(double u, double uc) const;

  const Params& params() const noexcept { return p_; }
  double area() const noexcept { return A_; }                 ///< A (length^2)
  double radiusOfGyration() const noexcept { return r_; }     ///< r = sqrt(I/A) (length)
  double compressionModulus() const noexcept { return Ec_; }  ///< Ec (force/length^2)
  double Tr() const noexcept { return Tr_; }                  ///< total rubber thickness n tr
  double height() const noexcept { return h_; }               ///< Tr + (n - 1) ts
  double Kv0() const noexcept { return Kv0_; }                ///< axial stiffness at zero shear
  double Fc() const noexcept { return Fc_; }                  ///< cavitation force 3 G A
  double Pcr0() const noexcept { return Pcr0_; }              ///< critical load at zero shear
  double postBucklingStiffness() const noexcept { return Kv0_ * kPostBuckling; }

  /// Ratio of the post-buckling stiffness to Kv0 (ElastomericX's choice).
  static constexpr double kPostBuckling = 1e-4;
  /// Lower bound of Pcr/Pcr0 (Kumar et al. 2014).
  static constexpr double kMinCriticalRatio = 0.2;

 private:
  /// Kv and dKv/duh.
  void stiffness(double uh, double& kv, double& dkv) const;
  /// Pcr and dPcr/duh.
  void criticalLoad(double uh, double& pcr, double& dpcr) const;

  Params p_;
  double A_ = 0.0, r_ = 0.0, Ec_ = 0.0, Tr_ = 0.0, h_ = 0.0, Kv0_ = 0.0, Fc_ = 0.0, Pcr0_ = 0.0;
};

}  // namespace dabs::elements
