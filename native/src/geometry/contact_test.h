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

#include "geometry/double_lanes.h"
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
  const double scale = size + frame.size + sphere.radius + margin;
  const double reach = sphere.radius + margin + contact_detail::kRelativeSlack * scale;

  if (!frame.degenerate) {
    // the sphere's touching point on the infinite side lies at axial a + reach * sin(alpha)
    const double axial = glm::dot(w, frame.axis);
    const double shift = reach * frame.sin_alpha;
    if (axial >= -shift && axial <= frame.length - shift) {
      const double threshold = reach * frame.sec_alpha + frame.r_distal + axial * frame.slope;
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

namespace contact_detail {
// what gap bounds give up to rounding, relative to the sizes they are made of: ten times
// may_touch's slack, so that the one never contradicts the other
constexpr double kGapBoundSlack = 10.0 * kRelativeSlack;
}  // namespace contact_detail

// Bounds of a sphere's exact gap to a body, as may_touch sees it: may_touch(margin) holds
// only where least <= margin, and surely where most <= margin. Kept with a candidate,
// they let a pass decide most spheres with one comparison each, even after the body
// moved (a solid that moved m is within m of where it was).
struct GapBounds {
  double least = -INFINITY, most = INFINITY;  // unknown: every test is made
};

// Whether a sphere whose gap to a body had `bounds` may lie within `margin` of it now
// that the body moved no further than `move`, and whether it surely does (each
// comparison's own rounding allowed for).
inline bool may_be_within(const GapBounds& bounds, double move, double margin) {
  return bounds.least - move <= margin * (1.0 + contact_detail::kGapBoundSlack);
}
inline bool surely_within(const GapBounds& bounds, double move, double margin) {
  return bounds.most + move <= margin * (1.0 - contact_detail::kGapBoundSlack);
}

// A contact test's answer (`test`: may_touch or may_touch_sphere at `margin`), asked only
// where the bounds leave it open.
template <class Test>
bool decided_may_touch(const GapBounds& bounds, double move, double margin, Test test) {
  if (!may_be_within(bounds, move, margin)) return false;
  return surely_within(bounds, move, margin) || test();
}

// The least margin at which may_touch(frame, sphere, margin) holds, as bounds: branch for
// branch may_touch's tests solved for their reach, less and plus a rounding allowance.
// In exact arithmetic that margin is the exact gap (0 inside), since may_touch is
// exact_distance <= margin; each branch that holds at a reach bounds the gap from above.
// Written once for a sphere (D = double) or two (Doubles2), the same operations in the
// same order: a detection bounds each hit of its walks, and two at a time took the square
// roots and divisions that are most of it in half the time.
template <class D>
void gap_bounds_of(const SegmentFrame& frame, D cx, D cy, D cz, D radius, D& least, D& most) {
  using lanes::greater;
  using lanes::lesser;
  using lanes::magnitude;
  using lanes::root;
  const D wx = cx - frame.distal.x, wy = cy - frame.distal.y, wz = cz - frame.distal.z;
  const double fixed =
      std::fabs(frame.distal.x) + std::fabs(frame.distal.y) + std::fabs(frame.distal.z);
  const D allowance =
      contact_detail::kGapBoundSlack * (fixed + magnitude(wx) + magnitude(wy) + magnitude(wz) +
                                        frame.length + frame.r_distal + frame.r_proximal + radius);
  // the end balls: |c - E| <= reach + r2, |c - D| <= reach + r1
  const D dx = cx - frame.proximal.x, dy = cy - frame.proximal.y, dz = cz - frame.proximal.z;
  D reach = lesser(root(wx * wx + wy * wy + wz * wz) - frame.r_distal,
                   root(dx * dx + dy * dy + dz * dz) - frame.r_proximal);
  if (!frame.degenerate) {
    // the side: |radial| <= reach / cos(alpha) + r2 + axial slope, with the touching
    // point in the band, -axial <= reach sin(alpha) <= length - axial, for a reach of
    // at least the sphere's radius (no margin is negative)
    const D axial = wx * frame.axis.x + wy * frame.axis.y + wz * frame.axis.z;
    const D rx = wx - axial * frame.axis.x, ry = wy - axial * frame.axis.y,
            rz = wz - axial * frame.axis.z;
    D low = (root(rx * rx + ry * ry + rz * rz) - frame.r_distal - axial * frame.slope) *
            frame.cos_alpha;
    D high = lanes::splat(low, INFINITY);
    if (frame.sin_alpha > 0.0) {
      low = greater(low, -axial / frame.sin_alpha);
      high = (frame.length - axial) / frame.sin_alpha;
    } else if (frame.sin_alpha < 0.0) {
      low = greater(low, (frame.length - axial) / frame.sin_alpha);
      high = -axial / frame.sin_alpha;
    } else {
      low = ((axial < 0.0) | (axial > frame.length)) ? lanes::splat(low, INFINITY) : low;
    }
    reach = ((low <= high + allowance) & (high >= radius - allowance)) ? lesser(reach, low) : reach;
  }
  // a reach below the radius holds at margin 0: the sphere sinks in by an unknown depth
  const D margin = reach - radius;
  least = margin - allowance;
  most = greater(margin, lanes::splat(margin, 0.0)) + allowance;
}

inline GapBounds gap_bounds(const SegmentFrame& frame, const Sphere& sphere) {
  GapBounds g;
  gap_bounds_of(frame, sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius, g.least,
                g.most);
  return g;
}

// The same for two spheres at once.
inline void gap_bounds(const SegmentFrame& frame, const Sphere& a, const Sphere& b, GapBounds& of_a,
                       GapBounds& of_b) {
#if defined(FRUSTA_DOUBLE_LANES)
  Doubles2 least, most;
  gap_bounds_of(frame, Doubles2{a.center.x, b.center.x}, Doubles2{a.center.y, b.center.y},
                Doubles2{a.center.z, b.center.z}, Doubles2{a.radius, b.radius}, least, most);
  of_a = {least[0], most[0]};
  of_b = {least[1], most[1]};
#else
  of_a = gap_bounds(frame, a);
  of_b = gap_bounds(frame, b);
#endif
}

// The same for two spheres and may_touch_sphere.
inline GapBounds gap_bounds_sphere(const Sphere& a, const Sphere& b) {
  const double apart = glm::length(a.center - b.center);
  const double allowance =
      contact_detail::kGapBoundSlack * (std::fabs(a.center.x) + std::fabs(a.center.y) +
                                        std::fabs(a.center.z) + apart + a.radius + b.radius);
  const double margin = apart - a.radius - b.radius;
  return {margin - allowance, std::max(margin, 0.0) + allowance};
}

}  // namespace frusta
