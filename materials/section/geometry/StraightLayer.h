// SPDX-License-Identifier: MIT
#pragma once

#include "materials/section/geometry/Fiber.h"

namespace dabs::materials::section {

/// Straight row of bars `layer straight matTag numBars areaBar yStart zStart yEnd zEnd`: bars
/// equally spaced from start to end inclusive (one bar sits at the midpoint), as OpenSees
/// SRC/material/section/repres/reinfLayer/StraightReinfLayer.cpp.
struct StraightLayer {
  int materialTag = 0;
  int numBars = 1;
  double barArea = 0.0;
  double yStart = 0.0, zStart = 0.0, yEnd = 0.0, zEnd = 0.0;

  void validate() const;
  void discretize(FiberList& out) const;
};

/// Circular arc of bars `layer circ matTag numBars areaBar yC zC radius ?startAng endAng?`
/// (degrees, default 0-360). A full circle spaces the bars 360/numBars apart; an arc places
/// bars at both ends, (end - start)/(numBars - 1) apart (OpenSees CircReinfLayer.cpp).
struct CircLayer {
  int materialTag = 0;
  int numBars = 1;
  double barArea = 0.0;
  double yCenter = 0.0, zCenter = 0.0, radius = 0.0;
  double startAngle = 0.0, endAngle = 360.0;

  void validate() const;
  void discretize(FiberList& out) const;
};

}  // namespace dabs::materials::section
