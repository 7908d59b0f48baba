// SPDX-License-Identifier: MIT
// The seed's frustum/sphere contact test (eq. 5), written as published, kept to
// measure it: it ignores the end balls and is loose near the end caps.
#pragma once

#include "geometry/segment_frame.h"
#include "geometry/types.h"

namespace frusta {

// |OC|^2 <= (R / cos(alpha) + r(k))^2 and -R/L <= k <= 1 + R/L. False for L == 0,
// where the published formula divides by zero.
bool patent_contact(const SegmentFrame& frame, const Sphere& sphere);

// Axial position k of seed eq. 4 (0 at E, 1 at D); 0 for a degenerate segment.
double axial_fraction(const SegmentFrame& frame, const vec3& point);

}  // namespace frusta
