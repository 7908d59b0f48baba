// SPDX-License-Identifier: MIT
// The exact reference: signed gap between a sphere and a segment solid (frustum
// union its two end balls). Everything approximate is measured against this.
#pragma once

#include "geometry/segment_frame.h"
#include "geometry/types.h"

namespace frusta {

struct Proximity {
  double distance = 0.0;  // sphere surface to solid surface; < 0: penetration
  Feature feature = Feature::kSide;  // the part of the solid that is nearest
  vec3 hand_point{0.0};    // nearest point on the solid's surface
  vec3 object_point{0.0};  // the sphere's surface point nearest the hand
  vec3 normal{0.0};        // unit, from the sphere's centre towards the hand
};

// Signed distance from a point to the solid: exact outside; inside, the depth in
// the deepest single part (a lower bound of the union's depth).
Proximity exact_proximity(const SegmentFrame& frame, const Sphere& sphere);

// Just the number, for hot loops and tests.
double exact_distance(const SegmentFrame& frame, const Sphere& sphere);

// The same for a ball of the hand (a palm sphere) against a sphere: the normal along
// their centres' line (+z where the centres coincide); `feature` means nothing here.
Proximity exact_proximity(const Sphere& hand, const Sphere& sphere);
double exact_distance(const Sphere& hand, const Sphere& sphere);

}  // namespace frusta
