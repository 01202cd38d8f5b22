// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "materials/UniaxialMaterial.h"
#include "materials/section/FiberGroup.h"
#include "materials/section/SectionForceDeformation.h"

namespace dabs::materials::section {

/// Fiber section (`section Fiber tag ?-GJ GJ? {...}`): plane sections remain plane, each fiber a
/// uniaxial material at (y, z) with area A (OpenSees/OpenSees:SRC/material/section/
/// FiberSection2d.cpp and FiberSection3d.cpp).
///  - 2D: resultants [P, Mz], deformations [eps, kz], fiber strain eps - y kz.
///  - 3D: resultants [P, Mz, My, T], deformations [eps, kz, ky, twist], fiber strain
///    eps - y kz + z ky, and an uncoupled linear torsion T = GJ twist.
/// Fibers are kept in groups by material type (FiberGroup): coordinates, areas and material states
/// side by side, updated in one loop each; the section owns its materials' copies.
template <int Ndm>
class FiberSection final : public SectionForceDeformation {
 public:
  static constexpr int kOrder = Ndm == 2 ? 2 : 4;
  struct Fiber {
    double y = 0.0, z = 0.0, area = 0.0;
    const UniaxialMaterial* material = nullptr;  ///< prototype, cloned by the constructor
  };

  /// `torsionStiffness` (GJ) is used in 3D only. With `aboutCentroid` the strains are taken
  /// about the fibers' area centroid (y - yBar, z - zBar; yBar = sum A y / sum A, z in 3D only),
  /// as OpenSees' FiberSection2d/3d do unless `-noCentroid` (OpenSees/OpenSees:SRC/material/
  /// section/FiberSection2d.cpp, yBar = QzBar / ABar): the section's reference axis is then its
  /// area centroid, whatever the coordinates the fibers were given in; without it the axis is
  /// y = 0 (and z = 0) of those coordinates. Fibers keep their given coordinates for responses.
  /// Throws InputError when there are no fibers or a fiber has a nonpositive area.
  FiberSection(int tag, const std::vector<Fiber>& fibers, double torsionStiffness = 0.0,
               bool aboutCentroid = false);
  /// The reference axis' position in the fibers' coordinates (0, 0 without aboutCentroid).
  double centroidY() const noexcept { return yBar_; }
  double centroidZ() const noexcept { return zBar_; }
  FiberSection(const FiberSection& other);
  FiberSection(FiberSection&&) noexcept = default;

  int order() const override { return kOrder; }
  std::span<const SectionCode> type() const override;
  [[nodiscard]] Status setTrialDeformation(const Eigen::Ref<const Eigen::VectorXd>& e) override;
  Eigen::Ref<const Eigen::VectorXd> getDeformation() const override { return e_; }
  Eigen::Ref<const Eigen::VectorXd> getStressResultant() const override { return s_; }
  Eigen::Ref<const Eigen::MatrixXd> getSectionTangent() const override { return k_; }
  Eigen::Ref<const Eigen::MatrixXd> getInitialTangent() const override { return k0_; }
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  std::unique_ptr<SectionForceDeformation> clone() const override {
    return std::make_unique<FiberSection>(*this);
  }
  /// The fiber strains are a function of the deformations, the torsion is elastic.
  bool keepsStateAtSameDeformation() const override {
    for (const auto& g : groups_)
      if (!g->keepsStateAtSameStrains()) return false;
    return true;
  }
  /// {"force"}, {"deformation"}, {"fiber", y, z, ?matTag?, "stressStrain"} (nearest fiber,
  /// optionally among those of material matTag: [stress, strain]).
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

  /// Fibers in the order they were given (as given: fibers merged for the evaluation are
  /// listed each with its own place and area).
  int numFibers() const noexcept { return static_cast<int>(places_->size()); }
  double fiberY(int i) const { return place(i).y; }
  double fiberZ(int i) const { return place(i).z; }
  double fiberArea(int i) const { return place(i).area; }
  /// Fiber i's trial stress and strain, and its material's tag.
  double fiberStress(int i) const { return group(i).stress(index(i)); }
  double fiberStrain(int i) const { return group(i).strain(index(i)); }
  int fiberMaterialTag(int i) const { return group(i).materialTag(); }
  /// Fiber material updates (setTrialStrain calls) since construction, for benchmarks.
  long materialUpdates() const noexcept override { return materialUpdates_; }

 private:
  using Vector = Eigen::Matrix<double, kOrder, 1>;
  using Matrix = Eigen::Matrix<double, kOrder, kOrder>;
  /// s_ and k_ (or k0_) from fiber sums, plus the uncoupled torsion in 3D.
  void store(const FiberSums& sums, bool initial);
  void sumCurrent();
  /// A fiber as given, and where it is evaluated.
  struct Place {
    double y = 0.0, z = 0.0, area = 0.0;
    std::size_t group = 0;  ///< its group
    int index = 0;          ///< its fiber in the group (shared by fibers merged into one)
  };
  const Place& place(int i) const { return (*places_)[static_cast<std::size_t>(i)]; }
  const FiberGroup& group(int i) const { return *groups_[place(i).group]; }
  int index(int i) const { return place(i).index; }

  std::vector<std::unique_ptr<FiberGroup>> groups_;
  /// The fibers as given, shared by the copies of the section (they never change).
  std::shared_ptr<const std::vector<Place>> places_;
  double gj_ = 0.0;
  Vector e_ = Vector::Zero(), eCommitted_ = Vector::Zero(), s_ = Vector::Zero();
  Matrix k_ = Matrix::Zero(), k0_ = Matrix::Zero();
  long materialUpdates_ = 0;
  int evaluatedFibers_ = 0;  ///< fibers after merging (the groups' sizes), a pass's updates
  double yBar_ = 0.0;        ///< reference axis in the fibers' coordinates (area centroid or 0)
  double zBar_ = 0.0;
};

using FiberSection2d = FiberSection<2>;
using FiberSection3d = FiberSection<3>;

}  // namespace dabs::materials::section
