// SPDX-License-Identifier: MIT
#include "geometry/segment_frame.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/trapezoid_distance.h"

namespace frusta {

namespace {
// Below this length (relative to the segment's size) the axis direction is noise.
constexpr double kDegenerateRelativeLength = 1e-12;
// A radial part this small (relative to |w|) is rounding noise, not a direction.
constexpr double kAxisNoise = 1e-15;
}  // namespace

SegmentFrame make_segment_frame(const Segment& segment) {
  // every member written once, in one initialiser: `SegmentFrame f;` had the struct zeroed
  // first (a rep stos, a seventh of this function's time), and passes make a frame per
  // segment each
  const vec3 d = segment.proximal - segment.distal;
  const double length = glm::length(d);
  const double size = length + segment.distal_radius + segment.proximal_radius;
  if (!(length > kDegenerateRelativeLength * size))
    return {segment.distal,
            segment.proximal,
            vec3(1.0, 0.0, 0.0),  // axis
            length,
            segment.distal_radius,
            segment.proximal_radius,
            0.0,  // slope
            1.0,  // cos_alpha
            1.0,  // sec_alpha
            0.0,  // sin_alpha
            size,
            true};  // degenerate
  // cos and sin from the side's own lengths rather than through atan: exact for a cylinder
  const double side = slant_length(length, segment.distal_radius, segment.proximal_radius);
  const double taper = segment.proximal_radius - segment.distal_radius;
  return {segment.distal,
          segment.proximal,
          d / length,  // axis
          length,
          segment.distal_radius,
          segment.proximal_radius,
          taper / length,  // slope
          length / side,   // cos_alpha
          side / length,   // sec_alpha
          taper / side,    // sin_alpha
          size,
          false};  // degenerate
}

AxialSplit split_axial(const SegmentFrame& frame, const vec3& point) {
  AxialSplit s;
  s.w = point - frame.distal;
  s.axial = glm::dot(s.w, frame.axis);
  s.radial = s.w - s.axial * frame.axis;
  s.radial_length = glm::length(s.radial);
  return s;
}

vec3 radial_direction(const SegmentFrame& frame, const AxialSplit& split) {
  const vec3& u = frame.axis;
  // w - (w.u)u keeps a rounding residue along u of ~eps|w|; near the axis that residue
  // is the whole radial part, so project it out once more before normalising
  const vec3 radial = split.radial - glm::dot(split.radial, u) * u;
  const double length = glm::length(radial);
  if (length > kAxisNoise * glm::length(split.w)) return radial / length;
  // on the axis every perpendicular is as good; pick the one least aligned with it
  const vec3 helper = std::fabs(u.x) < 0.9 ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
  return glm::normalize(glm::cross(glm::cross(u, helper), u));
}

}  // namespace frusta
