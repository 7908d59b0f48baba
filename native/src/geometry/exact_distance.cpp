// SPDX-License-Identifier: MIT
#include "geometry/exact_distance.h"

#include <glm/geometric.hpp>

#include "geometry/trapezoid_distance.h"

namespace frusta {

namespace {

// outward unit normal of a ball surface towards a point; the axis if they coincide
vec3 ball_outward(const vec3& center, const vec3& point, const vec3& fallback) {
  const vec3 d = point - center;
  const double n = glm::length(d);
  return n > 0.0 ? d / n : fallback;
}

}  // namespace

Proximity exact_proximity(const SegmentFrame& frame, const Sphere& sphere) {
  const vec3& o = sphere.center;
  const double to_distal = glm::length(o - frame.distal) - frame.r_distal;
  const double to_proximal = glm::length(o - frame.proximal) - frame.r_proximal;

  Proximity p;
  vec3 outward;  // the solid's outward normal at the nearest point
  double center_distance;
  if (to_distal <= to_proximal) {
    p.feature = Feature::kDistalBall;
    center_distance = to_distal;
    outward = ball_outward(frame.distal, o, -frame.axis);
  } else {
    p.feature = Feature::kProximalBall;
    center_distance = to_proximal;
    outward = ball_outward(frame.proximal, o, frame.axis);
  }

  if (!frame.degenerate) {
    const AxialSplit s = split_axial(frame, o);
    const TrapezoidDistance t = trapezoid_distance(s.axial, s.radial_length, frame.length,
                                                   frame.r_distal, frame.r_proximal);
    // strictly nearer: on a tie the ball (which contains the cap and rim) names the contact
    if (t.distance < center_distance) {
      const vec3 radial = radial_direction(frame, s);
      p.feature = Feature::kSide;
      center_distance = t.distance;
      outward = t.normal_x * frame.axis + t.normal_y * radial;
    }
  }

  p.distance = center_distance - sphere.radius;
  p.hand_point = o - center_distance * outward;
  p.object_point = o - sphere.radius * outward;
  p.normal = -outward;
  return p;
}

double exact_distance(const SegmentFrame& frame, const Sphere& sphere) {
  return exact_proximity(frame, sphere).distance;
}

Proximity exact_proximity(const Sphere& hand, const Sphere& sphere) {
  Proximity p;
  const vec3 d = hand.center - sphere.center;
  const double length = glm::length(d);
  p.normal = length > 0.0 ? d / length : vec3(0.0, 0.0, 1.0);
  p.distance = length - hand.radius - sphere.radius;
  p.hand_point = hand.center - hand.radius * p.normal;
  p.object_point = sphere.center + sphere.radius * p.normal;
  return p;
}

double exact_distance(const Sphere& hand, const Sphere& sphere) {
  return glm::length(hand.center - sphere.center) - hand.radius - sphere.radius;
}

}  // namespace frusta
