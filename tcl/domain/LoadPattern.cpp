// SPDX-License-Identifier: MIT
#include "tcl/domain/LoadPattern.h"

#include <algorithm>
#include <cmath>

namespace dabs::domain {

double LoadPattern::factor(double t) const {
  if (constant_) return frozenFactor_;
  return series_ ? fact_ * series_->factor(t) : 0.0;
}

void LoadPattern::setConstant(double t) {
  if (constant_) return;
  frozenFactor_ = factor(t);
  constant_ = true;
}

bool LoadPattern::usesNode(int tag) const {
  for (const NodalLoad& l : nodalLoads())
    if (l.node == tag) return true;
  for (const SupportDof& s : supportDofs())
    if (s.node == tag) return true;
  return false;
}

std::vector<SupportDof> PlainPattern::supportDofs() const {
  std::vector<SupportDof> out;
  for (const PrescribedDisp& p : prescribed) out.push_back({p.node, p.dof, "sp", false});
  return out;
}

void PlainPattern::supportMotion(double t, std::span<SupportMotion> out) const {
  const double f = factor(t);
  for (std::size_t k = 0; k < prescribed.size(); ++k) {
    const PrescribedDisp& p = prescribed[k];
    out[k] = SupportMotion{p.constant ? p.reference : p.reference * f, 0.0, 0.0};
  }
}

std::vector<SupportDof> MultipleSupportPattern::supportDofs() const {
  std::vector<SupportDof> out;
  for (const ImposedMotion& m : imposed) out.push_back({m.node, m.dof, "imposedMotion", true});
  return out;
}

void MultipleSupportPattern::supportMotion(double t, std::span<SupportMotion> out) const {
  for (std::size_t k = 0; k < imposed.size(); ++k) {
    const GroundMotion& gm = *groundMotions.at(imposed[k].groundMotion);
    out[k] = SupportMotion{gm.disp(t), gm.vel(t), gm.accel(t)};
  }
}

std::vector<SPConstraint> MultipleSupportPattern::replacedFixes() const {
  std::vector<SPConstraint> out;
  for (const ImposedMotion& m : imposed)
    if (m.replacedFix) out.push_back({m.node, m.dof});
  return out;
}

GroundMotion::GroundMotion(std::shared_ptr<const TimeSeries> accel,
                           std::shared_ptr<const TimeSeries> vel,
                           std::shared_ptr<const TimeSeries> disp, double fact)
    : accel_(std::move(accel)), vel_(std::move(vel)), disp_(std::move(disp)), fact_(fact) {
  const TimeSeries* source = accel_ ? accel_.get() : vel_.get();
  step_ = source ? source->samplingInterval() : 0.01;
  velSamples_ = {0.0};
  dispSamples_ = {0.0};
}

double GroundMotion::accel(double t) const {
  if (t < 0.0 || !accel_) return 0.0;
  return fact_ * accel_->factor(t);
}

// Samples of the integrated histories are extended on demand, so a motion of any length costs
// only what the analysis reaches (mutable caches of logically const functions).
double GroundMotion::integrated(const std::vector<double>& values, double t) const {
  const double x = t / step_;
  const auto i = static_cast<std::size_t>(std::floor(x));
  if (i + 1 >= values.size()) return values.back();
  const double frac = x - static_cast<double>(i);
  return values[i] + (values[i + 1] - values[i]) * frac;
}

double GroundMotion::vel(double t) const {
  if (t < 0.0) return 0.0;
  if (vel_) return fact_ * vel_->factor(t);
  if (!accel_) return 0.0;
  auto& v = velSamples_;
  while (static_cast<double>(v.size() - 1) * step_ <= t + step_) {
    const double t1 = static_cast<double>(v.size()) * step_;
    const double t0 = t1 - step_;
    // Trapezoid rule on the acceleration samples (OpenSees TrapezoidalTimeSeriesIntegrator).
    v.push_back(v.back() + 0.5 * step_ * (accel(t0) + accel(t1)));
  }
  return integrated(v, t);
}

double GroundMotion::disp(double t) const {
  if (t < 0.0) return 0.0;
  if (disp_) return fact_ * disp_->factor(t);
  if (!accel_ && !vel_) return 0.0;
  auto& d = dispSamples_;
  while (static_cast<double>(d.size() - 1) * step_ <= t + step_) {
    const double t1 = static_cast<double>(d.size()) * step_;
    const double t0 = t1 - step_;
    d.push_back(d.back() + 0.5 * step_ * (vel(t0) + vel(t1)));
  }
  return integrated(d, t);
}

}  // namespace dabs::domain
