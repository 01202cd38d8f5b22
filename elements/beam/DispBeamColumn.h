// SPDX-License-Identifier: MIT
#pragma once

#include "elements/beam/SectionBeamColumn.h"

namespace dabs::elements {

/// Displacement-based beam-column (`element dispBeamColumn`): section deformations interpolated
/// from the basic deformations (linear axial strain and curvature, Hermitian cubic transverse
/// displacement), q = sum w L B^T s and kb = sum w L B^T ks B over the integration points (the
/// formulation of OpenSees/OpenSees:SRC/element/dispBeamColumn/DispBeamColumn3d.cpp). Needs
/// several elements per member when the curvature is not linear.
template <int Ndm>
class DispBeamColumn final : public SectionBeamColumn<Ndm> {
 public:
  using Super = SectionBeamColumn<Ndm>;
  using Super::Super;
  using typename Super::Basic;
  using typename Super::BasicMatrix;
  using typename Super::Vector;

  std::string_view typeName() const override { return "dispBeamColumn"; }
  void initialize(const NodalCoordinates& x) override;
  [[nodiscard]] Status update(const Kinematics& trial) override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  /// After an update, under a linear transformation and with sections that keep their state at
  /// the same deformations (fiber sections of Concrete01/02, Steel01/02, elastic materials): the
  /// state is then a function of the displacements, and an update at the same ones (a transient
  /// step's predictor, which moves only the rates) would leave it as it is. OpenSees updates it.
  bool keepsStateAtSameDisplacements() const override { return stateCurrent_ && keepsState_; }
  void loadsChanged() override { stateCurrent_ = false; }

 private:
  Status formState(bool initial);
  /// formState() with the section arrays seen as fixed-size matrices of `Order` rows.
  template <int Order>
  Status formStateWith(bool initial);
  std::vector<SectionBasicMatrix<Super::kBasic>> bmat_;
  BasicMatrix kb_ = BasicMatrix::Zero();
  bool keepsState_ = false;    ///< linear transformation, sections that keep their state
  bool stateCurrent_ = false;  ///< the state is the one the last update formed
};

using DispBeamColumn2d = DispBeamColumn<2>;
using DispBeamColumn3d = DispBeamColumn<3>;

}  // namespace dabs::elements
