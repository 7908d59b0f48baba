// SPDX-License-Identifier: MIT
// The engine's contact test: conservative and cheap. The seed's side test (eq. 5)
// restricted to the band where its touching point lies on the real side, plus a
// ball test at each end (eqs. 10-11 and the joint balls). Inside the band the side
// test is exact; outside it the side's nearest point is a rim inside a ball. So in exact
// arithmetic this equals exact_distance <= margin; a rounding slack keeps it from
// ever missing a contact (a missed contact is a finger through an object).
#pragma once

#include "geometry/segment_frame.h"
#include "geometry/types.h"

namespace frusta {

// True when the sphere may lie within `margin` metres of the segment solid.
bool may_touch(const SegmentFrame& frame, const Sphere& sphere, double margin);

// True when two spheres may lie within `margin` metres of each other.
bool may_touch_sphere(const Sphere& a, const Sphere& b, double margin);

}  // namespace frusta
