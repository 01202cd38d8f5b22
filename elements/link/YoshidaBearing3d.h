// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "elements/FixedSizeElement.h"
#include "elements/link/KumarVertical.h"
#include "materials/BiaxialMaterial.h"
#include "materials/friction/CoulombCone.h"

namespace dabs::elements {

/// Laminated rubber bearing between two 6-dof nodes (Tcl: `element yoshidaBearing`).
///
/// Local frame: x is the bearing's axis from iNode to jNode (vertical in a bridge); for coincident
/// nodes x is global Z unless `-orient` gives it. Local y is the orient y vector made normal to x,
/// by default global X (global Y when x is along global X); z = x cross y. The shear plane is
/// local y-z.
///
/// Basic deformations (local, j relative to i, L = distance between the nodes):
///   axial    d0 = u_jx - u_ix                                  N  = Kv d0
///   shear y  d1 = u_jy - u_iy - L (th_iz + th_jz)/2           (Vy, Vz) from the bi-axial material
///   shear z  d2 = u_jz - u_iz + L (th_iy + th_jy)/2            with U = (d1, d2)
///   torsion  d3 = th_jx - th_ix                                T  = Kt d3
///   rocking  d4 = th_jy - th_iy,  d5 = th_jz - th_iz           My = Kry d4, Mz = Krz d5
/// The nodal forces are B^T q, so the moment L V of the shear force over the bearing's height is
/// shared equally between its ends and every rigid-body motion gives zero deformation.
///
/// Damage by shear strain g = |U| / Tr in any direction: damage 0 below the design limit, 1 once
/// the largest strain reached it, 2 once it reached the failure limit (failed; the time is
/// recorded). With AfterFailure::Release the shear force and stiffness are zero in every update
/// after the step in which failure was committed; the failing step itself keeps the material's
/// force, so a Newton iteration never sees the switch.
///
/// With AfterFailure::Drop the rubber ruptures: from the step after the one in which failure was
/// committed (the same switch as Release) it carries no shear, no tension, no torsion and no
/// rocking, and node j comes down by the bearing's height h (rubber, steel plates and sole plate)
/// onto the seat below it (pier cap or steel seat). The seat is a compression-only point contact
/// with Coulomb friction, in the basic (local) frame:
///   gap       g  = h + d0                     (> 0 open; d0 = u_jx - u_ix, so g = h at rupture
///                                               for a bearing without axial deformation)
///   normal    N  = Ks max(0, -g)             (compressive, >= 0), basic axial force q0 = -N
///   friction  s  = (d1, d2), the in-plane displacement of j relative to i; a spring Kst to the
///             stick point s_c (committed), return map of materials::CoulombCone (the contact
///             pair's law): q_(1,2) = Kst (s - s_c) while |Kst (s - s_c)| <= mu N (mu = mu_s after
///             a committed stick, mu_k after a committed slide), else mu_k N (s - s_c)/|s - s_c|,
///             and the stick point moves to s - q_(1,2)/Kst.
/// While open the stick point follows j (no friction force). Torsion and rocking are zero after
/// the drop: the girder rests on a seat point, which transmits no moment (other elements - the
/// girder, the pier - must hold the nodes' rotations, as for a released bearing's shear). The
/// sliding tangent is non-symmetric (dq/dd0 = -mu_k Ks n for a slide direction n, and
/// dq/ds = mu_k N (I - n n^T)/|s - s_c|), declared by hasNonSymmetricTangent().
///
/// Vertical behaviour (Params::vertical, Tcl `-vertical kumar ...`): by default the axial force
/// is linear, N = Kv d0. With the Kumar option it follows KumarVertical (Kumar, Whittaker and
/// Constantinou 2014): Kv falls with the shear displacement |U|, tension cavitates at 3GA and
/// softens with damage, compression is limited by the critical load Pcr(|U|). Kv and Tr then
/// come from the bearing's geometry (Kv0 = Ec A/Tr, Tr = n tr). N depends on U, so the tangent
/// has dN/dU in the axial row and is non-symmetric (hasNonSymmetricTangent()).
///
/// P-Delta (Params::pDelta, Tcl `-pDelta`; off by default): the axial force N at j, offset by the
/// shear deformation (d1, d2) from i, is a couple that the end moments balance. As ElastomericX
/// (OpenSees) does, half of it is added at each end, in the local frame:
///   Mz_i = Mz_j += N d1 / 2,   My_i = My_j -= N d2 / 2,
/// with the consistent tangent (the d(N)/du part too, so non-symmetric). For a bearing of nonzero
/// length ElastomericX adds terms in the end rotations times L as well; here d1, d2 already hold
/// the shear deformation with the rotations (the class comment), and nothing else is added.
///
/// The element's own viscous force (the material's Maxwell part) is a function of the
/// displacement increment over the step, so dampingTangent() is zero and the Maxwell stiffness is
/// in tangentStiff(). Rayleigh damping does not apply by default (as for OpenSees zero-length
/// links).
class YoshidaBearing3d final : public FixedSizeElement<2, 6> {
 public:
  /// What a bearing does once it reaches its failure shear strain: keep carrying load as if intact
  /// (the default, Yoshida et al.'s model has no rupture), release its shear force, keep
  /// carrying it while the analysis stops (AnalysisBuilder returns kBearingFailureStop), or
  /// rupture so that node j drops by h onto a seat with friction (see the class comment).
  enum class AfterFailure { Keep, Release, Stop, Drop };

