// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>

#include "elements/FixedSizeElement.h"
#include "elements/beam/SectionInterpolation.h"
#include "elements/transform/FrameTraits.h"
#include "materials/section/SectionForceDeformation.h"

namespace dabs::elements {

/// `element zeroLengthSection tag i j secTag ?-orient x1 x2 x3 yp1 yp2 yp3?`: a section between two
/// nodes at the same place, its deformations the relative displacements and rotations of node j
/// with respect to node i in local axes (OpenSees/OpenSees:SRC/element/zeroLength/
/// ZeroLengthSection.cpp): P along local x, Vy along y, Vz along z, T about x, My about y, Mz
/// about z. Local axes: x the orient x vector, z = x cross yp, y = z cross x (defaults: global X
/// and Y). Used for moment-curvature analysis, where the deformation is the curvature.
template <int Ndm>
class ZeroLengthSection final : public FixedSizeElement<2, FrameTraits<Ndm>::kDofPerNode> {
 public:
  using Base = FixedSizeElement<2, FrameTraits<Ndm>::kDofPerNode>;
  using typename Base::Matrix;
  using typename Base::Vector;
  static constexpr int kNumDof = Base::kNumDof;

  /// Throws InputError when x or yp is zero, they are parallel, or (2D) the section has a
  /// resultant a planar model does not have (My, Vz, T) or x/yp leave the X-Y plane.
  ZeroLengthSection(int tag, int nodeI, int nodeJ,
                    std::unique_ptr<materials::section::SectionForceDeformation> section,
                    const Eigen::Vector3d& x = Eigen::Vector3d::UnitX(),
                    const Eigen::Vector3d& yp = Eigen::Vector3d::UnitY());

  std::string_view typeName() const override { return "zeroLengthSection"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  bool rayleighByDefault() const override { return false; }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return this->kc_; }
  void commitState() override {
    section_->commitState();
    this->kc_ = this->k_;
  }
  long materialUpdates() const override { return section_->materialUpdates(); }
  void revertToLastCommit() override;
  void revertToStart() override;
  /// force/globalForce, basicForce/localForce (section resultants), deformation(s)/
  /// basicDeformation (section deformations), and `section ...` forwarded to the section.
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;
  std::string describe() const override;

  const materials::section::SectionForceDeformation& section() const { return *section_; }
  /// Local axes as rows (x, y, z), global components.
  const Eigen::Matrix3d& axes() const noexcept { return axes_; }

 private:
  using Compat = Eigen::Matrix<double, Eigen::Dynamic, kNumDof, 0, kMaxSectionOrder, kNumDof>;
  void formState();

  std::unique_ptr<materials::section::SectionForceDeformation> section_;
  Eigen::Matrix3d axes_ = Eigen::Matrix3d::Identity();
  Compat a_;         ///< section deformations = a_ u
  Compat ka_;        ///< scratch: ks a_
  SectionVector e_;  ///< scratch: trial section deformations
};

using ZeroLengthSection2d = ZeroLengthSection<2>;
using ZeroLengthSection3d = ZeroLengthSection<3>;

}  // namespace dabs::elements
