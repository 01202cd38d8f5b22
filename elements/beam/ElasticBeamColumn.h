// SPDX-License-Identifier: MIT
#pragma once

#include <cassert>
#include <cstring>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "elements/FixedSizeElement.h"
#include "elements/beam/BeamMemberLoads.h"
#include "elements/transform/CrdTransfNd.h"
#include "elements/transform/FrameTraits.h"

namespace dabs::elements {

/// What the 2D and 3D elastic beam-columns share (a template on the model dimension, as the
/// other frame code; elements/README.md): basic forces q = kb v through a coordinate
/// transformation, the stiffness formed once for transformations with a constant compatibility
/// matrix (Linear, PDelta: only the geometric part is added per update), the trial/commit state
/// and the responses. The derived class sets kb_ and the mass in initialize(). Member loads add
/// their fixed-end forces q0 to the basic forces and their reactions p0 to the end forces
/// (q = kb v + q0; OpenSees/OpenSees:SRC/element/elasticBeamColumn/ElasticBeam2d.cpp addLoad).
template <int Ndm>
class ElasticBeamColumn : public FixedSizeElement<2, FrameTraits<Ndm>::kDofPerNode> {
 public:
  using Transf = CrdTransfNd<Ndm>;
  static constexpr int Ndf = FrameTraits<Ndm>::kDofPerNode;
  using Vector = typename FixedSizeElement<2, Ndf>::Vector;

  ElasticBeamColumn(int tag, int nodeI, int nodeJ, std::unique_ptr<Transf> transf)
      : FixedSizeElement<2, Ndf>(tag, {nodeI, nodeJ}), transf_(std::move(transf)) {
    assert(transf_);
  }

  std::string_view typeName() const override { return "elasticBeamColumn"; }
  bool isLinear() const override { return transf_->isLinear(); }
  bool keepsStateAtSameDisplacements() const override { return stateCurrent_; }
  /// Under a linear transformation f = B^T kb B u, and the initial stiffness is B^T kb B: the
  /// same matrix (rigid offsets included), so the force is k0 u but for member loads.
  bool forceIsInitialStiffnessTimesDisplacements() const override {
    return constantTangent_ && loads_.empty();
  }
  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return this->kc_; }

  bool acceptsBeamLoads() const override { return true; }
  void zeroLoad() override {
    if (loads_.empty()) return;
    loads_.clear();
    stateCurrent_ = false;
  }
  void addLoad(const BeamLoad& load, double factor) override {
    loads_.add(load, factor, transf_->initialLength());
    stateCurrent_ = false;
  }

  [[nodiscard]] Status update(const Kinematics& trial) override {
    // Under a linear transformation the state is a function of the displacements and member
    // loads alone: the same displacements, bit for bit, give the same state, which is kept. (A
    // transient step's predictor leaves the displacements at the committed ones and updates
    // every element; on a linear frame that was half of all element updates.)
    if (stateCurrent_ && std::memcmp(trial.u.data(), uTrial_.data(), sizeof(uTrial_)) == 0)
      return Status::Ok;
    uTrial_ = trial.u;
    formState(uTrial_);
    // x * 0 is 0 for a finite x and NaN otherwise: one branch-free pass instead of allFinite().
    const bool finite = (this->f_.array() * 0.0).sum() == 0.0;
    stateCurrent_ = finite && constantTangent_;
    return finite ? Status::Ok : Status::NonFinite;
  }
  void commitState() override {
    transf_->commitState();
    uCommitted_ = uTrial_;
    // Under a linear transformation k_ is the constant k0_ (formState never changes it), so the
    // committed tangent already equals it: no 12 x 12 copy per step.
    if (!constantTangent_) this->kc_ = this->k_;
  }
  void revertToLastCommit() override {
    transf_->revertToLastCommit();
    uTrial_ = uCommitted_;
    formState(uTrial_);
    stateCurrent_ = false;
  }
  void revertToStart() override {
    transf_->revertToStart();
    resetState();
    this->kc_ = this->k_;
  }

  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override {
    if (args.size() != 1) return std::nullopt;
    const std::string& name = args[0];
    if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
      return Eigen::VectorXd(this->f_);
    if (name == "localForce" || name == "localForces")
      return Eigen::VectorXd(transf_->localForce(q_) + loads_.localEndForces());
    if (name == "basicForce" || name == "basicForces") return Eigen::VectorXd(q_);
    if (name == "deformations" || name == "basicDeformation" || name == "basicDeformations")
      return Eigen::VectorXd(transf_->basicDeformation());
    return std::nullopt;
  }

  /// Basic forces at the last update (2D: N, M_i, M_j; 3D: N, Mz_i, Mz_j, My_i, My_j, T).
  const typename Transf::Basic& basicForce() const noexcept { return q_; }
  const Transf& transformation() const noexcept { return *transf_; }

 protected:
  /// After kb_ is set: the initial global stiffness, formed once.
  void initializeStiffness() {
    this->k0_ = transf_->initialGlobalStiffness(kb_);
    constantCompat_ = transf_->hasConstantCompatibility();
    constantTangent_ = constantCompat_ && transf_->isLinear();
    this->k_ = this->k0_;
    this->kc_ = this->k0_;
  }
  /// Zero displacement, state formed from it.
  void resetState() {
    uTrial_.setZero();
    uCommitted_.setZero();
    formState(uTrial_);
    stateCurrent_ = false;
  }

  std::unique_ptr<Transf> transf_;
  typename Transf::BasicMatrix kb_ = Transf::BasicMatrix::Zero();

 private:
  void formState(const Vector& u) {
    transf_->update(u);
    q_ = kb_ * transf_->basicDeformation();
    if (!loads_.empty()) q_ += loads_.fixedEndForces();
    this->f_ = transf_->globalForce(q_);
    if (!loads_.empty()) this->f_ += globalReactions(*transf_, loads_);
    if (!constantCompat_) {
      this->k_ = transf_->globalStiffness(kb_, q_);
    } else if (!transf_->isLinear()) {
      this->k_ = this->k0_;
      transf_->addGeometricStiffness(this->k_, q_);
    }
  }

  typename Transf::Basic q_ = Transf::Basic::Zero();
  BeamMemberLoads<Transf::Basic::RowsAtCompileTime> loads_;
  bool constantCompat_ = false;   ///< B constant: k_ = k0_ + geometric part
  bool constantTangent_ = false;  ///< B constant and no geometric part: k_ = k0_ always
  /// The state is that of uTrial_ and the current member loads (kept by an update at uTrial_).
  bool stateCurrent_ = false;
  Vector uTrial_ = Vector::Zero();
  Vector uCommitted_ = Vector::Zero();
};

}  // namespace dabs::elements
