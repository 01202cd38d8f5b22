// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "elements/BeamLoad.h"
#include "materials/InputError.h"
#include "materials/Status.h"

namespace dabs::elements {

class FarPair;
class ContactPredictor;

/// Coordinates of an element's nodes in node order, each padded to 3D with zeros (a 2D model's
/// node (x, y) is (x, y, 0)).
using NodalCoordinates = std::vector<Eigen::Vector3d>;

/// Trial kinematics of one element, gathered by the domain in the element's dof order (node by
/// node, each node's dofs in order 1..ndf). All vectors are TOTAL values in the global frame.
struct Kinematics {
  Eigen::Ref<const Eigen::VectorXd> u;  ///< trial displacement
  Eigen::Ref<const Eigen::VectorXd> v;  ///< trial velocity
  Eigen::Ref<const Eigen::VectorXd> a;  ///< trial acceleration
  double time = 0.0;                    ///< trial (pseudo) time
  double dt = 0.0;                      ///< trial time minus committed time (0 in static steps)
};

/// A finite element seen by the domain. Elements store no Node* or Domain* (style.md section 3):
/// the domain passes coordinates once and trial kinematics at every update, so an element can be
/// tested alone. Getters never compute state: all state work happens in update().
///
/// Force convention: resistingForce() is the element's internal force on its nodes (global frame),
/// i.e. the force the nodes must apply to the element; it includes the element's own
/// velocity-dependent forces (dashpots) but not Rayleigh damping and not inertia, which the domain
/// forms from mass() and the Rayleigh factors.
class Element {
 public:
  explicit Element(int tag) noexcept : tag_(tag) {}
  virtual ~Element() = default;
  Element(const Element&) = delete;
  Element& operator=(const Element&) = delete;

  /// User tag given in the `element` command.
  int tag() const noexcept { return tag_; }
  /// Type name as in the `element` command (e.g. "zeroLength").
  virtual std::string_view typeName() const = 0;
  /// Tags of the connected nodes, in element order.
  virtual const std::vector<int>& nodeTags() const = 0;
  /// Number of element dofs (nodes x dofs per node).
  virtual int numDof() const = 0;
  /// Dofs per node the element expects; the domain checks each node has exactly this many.
  virtual int dofPerNode() const = 0;

  /// Called once when the element joins a domain, with its nodes' coordinates. Throws InputError
  /// for impossible geometry (zero length, vecxz parallel to the axis) so the command can report
  /// it.
  virtual void initialize(const NodalCoordinates& x) = 0;
  /// Sets the trial state from trial kinematics, starting from the committed state.
  [[nodiscard]] virtual Status update(const Kinematics& trial) = 0;

  /// Internal force (global frame) at the last update.
  virtual Eigen::Ref<const Eigen::VectorXd> resistingForce() const = 0;
  /// d(resistingForce)/du at the last update (global frame).
  virtual Eigen::Ref<const Eigen::MatrixXd> tangentStiff() const = 0;
  /// Stiffness of the virgin element (global frame).
  virtual Eigen::Ref<const Eigen::MatrixXd> initialStiff() const = 0;
  /// Tangent stiffness at the last commit, for Rayleigh betaKcomm (the initial stiffness before
  /// the first commit). Elements whose tangent changes override it; the default, the initial
  /// stiffness, is right for linear elements.
  virtual Eigen::Ref<const Eigen::MatrixXd> committedStiff() const { return initialStiff(); }
  /// d(resistingForce)/dv: the element's own dashpots (not Rayleigh). Zero by default.
  virtual Eigen::Ref<const Eigen::MatrixXd> dampingTangent() const;
  /// Mass matrix (global frame). Zero by default.
  virtual Eigen::Ref<const Eigen::MatrixXd> mass() const;
  /// The entries (column-major, j * numDof() + i, ascending) where tangentStiff, initialStiff,
  /// committedStiff, dampingTangent and mass can be nonzero; empty (the default) when any can.
  /// The assembly forms and adds only these: a zeroLength spring reaches 4 of its 144.
  virtual std::span<const int> matrixSupport() const { return {}; }
  /// True when tangentStiff() may be non-symmetric (sliding friction): the solver must use LU.
  virtual bool hasNonSymmetricTangent() const { return false; }
  /// True when Rayleigh damping applies to this element unless a region says otherwise
  /// (OpenSees: zeroLength and truss default to no Rayleigh damping, beams to yes).
  virtual bool rayleighByDefault() const { return true; }
  /// True when the element is linear, so its tangent never changes and needs no re-forming.
  virtual bool isLinear() const { return false; }
  /// True when the force is initialStiff() times the displacements and the whole state a function
  /// of the displacements alone (no member load, no dashpot, no history): the analysis may then
  /// form the force together with every such element's as one product with their assembled
  /// stiffness, and leave the element itself to be updated only when its state is read
  /// (Domain::setStateDeferred).
  virtual bool forceIsInitialStiffnessTimesDisplacements() const { return false; }
  /// True when the trial state is the one its last update formed and is a function of the nodes'
  /// displacements alone (not their rates, the time or a load changed since): an update at the
  /// same displacements would leave it as it is, so the analysis may skip that update. It stays
  /// true until an update at other displacements, a revert or a load change.
  virtual bool keepsStateAtSameDisplacements() const { return false; }
  /// False while the element's force, stiffness, damping and mass are all zero (an open contact):
  /// the assembly then skips it, though its place in the sparse pattern stays reserved.
  virtual bool isActive() const { return true; }
  /// True for an element that may turn inactive during an analysis (isActive false): the
  /// analysis then keeps its mass and Rayleigh damping out of the matrices it forms once and
  /// adds its inertia and damping forces itself while it is active.
  virtual bool mayTurnInactive() const { return false; }
  /// Material updates (setTrialStrain calls of section materials) since construction: a work count
  /// for benchmarks, not part of the state.
  virtual long materialUpdates() const { return 0; }

