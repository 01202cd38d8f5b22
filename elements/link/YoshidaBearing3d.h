// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "elements/FixedSizeElement.h"
#include "materials/BiaxialMaterial.h"

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
/// The element's own viscous force (the material's Maxwell part) is a function of the
/// displacement increment over the step, so dampingTangent() is zero and the Maxwell stiffness is
/// in tangentStiff(). Rayleigh damping does not apply by default (as for OpenSees zero-length
/// links).
class YoshidaBearing3d final : public FixedSizeElement<2, 6> {
 public:
  /// What a bearing does once it reaches its failure shear strain: keep carrying load as if intact
  /// (the default, Yoshida et al.'s model has no rupture), release its shear force, or keep
  /// carrying it while the analysis stops (AnalysisBuilder returns kBearingFailureStop).
  enum class AfterFailure { Keep, Release, Stop };

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
  };

  /// `p` must be valid; the material is cloned.
  YoshidaBearing3d(int tag, int iNode, int jNode, const materials::BiaxialMaterial& material,
                   const Params& p);

  std::string_view typeName() const override { return "yoshidaBearing"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  bool rayleighByDefault() const override { return false; }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return kc_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  /// force/globalForce (12), localForce (12), basicForce (6), deformation/basicDeformation (6),
  /// shearStrain, maxShearStrain, damage, failureTime (1 each), and the material's
  /// hystereticForce, viscousForce, backForce (2, local y-z), dissipatedEnergy (1).
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::string describe() const override;

  /// 0 below the design limit, 1 beyond it, 2 failed (trial state).
  int damage() const noexcept;
  /// Rotation from global to local: rows are the local x, y, z axes in global coordinates.
  const Eigen::Matrix3d& axes() const noexcept { return axes_; }
  const State& trialState() const noexcept { return trial_; }
  const State& committedState() const noexcept { return committed_; }
  const Params& params() const noexcept { return p_; }

 private:
  using Basic = Eigen::Matrix<double, 6, 1>;
  using BasicMatrix = Eigen::Matrix<double, 6, 6>;
  bool released() const noexcept {
    return committed_.failed && p_.afterFailure == AfterFailure::Release;
  }
  void assemble(const Basic& q, const BasicMatrix& kb);

  std::unique_ptr<materials::BiaxialMaterial> material_;
  Params p_;
  double length_ = 0.0;
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix<double, 6, kNumDof> b_ = Eigen::Matrix<double, 6, kNumDof>::Zero();  ///< global B
  State trial_{};
  State committed_{};
};

}  // namespace dabs::elements
