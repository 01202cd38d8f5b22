// SPDX-License-Identifier: MIT
#pragma once

#include "tcl/domain/TimeSeries.h"

namespace dabs::domain {

/// Near-fault velocity pulse of Mavroeidis and Papageorgiou (2003, "A mathematical representation
/// of near-fault ground motions", BSSA 93(3):1099-1131, eqs. 1-2):
///   v(t) = Vp/2 [1 + cos(2 pi (t - t0) / (gamma Tp))] cos(2 pi (t - t0)/Tp + nu)
/// for |t - t0| <= gamma Tp / 2, zero outside. `timeSeries NearFaultPulse tag -Tp Tp -Vp Vp
/// -gamma gamma -nu nu -t0 t0 ?-factor f? ?-velocity?` gives f times the ground acceleration dv/dt
/// (or the velocity with -velocity).
class NearFaultPulseSeries final : public TimeSeries {
 public:
  struct Params {
    double Tp = 1.0;      ///< pulse period (s)
    double Vp = 1.0;      ///< velocity amplitude
    double gamma = 2.0;   ///< oscillatory character (number of half cycles), > 1
    double nu = 0.0;      ///< phase (rad)
    double t0 = 0.0;      ///< time of the envelope's peak (s)
    double factor = 1.0;  ///< scale of the output
    bool velocity = false;
    /// Throws InputError for Tp <= 0, gamma <= 1, t0 < gamma Tp / 2 (pulse starting before 0).
    void validate() const;
  };
  NearFaultPulseSeries(int tag, const Params& p) : TimeSeries(tag), p_(p) {}
  double factor(double t) const override;
  double duration() const override { return p_.t0 + 0.5 * p_.gamma * p_.Tp; }
  double samplingInterval() const override { return p_.Tp / 400.0; }
  std::string describe() const override;
  /// Velocity of the pulse at t (independent of -velocity), for checks.
  double velocity(double t) const;

 private:
  Params p_;
};

}  // namespace dabs::domain
