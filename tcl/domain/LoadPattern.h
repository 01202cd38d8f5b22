// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "elements/BeamLoad.h"
#include "tcl/domain/Constraints.h"
#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

class PlainPattern;
class MultipleSupportPattern;

/// Reference nodal load (one value per node dof).
struct NodalLoad {
  int node = 0;
  Eigen::VectorXd values;
};
/// Member load on a beam element in its local axes (eleLoad -type -beamUniform|-beamPoint).
struct ElementLoad {
  int element = 0;
  elements::BeamLoad load;
};
/// A node dof whose motion a pattern prescribes.
struct SupportDof {
  int node = 0;
  int dof = 0;                 ///< 0-based
  const char* source = "";     ///< the command that made it, for error messages
  bool imposedMotion = false;  ///< moves with an imposed velocity (MultipleSupport)
};
/// Prescribed displacement, velocity and acceleration of a support dof.
struct SupportMotion {
  double disp = 0.0;
  double vel = 0.0;
  double accel = 0.0;
};
/// Uniform ground acceleration a_g in one direction (0-based dof), applied as -M r a_g.
struct GroundAcceleration {
  int dof = 0;
  double value = 0.0;
};

/// A load pattern: a time series scaling loads or support motions. After `loadConst` a pattern
/// keeps the factor it had then, whatever the time (OpenSees' setLoadConstant). What a pattern
/// applies (nodal and member loads, support motions, a ground acceleration) it tells through the
/// virtual methods below, which are empty for the patterns that have none of it, so the domain
/// and the analysis never ask which kind of pattern they hold.
class LoadPattern {
 public:
  LoadPattern(int tag, std::shared_ptr<const TimeSeries> series, double fact)
      : tag_(tag), series_(std::move(series)), fact_(fact) {}
  virtual ~LoadPattern() = default;

  int tag() const noexcept { return tag_; }
  /// Load factor at time t: fact * series(t), or the frozen factor after loadConst.
  double factor(double t) const;
  /// False when the pattern has no single load factor (MultipleSupport: one per ground motion).
  virtual bool hasFactor() const { return true; }
  /// Freezes the factor at its value at time t.
  void setConstant(double t);
  bool isConstant() const noexcept { return constant_; }
  /// The pattern's time series (may be null for MultipleSupport).
  const TimeSeries* series() const noexcept { return series_.get(); }

  /// Reference nodal loads, each scaled by factor(t).
  virtual std::span<const NodalLoad> nodalLoads() const { return {}; }
  /// Member loads, each scaled by factor(t).
  virtual std::span<const ElementLoad> elementLoads() const { return {}; }
  /// Number of support dofs whose motion the pattern prescribes.
  virtual std::size_t supportCount() const { return 0; }
  /// Those support dofs, in the order of supportMotion.
  virtual std::vector<SupportDof> supportDofs() const { return {}; }
  /// The supports' motion at time t; `out` has supportCount() entries.
  virtual void supportMotion(double /*t*/, std::span<SupportMotion> /*out*/) const {}
  /// The uniform ground acceleration at time t, when the pattern is one.
  virtual std::optional<GroundAcceleration> groundAcceleration(double /*t*/) const {
    return std::nullopt;
  }
  /// Fixes whose place the pattern's supports took; removing the pattern fixes them again.
  virtual std::vector<SPConstraint> replacedFixes() const { return {}; }
  /// True when the pattern uses node `tag` (a load or a support).
  bool usesNode(int tag) const;

  /// This pattern as one that takes nodal loads, member loads and sp (load, eleLoad, sp), or null.
  virtual PlainPattern* asPlain() noexcept { return nullptr; }
  /// This pattern as one that takes ground motions (groundMotion, imposedMotion), or null.
  virtual MultipleSupportPattern* asMultipleSupport() noexcept { return nullptr; }

 private:
  int tag_;
  std::shared_ptr<const TimeSeries> series_;
  double fact_;
  bool constant_ = false;
  double frozenFactor_ = 0.0;
};

