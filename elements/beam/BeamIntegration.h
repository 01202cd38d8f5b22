// SPDX-License-Identifier: MIT
#pragma once

#include <memory>
#include <string_view>
#include <vector>

namespace dabs::elements {

/// Integration rule along a beam-column (beamIntegration Lobatto|Legendre|Radau|NewtonCotes|
/// HingeRadau): locations xi in [0, 1] and weights summing to 1, plus the section tag of each
/// point. Stored by the model builder and read by force- and displacement-based elements.
class BeamIntegration {
 public:
  explicit BeamIntegration(int tag) noexcept : tag_(tag) {}
  virtual ~BeamIntegration() = default;
  BeamIntegration(const BeamIntegration&) = default;
  BeamIntegration& operator=(const BeamIntegration&) = delete;

  int tag() const noexcept { return tag_; }
  virtual std::string_view typeName() const = 0;
  /// Section tags, one per integration point.
  virtual std::vector<int> sectionTags() const = 0;
  /// Locations xi in [0, 1] for an element of length L (HingeRadau depends on L).
  virtual std::vector<double> locations(double length) const = 0;
  /// Weights (sum 1) for an element of length L.
  virtual std::vector<double> weights(double length) const = 0;
  [[nodiscard]] virtual std::unique_ptr<BeamIntegration> clone() const = 0;

 private:
  int tag_;
};

}  // namespace dabs::elements
