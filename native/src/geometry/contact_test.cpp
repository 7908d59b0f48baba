// SPDX-License-Identifier: MIT
#include "geometry/contact_test.h"

#include <cmath>

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
  // no square root: |w| by its 1-norm, which the slack only needs the size of, and the
  // radial distance compared squared (the test runs per tree node and per candidate)
  const vec3 w = sphere.center - frame.distal;
  const double size = std::fabs(w.x) + std::fabs(w.y) + std::fabs(w.z);
  const double scale = size + frame.length + frame.r_distal + frame.r_proximal + sphere.radius + margin;
  const double reach = sphere.radius + margin + kRelativeSlack * scale;

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
  return within_ball(frame.distal, frame.r_distal, sphere.center, reach) ||
         within_ball(frame.proximal, frame.r_proximal, sphere.center, reach);
}

bool may_touch_sphere(const Sphere& a, const Sphere& b, double margin) {
  const double scale = glm::length(a.center - b.center) + a.radius + b.radius + margin;
  return within_ball(a.center, a.radius, b.center, b.radius + margin + kRelativeSlack * scale);
}

}  // namespace frusta