/// `pattern Plain`: nodal loads, member loads and prescribed displacements scaled by the series.
class PlainPattern : public LoadPattern {
 public:
  using NodalLoad = domain::NodalLoad;
  using ElementLoad = domain::ElementLoad;
  /// Prescribed displacement: dof (0-based) of node equals reference value times the factor.
  struct PrescribedDisp {
    int node = 0;
    int dof = 0;
    double reference = 0.0;
    bool constant = false;  ///< `sp -const`: not scaled by the series
  };

  PlainPattern(int tag, std::shared_ptr<const TimeSeries> series, double fact)
      : LoadPattern(tag, std::move(series), fact) {}

  std::span<const NodalLoad> nodalLoads() const override { return loads; }
  std::span<const ElementLoad> elementLoads() const override { return memberLoads; }
  std::size_t supportCount() const override { return prescribed.size(); }
  std::vector<SupportDof> supportDofs() const override;
  void supportMotion(double t, std::span<SupportMotion> out) const override;
  PlainPattern* asPlain() noexcept override { return this; }

  std::vector<NodalLoad> loads;
  std::vector<PrescribedDisp> prescribed;
  std::vector<ElementLoad> memberLoads;  ///< eleLoad, scaled like the nodal loads
};

/// `pattern UniformExcitation`: the supports all move with one ground acceleration in one
/// direction; the analysis applies the effective load -M r a_g(t) and reports relative response.
class UniformExcitation : public LoadPattern {
 public:
  UniformExcitation(int tag, int dof, std::shared_ptr<const TimeSeries> accel, double fact,
                    double vel0)
      : LoadPattern(tag, std::move(accel), fact), dof_(dof), vel0_(vel0) {}
  /// Direction of shaking as a 0-based dof index.
  int dof() const noexcept { return dof_; }
  /// Initial relative velocity given to every node with mass in that direction (-vel0).
  double vel0() const noexcept { return vel0_; }
  std::optional<GroundAcceleration> groundAcceleration(double t) const override {
    return GroundAcceleration{dof_, factor(t)};
  }

 private:
  int dof_;
  double vel0_;
};

/// A ground motion: displacement, velocity and acceleration histories of a support. Missing
/// histories are integrated from the acceleration (or velocity) by the trapezoid rule on the
/// series' own sampling interval, as OpenSees' TrapezoidalTimeSeriesIntegrator does.
class GroundMotion {
 public:
  GroundMotion(std::shared_ptr<const TimeSeries> accel, std::shared_ptr<const TimeSeries> vel,
               std::shared_ptr<const TimeSeries> disp, double fact);
  double disp(double t) const;
  double vel(double t) const;
  double accel(double t) const;

 private:
  double integrated(const std::vector<double>& values, double t) const;
  std::shared_ptr<const TimeSeries> accel_, vel_, disp_;
  double fact_;
  double step_ = 0.0;                        // sampling interval of the integrated histories
  mutable std::vector<double> velSamples_;   // integrated velocity at k*step_ (no vel series)
  mutable std::vector<double> dispSamples_;  // integrated displacement at k*step_ (no disp series)
};

/// `pattern MultipleSupport`: each support dof follows its own ground motion (imposedMotion).
/// Support dofs are prescribed with total displacement, velocity and acceleration, so the inner
/// nodes feel them through stiffness and damping coupling.
class MultipleSupportPattern : public LoadPattern {
 public:
  struct ImposedMotion {
    int node = 0;
    int dof = 0;  ///< 0-based
    int groundMotion = 0;
    /// The dof was fixed: the motion takes the fix's place while the pattern exists (OpenSees'
    /// Transformation handler lets the imposed motion win), and removing the pattern fixes the
    /// dof again.
    bool replacedFix = false;
  };
  explicit MultipleSupportPattern(int tag) : LoadPattern(tag, nullptr, 1.0) {}
  bool hasFactor() const override { return false; }
  std::size_t supportCount() const override { return imposed.size(); }
  std::vector<SupportDof> supportDofs() const override;
  void supportMotion(double t, std::span<SupportMotion> out) const override;
  std::vector<SPConstraint> replacedFixes() const override;
  MultipleSupportPattern* asMultipleSupport() noexcept override { return this; }

  std::map<int, std::unique_ptr<GroundMotion>> groundMotions;
  std::vector<ImposedMotion> imposed;
};

}  // namespace dabs::domain
