// SPDX-License-Identifier: MIT
#include "geometry/contact_test.h"

#include <glm/geometric.hpp>

namespace frusta {

namespace {
// relative rounding slack: a few hundred ulps of the quantities compared
constexpr double kRelativeSlack = 1e-13;

bool within_ball(const vec3& center, double ball_radius, const vec3& point, double reach) {
  const vec3 d = point - center;
  const double limit = reach + ball_radius;
  return glm::dot(d, d) <= limit * limit;
}
}  // namespace

bool may_touch(const SegmentFrame& frame, const Sphere& sphere, double margin) {
  const AxialSplit s = split_axial(frame, sphere.center);
  const double scale = glm::length(s.w) + frame.length + frame.r_distal + frame.r_proximal +
                       sphere.radius + margin;
  const double reach = sphere.radius + margin + kRelativeSlack * scale;

  if (!frame.degenerate) {
    // the sphere's touching point on the infinite side lies at axial a + reach * sin(alpha)
    const double shift = reach * frame.sin_alpha;
    if (s.axial >= -shift && s.axial <= frame.length - shift) {
      const double threshold = reach / frame.cos_alpha + frame.r_distal + s.axial * frame.slope;
      if (s.radial_length <= threshold) return true;
    }
  }
  // a ball bulges past the side next to its own end, so both are tested everywhere
  return within_ball(frame.distal, frame.r_distal, sphere.center, reach) ||
         within_ball(frame.proximal, frame.r_proximal, sphere.center, reach);
}

bool may_touch_sphere(const Sphere& a, const Sphere& b, double margin) {
  const double scale = glm::length(a.center - b.center) + a.radius + b.radius + margin;
  return within_ball(a.center, a.radius, b.center, b.radius + margin + kRelativeSlack * scale);
}

}  // namespace frusta
