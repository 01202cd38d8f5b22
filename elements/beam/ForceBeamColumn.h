// SPDX-License-Identifier: MIT
#pragma once

#include <array>

#include "elements/beam/SectionBeamColumn.h"

namespace dabs::elements {

/// Force-based (flexibility) beam-column (`element forceBeamColumn`): section forces are exact
/// equilibrium interpolations s = b(x) q of the basic forces, so one element reproduces any
/// linear-moment member (Spacone, Filippou & Taucer 1996, Earthquake Eng. Struct. Dyn. 25(7);
/// OpenSees/OpenSees:SRC/element/forceBeamColumn/ForceBeamColumn3d.cpp). Element state
/// determination iterates on q until the compatible section deformations integrate to the trial
/// basic deformations (Neuenhofer & Filippou 1997, J. Struct. Eng. 123(7), the "iterative"
/// scheme), starting from the last trial state, with OpenSees' three strategies in turn (its
/// ForceBeamColumn2d/3d::update): Newton on the current section flexibilities (maxIter
/// iterations), the initial section flexibilities at every iteration (10 maxIter), and at the
/// first iteration only (maxIter), each from the update's start point. Where OpenSees then stops
/// (its default of one subdivision), this element starts again from the committed state and
/// splits the increment into 4 and 16 sub-increments; if those fail too, update() returns
/// Status::NotConverged (never loops forever). As in OpenSees,
/// an update whose basic deformations have not changed (a norm of DBL_EPSILON at most) keeps the
/// state without evaluating a section, unless member loads act or changed. Member loads add
/// their simply supported section forces: s(x) = b(x) q + sp(x), and their reactions to the end
/// forces (OpenSees' ForceBeamColumn2d::computeSectionForces and computeReactions).
template <int Ndm>
class ForceBeamColumn final : public SectionBeamColumn<Ndm> {
 public:
  using Super = SectionBeamColumn<Ndm>;
  using typename Super::Basic;
  using typename Super::BasicMatrix;
  using typename Super::Vector;
  static constexpr int kBasic = Super::kBasic;

  /// maxIter >= 1 and tol > 0 (OpenSees defaults 10 and 1e-12); as in OpenSees, an iteration
  /// has converged when the energy norm |dv . dq| of its correction is below tol.
  ForceBeamColumn(int tag, int nodeI, int nodeJ, std::vector<BeamIntegrationPoint> points,
                  std::unique_ptr<typename Super::Transf> transf, double massPerLength,
                  int maxIter = 10, double tol = 1e-12)
      : Super(tag, nodeI, nodeJ, std::move(points), std::move(transf), massPerLength),
        maxIter_(maxIter),
        tol_(tol) {}

  std::string_view typeName() const override { return "forceBeamColumn"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  /// Adds plasticDeformation (v - fe q with the initial section flexibilities) to the common
  /// responses.
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override;

 private:
  static constexpr int kMaxPoints = 20;
  /// Element state that the iterations change: basic forces, flexibility, section deformations,
  /// resisting forces and flexibilities at every point.
  struct State {
    Basic q = Basic::Zero();
    Basic v = Basic::Zero();
    BasicMatrix kb = BasicMatrix::Zero();
    std::array<SectionVector, kMaxPoints> e, sr;
    std::array<SectionMatrix, kMaxPoints> fs;
    /// Copies o's element data and its first n points.
    void assign(const State& o, int n) {
      q = o.q;
      v = o.v;
      kb = o.kb;
      for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) {
        e[i] = o.e[i];
        sr[i] = o.sr[i];
        fs[i] = o.fs[i];
      }
    }
  };
  /// The section flexibility a local iteration corrects the section deformations with.
  enum class Correction {
    Current,       ///< the current one (Newton), maxIter iterations
    Initial,       ///< the initial one at every iteration, 10 maxIter iterations
    InitialFirst,  ///< the initial one at the first iteration, then the current one
  };
  void loadsChanged() override;
  Status iterate(State& s, const Basic& target, Correction c = Correction::Current) const;
  /// iterate() with the section arrays seen as fixed-size matrices of `Order` rows (all sections
  /// of that order) or as they are (Eigen::Dynamic).
  template <int Order>
  Status iterateWith(State& s, const Basic& target, Correction c) const;
  Status solve(const Basic& target);
  void finish();
  /// Trial and committed states at the virgin state formed by initialize() (no deformation).
  void startFromVirginState();

  int maxIter_;
  double tol_;
  std::vector<SectionBasicMatrix<kBasic>> bmat_;
  BasicMatrix fe_ = BasicMatrix::Zero();  ///< initial (elastic) flexibility
  /// Section forces of the member loads in the basic system, per point (empty without loads).
  std::vector<SectionVector> sp_;
  State trial_, committed_;
  /// The state at zero deformation, formed once by initialize(); its fs are the sections'
  /// initial flexibilities, which the initial-flexibility strategies iterate with.
  State virgin_;
  State attemptStart_;            ///< an update's start point, for its second and third strategy
  bool trialIsCommitted_ = true;  ///< trial_ equals committed_ (no update since commit/revert)
  /// Updated since initialize(), revertToStart() or the last change of member loads.
  bool updated_ = false;
};

using ForceBeamColumn2d = ForceBeamColumn<2>;
using ForceBeamColumn3d = ForceBeamColumn<3>;

}  // namespace dabs::elements