  /// The seat a dropped bearing's node j lands on (AfterFailure::Drop).
  struct Seat {
    double h = 0.0;    ///< drop height: the bearing's height (length), >= 0
    double Ks = 0.0;   ///< normal (vertical) stiffness of the seat (force/length), > 0
    double muS = 0.0;  ///< static friction coefficient, >= 0
    double muK = 0.0;  ///< kinetic friction coefficient, 0 <= muK <= muS
    double Kst = 0.0;  ///< tangential stick stiffness (force/length), > 0
  };

  /// Element parameters (the material is passed separately).
  struct Params {
    double Tr = 0.0;   ///< total rubber thickness (length), for the shear strain |U|/Tr
    double Kv = 0.0;   ///< axial stiffness (force/length)
    double Kt = 0.0;   ///< torsional stiffness (moment/radian)
    double Kry = 0.0;  ///< rocking stiffness about local y (moment/radian)
    double Krz = 0.0;  ///< rocking stiffness about local z (moment/radian)
    std::optional<Eigen::Vector3d> orientX;  ///< local x (global frame), with orientY
    std::optional<Eigen::Vector3d> orientY;  ///< vector in the local x-y plane (global frame)
    double mass = 0.0;          ///< total mass, lumped half to each node's translations
    double designLimit = 2.5;   ///< design shear strain (250 %)
    double failureLimit = 3.0;  ///< failure shear strain (300 %)
    AfterFailure afterFailure = AfterFailure::Keep;
    Seat seat;  ///< used with AfterFailure::Drop only (the Tcl defaults: Ks = Kv, Kst = Ks)
    bool pDelta = false;  ///< add the P-Delta moments of the axial force (class comment)
    /// Kumar et al.'s vertical law; when given, Tr and Kv are replaced by its n tr and Kv0.
    std::optional<KumarVertical::Params> vertical;

    /// Throws InputError{field, reason} for parameters that cannot make a valid element.
    void validate() const;
  };

  /// History of the element apart from the material's own state.
  struct State {
    Eigen::Matrix<double, 6, 1> deformation = Eigen::Matrix<double, 6, 1>::Zero();  ///< d0..d5
    Eigen::Matrix<double, 6, 1> basicForce =
        Eigen::Matrix<double, 6, 1>::Zero();  ///< N Vy Vz T My Mz
    double shearStrain = 0.0;                 ///< |U| / Tr
    double maxShearStrain = 0.0;              ///< largest |U| / Tr so far
    bool failed = false;                      ///< failure limit reached
    double failureTime = -1.0;  ///< time of the step in which it was reached (-1: never)
    // Seat of a dropped bearing (AfterFailure::Drop, from the step after failure on).
    bool dropped = false;  ///< the rubber has ruptured and node j is on (or above) the seat
    double seatGap = 0.0;  ///< g = h + d0 (length, > 0 open); 0 before the drop
    Eigen::Vector3d seatForce = Eigen::Vector3d::Zero();   ///< N (>= 0), Ft1, Ft2 on j (local)
    Eigen::Vector2d stickPoint = Eigen::Vector2d::Zero();  ///< s_c (local y, z), relative to i
    bool sliding = false;                                  ///< the friction cone was exceeded
    double seatDissipated = 0.0;    ///< work of the seat friction so far (force x length)
    KumarVertical::State vertical;  ///< history of the vertical law (Params::vertical only)
  };

