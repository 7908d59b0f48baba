// SPDX-License-Identifier: MIT
// Signed distance from a point of the meridian half-plane (x along the axis from E,
// y >= 0 from the axis) to the frustum's section: the trapezoid
// (0,0) (0,r2) (L,r1) (L,0). Distance to a solid of revolution equals this 2-D
// distance, which makes it the exact reference for the frustum part.
#pragma once

#include <cmath>

namespace frusta {

struct TrapezoidDistance {
  double distance = 0.0;  // negative inside: depth to the nearest boundary edge
  double nearest_x = 0.0, nearest_y = 0.0;  // nearest boundary point
  double normal_x = 0.0, normal_y = 1.0;    // unit outward normal there
};

TrapezoidDistance trapezoid_distance(double x, double y, double length, double r_distal,
                                     double r_proximal);

// The length of the section's slanted edge, from (0, r2) to (L, r1). A plain root, not
// std::hypot: a hand's lengths are far from overflow, and hypot took a tenth of a
// trembling grasp's step (a frame per segment per trial).
inline double slant_length(double length, double r_distal, double r_proximal) {
  const double taper = r_proximal - r_distal;
  return std::sqrt(length * length + taper * taper);
}

}  // namespace frusta
