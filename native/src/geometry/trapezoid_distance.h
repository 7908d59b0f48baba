// SPDX-License-Identifier: MIT
// Signed distance from a point of the meridian half-plane (x along the axis from E,
// y >= 0 from the axis) to the frustum's section: the trapezoid
// (0,0) (0,r2) (L,r1) (L,0). Distance to a solid of revolution equals this 2-D
// distance, which makes it the exact reference for the frustum part.
#pragma once

namespace frusta {

struct TrapezoidDistance {
  double distance = 0.0;  // negative inside: depth to the nearest boundary edge
  double nearest_x = 0.0, nearest_y = 0.0;  // nearest boundary point
  double normal_x = 0.0, normal_y = 1.0;    // unit outward normal there
};

TrapezoidDistance trapezoid_distance(double x, double y, double length, double r_distal,
                                     double r_proximal);

}  // namespace frusta
