// SPDX-License-Identifier: MIT
#pragma once

#include <vector>

#include "elements/beam/BeamIntegration.h"

namespace dabs::elements {

/// Classical rules with one section type at every point (`beamIntegration Lobatto|Legendre|
/// Radau|NewtonCotes tag secTag N`), mapped from [-1, 1] to xi in [0, 1] (weights sum to 1):
///  - Lobatto: Gauss-Lobatto, both ends included (N >= 2);
///  - Legendre: Gauss-Legendre, interior points (N >= 1);
///  - Radau: Gauss-Radau with the point at end I (xi = 0) (N >= 1);
///  - NewtonCotes: equally spaced closed rule (N >= 2).
/// Points and weights are computed (Newton iteration on Legendre polynomials, Abramowitz &
/// Stegun 1964, 25.4.29-25.4.32), not tabulated.
class QuadratureIntegration final : public BeamIntegration {
 public:
  enum class Rule { Lobatto, Legendre, Radau, NewtonCotes };
  /// Throws InputError when N is out of range for the rule.
  QuadratureIntegration(int tag, Rule rule, int sectionTag, int numPoints);

  std::string_view typeName() const override;
  std::vector<int> sectionTags() const override {
    return std::vector<int>(xi_.size(), sectionTag_);
  }
  std::vector<double> locations(double) const override { return xi_; }
  std::vector<double> weights(double) const override { return w_; }
  std::unique_ptr<BeamIntegration> clone() const override {
    return std::make_unique<QuadratureIntegration>(*this);
  }

 private:
  Rule rule_;
  int sectionTag_;
  std::vector<double> xi_, w_;
};

/// Modified Gauss-Radau plastic-hinge integration (`beamIntegration HingeRadau tag secI lpI secJ
/// lpJ secE`; Scott & Fenves 2006, J. Struct. Eng. 132(2), eq. 21): two points in each hinge
/// region of length 4 lp (two-point Radau: at the end and at 8/3 lp, weights lp and 3 lp, so the
/// end section carries the hinge length lp and the point at 8/3 lp is elastic) and two-point
/// Gauss-Legendre on the interior [4 lpI, L - 4 lpJ] with the elastic section secE.
class HingeRadauIntegration final : public BeamIntegration {
 public:
  /// Throws InputError unless lpI, lpJ >= 0 and 4 (lpI + lpJ) < L is possible (checked per L).
  HingeRadauIntegration(int tag, int secI, double lpI, int secJ, double lpJ, int secE);
  std::string_view typeName() const override { return "HingeRadau"; }
  /// Only the end points carry the hinge sections; the second Radau point of each hinge region
  /// (at 8/3 lp) takes the elastic section, as in Scott & Fenves (2006) and OpenSees.
  std::vector<int> sectionTags() const override {
    return {secI_, secE_, secE_, secE_, secE_, secJ_};
  }
  std::vector<double> locations(double length) const override;
  std::vector<double> weights(double length) const override;
  std::unique_ptr<BeamIntegration> clone() const override {
    return std::make_unique<HingeRadauIntegration>(*this);
  }

 private:
  int secI_, secJ_, secE_;
  double lpI_, lpJ_;
};

}  // namespace dabs::elements
