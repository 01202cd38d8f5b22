// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>

#include "contact/ContactGeometry.h"
#include "contact/ContactSearch.h"
#include "contact/CoulombFriction.h"
#include "contact/NormalLaw.h"
#include "elements/ContactPredictor.h"
#include "elements/FarPair.h"
#include "elements/FixedSizeElement.h"

namespace dabs::contact {

/// Contact status reported by the `status` response.
enum class ContactStatus : int { Open = 0, Stick = 1, Slide = 2 };

/// Parameters of a node-to-surface pair (Tcl: `element nodeToSurface tag k a b c d -K K ?-e e?
/// ?-law kelvin|hertz|hertzdamp|jankowski? ?-n n? ?-v0 v0? ?-Kt Kt? ?-et et? ?-mu_s mus?
/// ?-mu_k muk? ?-masses M1 M2? ?-search dist?`).
struct NodeToSurfaceParams {
  double K = 0.0;  ///< normal penalty stiffness: EA/L of the contactor body (kelvin), or the
                   ///< power laws' k_h / beta (force/length^n); see NormalLaw
  double e = 1.0;  ///< normal restitution (kelvin [0, 1], hertzdamp and jankowski (0, 1])
  ImpactLaw law = ImpactLaw::Kelvin;  ///< normal impact law (NormalLaw)
  double n = 1.5;                     ///< exponent of hertz and hertzdamp
  double v0 = 0.0;                    ///< hertzdamp: approach speed the damping is tuned to
  double Kt = 0.0;   ///< tangential penalty stiffness (force/length); 0: the value of K
  double et = 1.0;   ///< tangential restitution in [0, 1]
  double muS = 0.0;  ///< static friction coefficient
  double muK = 0.0;  ///< kinetic friction coefficient (<= muS)
  double M1 = 0.0;   ///< masses of the two bodies, for the dashpots (needed when e < 1 or et < 1)
  double M2 = 0.0;
  double search = std::numeric_limits<double>::infinity();  ///< search distance (> 0)
  /// Throws InputError{field, reason} (fields as in the Tcl command: K, e, n, v0, Kt, et, mu_s,
  /// mu_k, M1, M2, search).
  void validate() const;
};

/// Everything that changes with the trial (one struct: commit and revert are one assignment).
/// Local components are in the fixed surface frame (n, t1, t2) of ContactGeometry.h.
struct NodeToSurfaceState {
  double gap = std::numeric_limits<double>::infinity();  ///< g (> 0 open); beyond the search
                                                         ///< distance: a lower bound of it
                                                         ///< (first: a far pair's step writes
                                                         ///< it alone)
  ContactStatus status = ContactStatus::Open;
  Eigen::Vector2d stickXi = Eigen::Vector2d::Zero();  ///< stick point, target parametric coords
  bool stickValid = false;                            ///< stickXi holds a stick point
  Eigen::Vector2d projXi = Eigen::Vector2d::Zero();   ///< projection of the contactor
  bool projValid = false;                             ///< projXi computed and on the quad
  Eigen::Vector3d force = Eigen::Vector3d::Zero();    ///< contact force on the contactor: normal
                                                      ///< N (compression > 0), tangential t1, t2
  double dashpotPower = 0.0;                          ///< power dissipated by the dashpots (>= 0)
  double frictionEnergy = 0.0;                        ///< accumulated friction work (>= 0)
  double dampingEnergy = 0.0;                         ///< accumulated dashpot work (trapezoid rule)
  Eigen::Vector2d plasticSlip = Eigen::Vector2d::Zero();  ///< accumulated slip vector (t1, t2)
  double slipLength = 0.0;                                ///< accumulated slip path length
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();      ///< time integral of `force` (trapezoid)
};

/// The far test of a pair on its own: the reference coordinates of its nodes (k, a, b, c, d), the
/// outward normal of the target and the search distance. The analysis keeps a copy of it for each
/// pair that may sleep, so the once-a-step test of a sleeping pair reads compact arrays and not
/// the element.
struct FarTest {
  std::array<Eigen::Vector3d, 5> X{};           ///< reference coordinates (k, a, b, c, d)
  Eigen::Vector3d n = Eigen::Vector3d::Zero();  ///< outward unit normal of the target
  ContactSearch search = ContactSearch();       ///< search distance
  /// ContactSearch::isFar of the contactor at X[0] + u[0] and the quad at X[i] + u[i] (true:
  /// far, `bound` written); false for non-finite positions.
  bool isFar(const std::array<Eigen::Vector3d, 5>& u, double& bound) const noexcept;
};

/// Point-to-surface contact with friction after Zhu, Abe and Fujino (2002, "Modelling
/// three-dimensional non-linear seismic performance of elevated bridges with emphasis on pounding
/// of girders", EESD 31:1891-1913): a contactor node k against a target quad a, b, c, d.
///
/// Model. While k penetrates the quad (gap g < 0, projection on the quad), the normal force is
/// N = max(0, -K g - C gdot) (NormalLaw: penalty spring plus restitution dashpot, never pulling;
/// or another impact law of NormalLaw: hertz, hertzdamp, jankowski) and the tangential force
/// follows CoulombFriction (spring Kt = K to a stick point kept in the state plus a tangential
/// dashpot, the sum bounded by the static/kinetic cone). The force on k is R = N m + F1 t1 + F2 t2,
/// where m = dg/dx_k = n - grad_s(z_surface) is the normal of the current surface scaled so that
/// m.n = 1 (m = n for a face that stays parallel to its reference plane); the target nodes receive
/// -N_i(p) R, the bilinear shape functions at the projection p (static equilibrium by linear
/// interpolation at p). The frictionless, undamped part is the gradient of K g^2 / 2, so its
/// tangent is symmetric.
///
/// Assumptions and conventions:
/// - Small rotations of the target: the surface frame is fixed at the reference geometry
///   (ContactGeometry.h) and projections are taken along n. Translations may be large; a
///   contactor sliding past an edge of the quad leaves contact (zero force).
/// - No tension: N is clipped at zero, so the effective restitution exceeds e
///   (NormalLaw::effectiveRestitution).
/// - A new contact places the stick point at the contactor's projection in the last committed
///   state, so the first trial already has tangential stiffness.
/// - Only translations carry contact forces (dofs 1-3 of each node); with ndf 6 the rotations get
///   zero force and stiffness.
/// - Beyond the search distance (ContactSearch's bound) the update costs the distance test and adds
///   nothing, except in the step after a closed state (a release step is always evaluated).
/// - Release step (closed at the last commit, open in the trial): the normal force is
///   N = -N_r g / (g - g_n), N_r = min(N_n, K delta_n), so that the step's trapezoid work is the
///   energy of linear unloading, 0.5 N_r delta_n; without it a large step on a stiff contact gains
///   energy under the trapezoidal rule. The force is zero at g = 0 and slightly tensile (status
///   open) for that one step. The power laws (spring K delta^n) use the same idea with their
///   stored energy N_r delta_n / (n + 1) (NormalLaw::releaseForce), tensile already at g = 0.
///
/// The tangent is exact (forward-mode automatic differentiation of the force, including the moving
/// load point and the return map); it is non-symmetric when friction or a dashpot is on.
/// dampingTangent() holds d(force)/d(velocity) of the dashpots and of the velocity-dependent N.
template <int Ndf>
class NodeToSurfaceContact3d : public elements::FixedSizeElement<5, Ndf, 0u>,
                               public elements::FarPair,
                               public elements::ContactPredictor {
  static_assert(Ndf >= 3, "contact needs three translational dofs per node");
  // No mass, no initial or committed tangent (they read as zero); the tangent and the damping
  // tangent are the pair's own, allocated at its first contact (see tangents_).
  using Base = elements::FixedSizeElement<5, Ndf, 0u>;
  using Matrix = typename Base::Matrix;
  using HeldStatus = elements::Element::HeldStatus;

 public:
  /// `params` must be validated. Node order: contactor, then a, b, c, d.
  NodeToSurfaceContact3d(int tag, int contactor, const std::array<int, 4>& target,
                         const NodeToSurfaceParams& params);

  std::string_view typeName() const override { return "nodeToSurface"; }
  /// Builds the surface frame; throws InputError for a degenerate quad or when the outward normal
  /// (b - a) x (d - a) points away from the contactor's side.
  void initialize(const elements::NodalCoordinates& x) override;
  [[nodiscard]] Status update(const elements::Kinematics& trial) override;

  bool hasNonSymmetricTangent() const override;
  bool rayleighByDefault() const override { return false; }

  /// Held statuses (Element::HeldStatus): the normal law's branch (open, Kelvin, spring alone,
  /// release) and, in contact, sticking or sliding. See holdStatus().
  bool switchesStatus() const override { return true; }
  /// Holds the branches of the last update until the next commit or revert. While held, update()
  /// evaluates the held branch's force whatever the trial: the Kelvin force without the
  /// no-tension clip, the open state's zero force inside the face, the stick force outside the
  /// cone, the sliding force inside it; the equations of the step are then smooth.
  void holdStatus() override;
  /// Compares the held branches with those the last update's state gives and holds those when
  /// they differ; a pair closed at the last commit whose held contact separates with a force
  /// that would pull holds the release force before open (Kelvin, and power laws with n <= 1; the
  /// contact ends in this step, and in a step longer than the impact its end state lies outside the
  /// face). A switch back to a branch already held in the step would cycle; then two set-valued
  /// selections apply, the limits of the law where it jumps (Filippov 1988): (1) a pair with a
  /// dashpot that would switch between Kelvin inside the face and open or the release force outside
  /// it, while approaching, holds the spring force alone; the dashpot force jumps from 0 to C
  /// |gdot| at the face, and an end state of the step exists only within that jump, with N between
  /// 0 and the Kelvin force (the spring alone agrees while the pair penetrates and approaches, g <=
  /// 0 and gdot <= 0, where it is at most the Kelvin force); (2) a pair that has held both stick
  /// and slide may slide while its trial force is at least the kinetic limit mu_k N (the cone drops
  /// from mu_s N to mu_k N at the onset of sliding). A held slide whose trial force reverses sticks
  /// at once (update()). Conflict after kMaxSwitches switches in a step.
  elements::Element::HeldStatus checkHeldStatus() override;
  /// A power-law pair (spring k delta^n, n > 1) asks Newton for a longer step while Newton
  /// shrinks its deep penetration slowly (NormalLaw::slowShrink in this update and the last):
  /// NormalLaw::forceVariableStepScale of the change from the last update's penetration to this
  /// one's, both on a closed branch (1 otherwise).
  bool scalesNewtonSteps() const override { return normal_.exponent() > 1.0; }
  double newtonStepScale() const override { return stepScale_; }
  /// Open contacts carry nothing, so the assembly skips them.
  bool isActive() const override { return !forcesZero_; }
  bool mayTurnInactive() const override { return true; }
  Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const override {
    if (tangents_) return tangents_->k;
    return Base::zero();
  }
  Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const override {
    if (tangents_) return tangents_->c;
    return Base::zero();
  }

  /// While the pair is far in both states (see farInBothStates_) the trial state differs from the
  /// committed one in the gap alone, so commit and revert copy the gap.
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  /// force | contactForce (N, t1, t2) | gap | status | slip (length, t1, t2) |
  /// dissipatedEnergy (total, friction, dashpots) | impulse (N, t1, t2).
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::string describe() const override;

  /// Far-pair shortcut for the analysis (sleeping pairs): with the nodes' translations `u` (k, a,
  /// b, c, d), when the pair has a search distance and is far by its bound, sets the trial state
  /// update() would set (open, no force, the bound as gap) without the rest of update()'s work and
  /// returns true; otherwise changes nothing and returns false (then call update()).
  bool updateIfFar(const std::array<Eigen::Vector3d, 5>& u, double dt);

  /// The far-pair interface (elements::FarPair) while the pair has a search distance: only then
  /// may it sleep.
  elements::FarPair* farPair() noexcept override { return search_.enabled() ? this : nullptr; }
  /// Every pair predicts its contact for contact stepping.
  const elements::ContactPredictor* contactPredictor() const noexcept override { return this; }
  elements::FarPair::Geometry farGeometry() const override {
    return elements::FarPair::Geometry{X_, frame_.n, search_.distance()};
  }
  /// farTest().isFar: the test updateIfFar makes.
  bool isFarAt(const std::array<Eigen::Vector3d, 5>& u, double& bound) const override {
    return farTest().isFar(u, bound);
  }
  double committedGap() const override { return committed_.gap; }
  bool committedClosed() const override { return committed_.status != ContactStatus::Open; }
  bool committedTension() const override {
    return committed_.status == ContactStatus::Open && committed_.force(0) != 0.0;
  }
  /// m from -masses M1 M2 when both are given, else the contactor node's mass and the sum of the
  /// four face nodes' masses (a face without mass is fixed: m = M1).
  double contactDuration(std::span<const double> nodeMasses, double gapRate) const override;
  /// The step over which the damping force's rise at the touch moves at most 1 % of the relative
  /// momentum m v (m = M1 M2 / (M1 + M2) from -masses): Kelvin, the jump C v, C h / (2 m) = 0.01
  /// (xi omega h = 0.01); Jankowski, c delta^(1/4) v with delta = v h, c v^(1/4) h^(5/4) /
  /// (2 m) = 0.01, v = |gapRate|; infinity for hertz and hertzdamp (their force starts from zero
  /// with zero slope).
  double touchStep(double gapRate) const override;
  /// The second half of updateIfFar, for a pair whose far test (farTest()) the caller made: sets
  /// the trial state of a far pair with distance bound `bound` and returns true, or changes
  /// nothing and returns false when the step must be evaluated (a release step). Without a
  /// search distance: false. Inline for the step of a far in both states pair (the gap alone
  /// changes), which is what every sleeping pair's step takes.
  bool setFarTrial(double bound, double dt) override {
    if (farInBothStates_ && search_.enabled()) {
      trial_.gap = bound;
      return true;
    }
    return setFarTrialFromCommitted(bound, dt);
  }
  /// The data of the far test (a copy, for the analysis' own arrays).
  FarTest farTest() const { return FarTest{X_, frame_.n, search_}; }
  /// True when the pair was far (beyond its search distance) in the last committed state.
  bool committedFar() const noexcept override {
    return search_.enabled() && committed_.status == ContactStatus::Open && !committed_.projValid &&
           committed_.gap > search_.distance();
  }
  /// True when the trial state is farther than `factor` x the search distance.
  bool trialFarBeyond(double factor) const noexcept override {
    return search_.enabled() && trial_.status == ContactStatus::Open && !trial_.projValid &&
           trial_.gap > factor * search_.distance();
  }
  bool hasSearch() const noexcept { return search_.enabled(); }
  /// True while the pair is far in both states: its trial and committed states are far, quiet and
  /// equal but for the gap (see farInBothStates_).
  bool farInBothStates() const noexcept override { return farInBothStates_; }
  /// Sets the gap of a far in both states pair in both states to `bound` (the analysis forms it
  /// anew for a pair it left alone for some steps); false, changing nothing, when not far in both
  /// states.
  bool setGapInBothStates(double bound) noexcept override {
    if (!farInBothStates_) return false;
    trial_.gap = committed_.gap = bound;
    return true;
  }
  /// True when the last committed state carried a compressive normal force (the next step may be
  /// a release step, which the far test must not skip).
  bool closedAtCommit() const noexcept {
    return committed_.status != ContactStatus::Open && committed_.force(0) > 0.0;
  }

  const NodeToSurfaceState& trialState() const noexcept { return trial_; }
  const NodeToSurfaceState& committedState() const noexcept { return committed_; }
  const SurfaceFrame& frame() const noexcept { return frame_; }
  const NodeToSurfaceParams& params() const noexcept { return params_; }

 private:
  void clearForces();
  /// setFarTrial's other cases: from a far committed state, or the release step (false).
  bool setFarTrialFromCommitted(double bound, double dt);
  /// True when `s` is open, off the quad, without force or dashpot power (the far state).
  static bool quietFar(const NodeToSurfaceState& s) noexcept {
    return s.status == ContactStatus::Open && !s.projValid && s.force.isZero(0.0) &&
           s.dashpotPower == 0.0;
  }

  // What a far pair's once-a-step test and its commit touch comes first, next to the start of
  // the object (the bases hold about 180 bytes: the vtable pointers of the element and of its two
  // interfaces, tag, node list and force vector), so that a sleeping pair costs a few cache
  // lines of one page per step.
  bool forcesZero_ = true;
  bool holding_ = false;           ///< update() evaluates held_ (see holdStatus)
  std::uint8_t switches_ = 0;      ///< switches of the held branches in this step
  std::uint8_t triedNormal_ = 0;   ///< normal branches held in this step (bit per branch)
  std::uint8_t triedSliding_ = 0;  ///< friction branches held in this step (1 stick, 2 slide)
  std::uint8_t crossings_ = 0;     ///< held closed branch: updates whose gap changed sign
  bool lastInside_ = false;        ///< held closed branch: the last update's gap was < 0
  bool frictionHeld_ = false;      ///< held_.sliding is held (else the next contact update's)
  bool powerClosed_ = false;       ///< last update: a power law's closed force (inside, or held)
  bool smoothClosed_ = false;      ///< ... and one smooth across the face
  double stepScale_ = 1.0;         ///< last update's newtonStepScale()
  std::uint8_t shrinks_ = 0;       ///< updates running (up to 2) with NormalLaw::slowShrink
  /// trial_ equals committed_ but for the gap, both quietFar, and the matrices are zero: set by a
  /// full commit or revert of such a state, cleared by every other write of trial_.
  bool farInBothStates_ = false;
  ContactSearch search_;
  NodeToSurfaceState trial_{};
  NodeToSurfaceState committed_{};
  NodeToSurfaceParams params_;
  NormalLaw normal_;
  CoulombFriction friction_;
  SurfaceFrame frame_;
  std::array<Eigen::Vector3d, 5> X_{};                ///< reference coordinates (k, a, b, c, d)
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();  ///< reference centroid of the quad
  NodeToSurfaceState initial_{};  ///< state of the undeformed geometry (set by initialize)
  /// Tangent stiffness and d(force)/d(velocity) at the last update (global), allocated by the
  /// first update that gives the pair a force (zero until then). The two matrices are 3.6 kB
  /// (ndf 3) of a pair's 4.7 kB; a pair that never touches (most pairs of a long viaduct at any
  /// time) stays small, and so spreads the rest of the model's data over less memory: with 800
  /// pairs among the elements they join, the model's iterations ran measurably slower when every
  /// pair held its matrices.
  struct Tangents {
    Matrix k = Matrix::Zero();
    Matrix c = Matrix::Zero();
  };
  std::unique_ptr<Tangents> tangents_;

  /// Branch of the normal law: no force; the law's closed force unclipped (Kelvin: -K g - C gdot;
  /// the name stays for every law); the law's spring alone, without its rate term (-K g for
  /// kelvin, k delta^n for a power law: the selection when closed and open cycle while the pair
  /// approaches, see checkHeldStatus; only for laws with a rate term); the release force.
  enum class NormalBranch : std::uint8_t { Open, Kelvin, Spring, Release };
  struct Branches {
    NormalBranch normal = NormalBranch::Open;
    bool sliding = false;  ///< in contact (Kelvin or Spring) with friction: sliding
    bool operator==(const Branches&) const = default;
  };
  static constexpr int kMaxSwitches = 8;
  /// Sign changes of the gap under a held closed jankowski branch after which an approaching pair
  /// holds the spring alone (see update()).
  static constexpr int kMaxCrossings = 1;
  static std::uint8_t bit(NormalBranch b) noexcept {
    return static_cast<std::uint8_t>(1u << static_cast<unsigned>(b));
  }
  /// Commit and revert end the step: nothing is held and no branch has been tried.
  void releaseHold() noexcept {
    holding_ = false;
    switches_ = triedNormal_ = triedSliding_ = crossings_ = shrinks_ = 0;
  }
  static bool inContact(NormalBranch b) noexcept {
    return b == NormalBranch::Kelvin || b == NormalBranch::Spring;
  }
  /// Notes the branches `b` as held in this step (a switch back to one of them would cycle).
  void noteTried(const Branches& b) noexcept {
    triedNormal_ = static_cast<std::uint8_t>(triedNormal_ | bit(b.normal));
    if (inContact(b.normal) && frictionHeld_)
      triedSliding_ = static_cast<std::uint8_t>(triedSliding_ | (b.sliding ? 2u : 1u));
  }
  Branches held_{};            ///< the held branches (while holding_)
  Branches natural_{};         ///< the branches the last update's state gives
  bool springAgrees_ = false;  ///< last update: g <= 0 and gdot <= 0 (the spring branch agrees)
  bool approaching_ = false;   ///< last update: gdot <= 0 (on the face)
  bool separating_ = false;    ///< last update: gdot > 0 (on the face; off it neither is set)
  bool slideAgrees_ = false;   ///< last update: trial friction force >= mu_k N (sliding agrees)
  bool onRamp_ = false;        ///< last update: a held power-law release force on its ramp
  Eigen::Vector2d trialFriction_ = Eigen::Vector2d::Zero();   ///< last update's trial force
  Eigen::Vector2d slideDirection_ = Eigen::Vector2d::Zero();  ///< trial force when slide was held
};

extern template class NodeToSurfaceContact3d<3>;
extern template class NodeToSurfaceContact3d<6>;

}  // namespace dabs::contact
