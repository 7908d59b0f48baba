// SPDX-License-Identifier: MIT
// The engine's contact test: conservative and cheap. The seed's side test (eq. 5)
// restricted to the band where its touching point lies on the real side, plus a
// ball test at each end (eqs. 10-11 and the joint balls). Inside the band the side
// test is exact; outside it the side's nearest point is a rim inside a ball. So in exact
// arithmetic this equals exact_distance <= margin; a rounding slack keeps it from
// ever missing a contact (a missed contact is a finger through an object).
#pragma once

#include <cmath>

#include <glm/geometric.hpp>

#include "geometry/segment_frame.h"
#include "geometry/types.h"

namespace frusta {

namespace contact_detail {
// relative rounding slack: a few hundred ulps of the quantities compared
constexpr double kRelativeSlack = 1e-13;

inline bool within_ball(const vec3& center, double ball_radius, const vec3& point, double reach) {
  const vec3 d = point - center;
  const double limit = reach + ball_radius;
  return glm::dot(d, d) <= limit * limit;
}
}  // namespace contact_detail

// True when the sphere may lie within `margin` metres of the segment solid. Inline: it
// runs per tree node and per candidate in every pass over them (4 % of a grasp's step
// went to the call).
inline bool may_touch(const SegmentFrame& frame, const Sphere& sphere, double margin) {
  // no square root: |w| by its 1-norm, which the slack only needs the size of, and the
  // radial distance compared squared (the test runs per tree node and per candidate)
  const vec3 w = sphere.center - frame.distal;
  const double size = std::fabs(w.x) + std::fabs(w.y) + std::fabs(w.z);
  const double scale =
      size + frame.length + frame.r_distal + frame.r_proximal + sphere.radius + margin;
  const double reach = sphere.radius + margin + contact_detail::kRelativeSlack * scale;

  if (!frame.degenerate) {
    // the sphere's touching point on the infinite side lies at axial a + reach * sin(alpha)
    const double axial = glm::dot(w, frame.axis);
    const double shift = reach * frame.sin_alpha;
    if (axial >= -shift && axial <= frame.length - shift) {
      const double threshold = reach / frame.cos_alpha + frame.r_distal + axial * frame.slope;
      const vec3 radial = w - axial * frame.axis;
      if (threshold >= 0.0 && glm::dot(radial, radial) <= threshold * threshold) return true;
    }
  }
  // a ball bulges past the side next to its own end, so both are tested everywhere
  return contact_detail::within_ball(frame.distal, frame.r_distal, sphere.center, reach) ||
         contact_detail::within_ball(frame.proximal, frame.r_proximal, sphere.center, reach);
}

// True when two spheres may lie within `margin` metres of each other.
bool may_touch_sphere(const Sphere& a, const Sphere& b, double margin);

}  // namespace frusta
