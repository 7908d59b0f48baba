// SPDX-License-Identifier: MIT
#include "geometry/trapezoid_distance.h"

#include <algorithm>
#include <cmath>

namespace frusta {

namespace {

struct EdgeHit {
  double distance_squared;
  double x, y;
};

EdgeHit nearest_on_edge(double px, double py, double ax, double ay, double bx, double by) {
  const double ex = bx - ax, ey = by - ay;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((px - ax) * ex + (py - ay) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double x = ax + t * ex, y = ay + t * ey;
  return {(px - x) * (px - x) + (py - y) * (py - y), x, y};
}

}  // namespace

TrapezoidDistance trapezoid_distance(double x, double y, double length, double r_distal,
                                     double r_proximal) {
  TrapezoidDistance out;
  // the lateral edge's outward unit normal, (-sin alpha, cos alpha)
  const double side = slant_length(length, r_distal, r_proximal);
  const double lateral_nx = side > 0.0 ? -(r_proximal - r_distal) / side : 0.0;
  const double lateral_ny = side > 0.0 ? length / side : 1.0;

  const double lateral_gap = (x * lateral_nx + (y - r_distal) * lateral_ny);
  const bool inside = length > 0.0 && x >= 0.0 && x <= length && lateral_gap <= 0.0;
  if (inside) {
    // depth is the distance to the nearest edge line: cap E, cap D or the side
    const double to_distal = x, to_proximal = length - x, to_side = -lateral_gap;
    if (to_side <= to_distal && to_side <= to_proximal) {
      // the side point is a step of to_side along the outward normal
      out = {-to_side, x + to_side * lateral_nx, y + to_side * lateral_ny, lateral_nx, lateral_ny};
    } else if (to_distal <= to_proximal) {
      out = {-to_distal, 0.0, y, -1.0, 0.0};
    } else {
      out = {-to_proximal, length, y, 1.0, 0.0};
    }
    return out;
  }

  const EdgeHit candidates[3] = {
      nearest_on_edge(x, y, 0.0, r_distal, length, r_proximal),  // side
      nearest_on_edge(x, y, 0.0, 0.0, 0.0, r_distal),            // cap at E
      nearest_on_edge(x, y, length, 0.0, length, r_proximal),    // cap at D
  };
  const EdgeHit* best = &candidates[0];
  for (const EdgeHit& c : candidates)
    if (c.distance_squared < best->distance_squared) best = &c;
  out.distance = std::sqrt(best->distance_squared);
  out.nearest_x = best->x;
  out.nearest_y = best->y;
  if (out.distance > 0.0) {
    out.normal_x = (x - best->x) / out.distance;
    out.normal_y = (y - best->y) / out.distance;
  } else {
    out.normal_x = lateral_nx;  // on the boundary: the side's normal is as good as any
    out.normal_y = lateral_ny;
  }
  return out;
}

}  // namespace frusta
