// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <vector>

#include "elements/BeamLoad.h"
#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// A load pattern: a time series scaling loads or support motions. After `loadConst` a pattern
/// keeps the factor it had then, whatever the time (OpenSees' setLoadConstant).
class LoadPattern {
 public:
  enum class Kind { Plain, UniformExcitation, MultipleSupport };

  LoadPattern(int tag, Kind kind, std::shared_ptr<const TimeSeries> series, double fact)
      : tag_(tag), kind_(kind), series_(std::move(series)), fact_(fact) {}
  virtual ~LoadPattern() = default;

  int tag() const noexcept { return tag_; }
  Kind kind() const noexcept { return kind_; }
  /// Load factor at time t: fact * series(t), or the frozen factor after loadConst.
  double factor(double t) const;
  /// Freezes the factor at its value at time t.
  void setConstant(double t);
  bool isConstant() const noexcept { return constant_; }
  /// The pattern's time series (may be null for MultipleSupport).
  const TimeSeries* series() const noexcept { return series_.get(); }

 private:
  int tag_;
  Kind kind_;
  std::shared_ptr<const TimeSeries> series_;
  double fact_;
  bool constant_ = false;
  double frozenFactor_ = 0.0;
};

/// `pattern Plain`: nodal loads, member loads and prescribed displacements scaled by the series.
class PlainPattern : public LoadPattern {
 public:
  /// Reference nodal load (one value per node dof).
  struct NodalLoad {
    int node = 0;
    Eigen::VectorXd values;
  };
  /// Prescribed displacement: dof (0-based) of node equals reference value times the factor.
  struct PrescribedDisp {
    int node = 0;
    int dof = 0;
    double reference = 0.0;
    bool constant = false;  ///< `sp -const`: not scaled by the series
  };
  /// Member load on a beam element in its local axes (eleLoad -type -beamUniform|-beamPoint),
  /// scaled like the nodal loads.
  struct ElementLoad {
    int element = 0;
    elements::BeamLoad load;
  };

  PlainPattern(int tag, std::shared_ptr<const TimeSeries> series, double fact)
      : LoadPattern(tag, Kind::Plain, std::move(series), fact) {}

  std::vector<NodalLoad> loads;
  std::vector<PrescribedDisp> prescribed;
  std::vector<ElementLoad> elementLoads;
};

/// `pattern UniformExcitation`: the supports all move with one ground acceleration in one
/// direction; the analysis applies the effective load -M r a_g(t) and reports relative response.
class UniformExcitation : public LoadPattern {
 public:
  UniformExcitation(int tag, int dof, std::shared_ptr<const TimeSeries> accel, double fact,
                    double vel0)
      : LoadPattern(tag, Kind::UniformExcitation, std::move(accel), fact), dof_(dof), vel0_(vel0) {}
  /// Direction of shaking as a 0-based dof index.
  int dof() const noexcept { return dof_; }
  /// Initial relative velocity given to every node with mass in that direction (-vel0).
  double vel0() const noexcept { return vel0_; }

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
  explicit MultipleSupportPattern(int tag)
      : LoadPattern(tag, Kind::MultipleSupport, nullptr, 1.0) {}
  std::map<int, std::unique_ptr<GroundMotion>> groundMotions;
  std::vector<ImposedMotion> imposed;
};

}  // namespace dabs::domain