  /// Held statuses (an active-set method for the iterations of a step). An element whose force
  /// switches between laws with its state (a contact: open or closed, sticking or sliding) makes
  /// the step's equations nonsmooth, and Newton may cycle between the laws without converging.
  /// Once the analysis holds the statuses, update() evaluates the law of the held status whatever
  /// the trial, so the equations are smooth; when the iterations converge, checkHeldStatus()
  /// compares the held status with the one the converged state gives, and a disagreement makes
  /// the element hold that one and the analysis iterate on. Commit and revert release the hold.
  enum class HeldStatus {
    Agrees,    ///< nothing held, or the held status is the state's own
    Switched,  ///< the element now holds another status: update again and iterate on
    Conflict   ///< no status the element may hold agrees with the state (the step fails)
  };
  /// True when the element has statuses to hold.
  virtual bool switchesStatus() const { return false; }
  /// Holds the status of the last update.
  virtual void holdStatus() {}
  /// See HeldStatus; call after an update.
  virtual HeldStatus checkHeldStatus() { return HeldStatus::Agrees; }
  /// True when the element may ask Newton for a longer step (newtonStepScale).
  virtual bool scalesNewtonSteps() const { return false; }
  /// The multiple of the step Newton just took (the change from the element's previous update
  /// to its last one) that the element asks for: 1 for none. An element whose force is far from
  /// linear in its deformation where Newton converges slowly on it (a contact spring k delta^n
  /// from a deep penetration) asks for the step Newton on a variable in which it is linear would
  /// take. Call after an update.
  virtual double newtonStepScale() const { return 1.0; }

  /// The element's far-pair interface when it may sleep while far from contact (a contact pair
  /// with a search distance), else null. The analysis reaches such elements through it alone, so
  /// a new contact element needs no change to the solver.
  virtual FarPair* farPair() noexcept { return nullptr; }
  /// The element's contact prediction for contact stepping when it makes and breaks contact,
  /// else null.
  virtual const ContactPredictor* contactPredictor() const noexcept { return nullptr; }

  /// True when the element takes member loads (addLoad).
  virtual bool acceptsBeamLoads() const { return false; }
  /// Removes every member load; the domain calls it before it applies the load patterns' member
  /// loads at a new time (OpenSees' zeroLoad).
  virtual void zeroLoad() {}
  /// Adds `factor` times a member load, in effect from the next update. Throws InputError when the
  /// element takes no member loads or the load does not fit it.
  virtual void addLoad(const BeamLoad& load, double factor);

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  /// Named response for `eleResponse` and element recorders (e.g. {"force"},
  /// {"section","2","force"}); nullopt when the name is unknown.
  virtual std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const;
  /// Human-readable description for `print -ele`.
  virtual std::string describe() const;

 private:
  int tag_;
};

}  // namespace dabs::elements