  /// `p` must be valid; the material is cloned.
  YoshidaBearing3d(int tag, int iNode, int jNode, const materials::BiaxialMaterial& material,
                   const Params& p);

  std::string_view typeName() const override { return "yoshidaBearing"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  bool rayleighByDefault() const override { return false; }
  /// True once the bearing has dropped onto its seat (trial state), where sliding friction makes
  /// the tangent non-symmetric; an intact bearing keeps the symmetric solver.
  /// The Kumar vertical law couples N to the shear displacement (dN/dU without dV/dd0), so a
  /// bearing with it declares a non-symmetric tangent throughout.
  bool hasNonSymmetricTangent() const override {
    return trial_.dropped || coupledVertical() || p_.pDelta;
  }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return kc_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  /// The vertical law (Params::vertical), or null for the linear axial spring.
  const KumarVertical* verticalLaw() const noexcept { return vertical_ ? &*vertical_ : nullptr; }

  /// force/globalForce (12), localForce (12), basicForce (6), deformation/basicDeformation (6),
  /// shearStrain, maxShearStrain, damage, failureTime (1 each), and the material's
  /// hystereticForce, viscousForce, backForce (2, local y-z), dissipatedEnergy (1); the seat's
  /// dropped (1: 0 or 1), seatGap (1, g = h + d0, 0 before the drop), seatForce (3: N, Ft1, Ft2,
  /// force of the seat on node j in local y-z), seatStatus (1: 0 intact or open, 1 stick,
  /// 2 slide) and seatDissipatedEnergy (1); with the Kumar vertical law, verticalStiffness (Kv at
  /// the trial |U|), criticalLoad (Pcr, > 0), cavitationForce (the damaged Fcn), maxTension (umax)
  /// and verticalBranch (0 elastic, 1 post-cavitation envelope, 2 after cavitation, 3 buckled).
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::string describe() const override;

  /// 0 below the design limit, 1 beyond it, 2 failed (trial state).
  int damage() const noexcept;
  /// Rotation from global to local: rows are the local x, y, z axes in global coordinates.
  const Eigen::Matrix3d& axes() const noexcept { return axes_; }
  const State& trialState() const noexcept { return trial_; }
  const State& committedState() const noexcept { return committed_; }
  const Params& params() const noexcept { return p_; }
  /// The Tcl word of an AfterFailure mode (keep, release, stop, drop).
  static const char* afterFailureName(AfterFailure mode) noexcept;

 private:
  using Basic = Eigen::Matrix<double, 6, 1>;
  using BasicMatrix = Eigen::Matrix<double, 6, 6>;
  bool released() const noexcept {
    return committed_.failed && p_.afterFailure == AfterFailure::Release;
  }
  bool dropping() const noexcept {
    return committed_.failed && p_.afterFailure == AfterFailure::Drop;
  }
  /// Seat contact of a dropped bearing: sets the trial seat state and the basic force and
  /// tangent (axial and shear rows; torsion and rocking zero).
  void seatContact(State& t, Basic& q, BasicMatrix& kb) const;
  void assemble(const Basic& q, const BasicMatrix& kb);
  /// Adds the P-Delta end moments of the axial force q(0) and their tangent to f_ and k_.
  void addPDelta(const Basic& d, const Basic& q, const BasicMatrix& kb);
  bool coupledVertical() const noexcept {
    return vertical_ && (vertical_->params().kvShear || vertical_->params().buckling);
  }

  std::unique_ptr<materials::BiaxialMaterial> material_;
  Params p_;
  materials::CoulombCone seatCone_;        ///< friction law of the seat (AfterFailure::Drop)
  std::optional<KumarVertical> vertical_;  ///< vertical law (Params::vertical)
  double length_ = 0.0;
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, kNumDof> b_ = Eigen::Matrix<double, 6, kNumDof>::Zero();  ///< global B
  /// Unit local z (my_: y) moments at both ends in global dofs (the P-Delta moment directions).
  Eigen::Matrix<double, kNumDof, 1> mz_ = Eigen::Matrix<double, kNumDof, 1>::Zero();
  Eigen::Matrix<double, kNumDof, 1> my_ = Eigen::Matrix<double, kNumDof, 1>::Zero();
  State trial_{};
  State committed_{};
};

}  // namespace dabs::elements
