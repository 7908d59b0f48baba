// SPDX-License-Identifier: MIT
// Per-segment quantities every sphere test needs, computed once per segment so a
// pair test is a handful of multiply-adds.
#pragma once

#include "geometry/types.h"

namespace frusta {

struct SegmentFrame {
  vec3 distal{0.0};     // E, origin of the axial coordinate
  vec3 proximal{0.0};   // D
  vec3 axis{1.0, 0.0, 0.0};  // u = (D - E) / L; +x when L == 0
  double length = 0.0;  // L
  double r_distal = 0.0;    // r2
  double r_proximal = 0.0;  // r1
  double slope = 0.0;   // tan(alpha) = (r1 - r2) / L; 0 when L == 0
  double cos_alpha = 1.0;
  double sec_alpha = 1.0;  // 1 / cos(alpha): a division per node test in every walk was dear
  double sin_alpha = 0.0;
  double size = 0.0;        // L + r1 + r2: the segment's part of every test's rounding scale
  bool degenerate = false;  // L too short for an axis: the solid is its two balls
};

SegmentFrame make_segment_frame(const Segment& segment);

// w = O - E split into its axial coordinate a (metres from E towards D) and its
// radial part p (perpendicular to the axis), with q = |p|.
struct AxialSplit {
  vec3 w{0.0};
  double axial = 0.0;
  vec3 radial{0.0};
  double radial_length = 0.0;
};

AxialSplit split_axial(const SegmentFrame& frame, const vec3& point);

// Unit vector perpendicular to the axis pointing from the axis to the point;
// a fixed perpendicular when the point lies on the axis.
vec3 radial_direction(const SegmentFrame& frame, const AxialSplit& split);

}  // namespace frusta
