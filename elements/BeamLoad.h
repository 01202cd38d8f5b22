// SPDX-License-Identifier: MIT
#pragma once

#include <Eigen/Core>
#include <optional>

namespace dabs::elements {

/// A member load on a beam-column at unit load factor, in the element's local axes (x along the
/// member from node I to J, y and z the section axes of its transformation): the `eleLoad -type
/// -beamUniform | -beamPoint` loads of OpenSees.
struct BeamLoad {
  enum class Type {
    Uniform,  ///< force per length over the part [a L, b L] of the member: w at a L, varying
              ///< linearly to wEnd at b L when wEnd is given
    Point     ///< force w at a L from node I
  };
  Type type = Type::Uniform;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();  ///< local (x, y, z) components
  double a = 0.0;  ///< start of the loaded part (Uniform) or the point's position (Point), / L
  double b = 1.0;  ///< end of the loaded part / L (Uniform only)
  std::optional<Eigen::Vector3d> wEnd;  ///< Uniform: intensity at b L (absent: w all along)
};

}  // namespace dabs::elements
