// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "materials/ResponseArgs.h"
#include "elements/FixedSizeElement.h"
#include "elements/beam/SectionInterpolation.h"
#include "elements/transform/CrdTransfNd.h"
#include "elements/transform/FrameTraits.h"
#include "elements/beam/BeamMemberLoads.h"
#include "elements/beam/ConsistentMass.h"

namespace dabs::elements {

/// One integration point of a section-based beam-column.
struct BeamIntegrationPoint {
  std::unique_ptr<materials::section::SectionForceDeformation> section;
  double xi = 0.0;      ///< location in [0, 1]
  double weight = 0.0;  ///< weight (sum 1)
};

/// Common part of forceBeamColumn and dispBeamColumn: transformation, integration points,
/// lumped mass and the responses that do not depend on the formulation.
template <int Ndm>
class SectionBeamColumn : public FixedSizeElement<2, FrameTraits<Ndm>::kDofPerNode> {
 public:
  using Traits = FrameTraits<Ndm>;
  using Transf = typename Traits::Transf;
  using Basic = typename Transf::Basic;
  using BasicMatrix = typename Transf::BasicMatrix;
  using Base = FixedSizeElement<2, Traits::kDofPerNode>;
  using typename Base::Matrix;
  using typename Base::Vector;
  static constexpr int kBasic = Traits::kBasic;

  /// `points` hold section clones with their locations and weights; `massPerLength` >= 0.
  SectionBeamColumn(int tag, int nodeI, int nodeJ, std::vector<BeamIntegrationPoint> points,
                    std::unique_ptr<Transf> transf, double massPerLength)
      : Base(tag, {nodeI, nodeJ}),
        points_(std::move(points)),
        transf_(std::move(transf)),
        massPerLength_(massPerLength) {}

  /// -cMass: consistent instead of lumped mass (cubic transverse, linear axial, no rotary or
  /// torsional inertia, as OpenSees' force/disp beam-columns). Call before initialize().
  void setConsistentMass(bool consistent) noexcept { consistentMass_ = consistent; }

  Eigen::Ref<const Eigen::MatrixXd> committedStiff() const override { return this->kc_; }

  bool acceptsBeamLoads() const override { return true; }
  void zeroLoad() override {
    if (loads_.empty()) return;
    loads_.clear();
    loadsChanged();
  }
  void addLoad(const BeamLoad& load, double factor) override {
    loads_.add(load, factor, transf_->initialLength());
    loadsChanged();
  }

  /// Basic forces at the last update.
  const Basic& basicForce() const noexcept { return q_; }
  const Transf& transformation() const noexcept { return *transf_; }
  int numSections() const noexcept { return static_cast<int>(points_.size()); }
  const materials::section::SectionForceDeformation& section(int i) const {
    return *points_[i].section;
  }

  long materialUpdates() const override {
    long n = 0;
    for (const auto& p : points_) n += p.section->materialUpdates();
    return n;
  }

  /// globalForce, localForce, basicForce, basicDeformation, integrationPoints, and
  /// `section i ...` (1-based i) forwarded to the section.
  std::optional<Eigen::VectorXd> response(std::span<const std::string> args) const override {
    if (args.empty()) return std::nullopt;
    const std::string& name = args[0];
    if (name == "section" && args.size() >= 3) {
      const std::optional<int> i = responseInteger(args[1]);
      if (!i || *i < 1 || *i > numSections()) return std::nullopt;
      return points_[*i - 1].section->response(args.subspan(2));
    }
    if (args.size() != 1) return std::nullopt;
    if (name == "force" || name == "forces" || name == "globalForce" || name == "globalForces")
      return Eigen::VectorXd(this->f_);
    if (name == "localForce" || name == "localForces")
      return Eigen::VectorXd(transf_->localForce(q_) + loads_.localEndForces());
    if (name == "basicForce" || name == "basicForces") return Eigen::VectorXd(q_);
    if (name == "basicDeformation" || name == "basicDeformations" || name == "deformations")
      return Eigen::VectorXd(transf_->basicDeformation());
    if (name == "integrationPoints") {
      Eigen::VectorXd x(numSections());
      for (int i = 0; i < numSections(); ++i) x(i) = points_[i].xi * transf_->initialLength();
      return x;
    }
    if (name == "integrationWeights") {
      Eigen::VectorXd w(numSections());
      for (int i = 0; i < numSections(); ++i) w(i) = points_[i].weight * transf_->initialLength();
      return w;
    }
    return std::nullopt;
  }

 protected:
  /// Called after the member loads changed (force-based elements recompute their section loads).
  virtual void loadsChanged() {}
  /// Global end forces of the basic forces q plus the member loads' reactions.
  Vector endForces(const Basic& q) const {
    Vector f = transf_->globalForce(q);
    if (!loads_.empty()) f += globalReactions(*transf_, loads_);
    return f;
  }

  /// Sets the transformation, lumped mass and point data; throws InputError for bad geometry.
  void initializeGeometry(const NodalCoordinates& x) {
    if (x.size() != 2) throw InputError("element", "needs 2 nodes");
    transf_->initialize(x[0], x[1]);
    uniformOrder_ = points_.empty() ? 0 : points_.front().section->order();
    for (const auto& p : points_)
      if (p.section->order() != uniformOrder_) uniformOrder_ = 0;
    this->m_.setZero();
    const double mass = massPerLength_ * transf_->initialLength();
    if (consistentMass_ && mass > 0.0) {
      this->m_ = transf_->globalFromLocal(consistentMass<Ndm>(mass, transf_->initialLength()));
      return;
    }
    for (int n = 0; n < 2; ++n)
      for (int d = 0; d < Ndm; ++d)
        this->m_(n * Traits::kDofPerNode + d, n * Traits::kDofPerNode + d) = 0.5 * mass;
  }

  std::vector<BeamIntegrationPoint> points_;
  /// The order all sections share (the section loops then run on fixed-size matrices), or 0.
  int uniformOrder_ = 0;
  std::unique_ptr<Transf> transf_;
  double massPerLength_ = 0.0;
  bool consistentMass_ = false;
  BeamMemberLoads<kBasic> loads_;
  Basic q_ = Basic::Zero();
  Vector uTrial_ = Vector::Zero();
  Vector uCommitted_ = Vector::Zero();
};

}  // namespace dabs::elements
