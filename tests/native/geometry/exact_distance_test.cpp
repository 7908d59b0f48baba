// SPDX-License-Identifier: MIT
// The exact reference against hand-computed values and, over a million seeded cases,
// against an independent brute-force distance (brute_force_reference.h).
#include "geometry/exact_distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "brute_force_reference.h"
#include "geometry/segment_frame.h"
#include "property_support.h"
#include "geometry_fixtures.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;
using scenes::Family;


TEST(ExactDistance, CylinderSideGapIsRadialDistanceMinusBothRadii) {
  const SegmentFrame f = make_segment_frame({{0.04, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.01, 0.01});
  const Proximity p = exact_proximity(f, {{0.02, 0.03, 0.0}, 0.005});
  EXPECT_NEAR(p.distance, 0.015, 1e-15);
  EXPECT_EQ(p.feature, Feature::kSide);
  expect_vec_near(p.hand_point, {0.02, 0.01, 0.0}, 1e-15);
  expect_vec_near(p.object_point, {0.02, 0.025, 0.0}, 1e-15);
  expect_vec_near(p.normal, {0.0, -1.0, 0.0}, 1e-15);
}

TEST(ExactDistance, ConeSideGapAlongTheSideNormal) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  // side point at x = 2 cm, r(x) = 7.5 mm; sphere R = 1 cm at 5 mm from it along the
  // outward normal (-sin, cos); both balls are farther (ball E 14.7 mm, ball D 10.1 mm)
  const vec3 side_point(0.02, 0.0075, 0.0);
  const vec3 outward(-kSin, kCos, 0.0);
  const Sphere s{side_point + 0.015 * outward, 0.01};
  const Proximity p = exact_proximity(f, s);
  EXPECT_NEAR(p.distance, 0.005, 1e-15);
  EXPECT_EQ(p.feature, Feature::kSide);
  expect_vec_near(p.hand_point, side_point, 1e-15);
  expect_vec_near(p.normal, -outward, 1e-15);
  expect_vec_near(p.object_point, side_point + 0.005 * outward, 1e-15);
  EXPECT_DOUBLE_EQ(exact_distance(f, s), p.distance);
}

TEST(ExactDistance, SphereBeyondTheTipHitsTheTipBall) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  // 2 mm beyond the tip ball along the axis
  const Proximity p = exact_proximity(f, {{-0.015, 0.0, 0.0}, 0.01});
  EXPECT_NEAR(p.distance, 0.002, 1e-15);
  EXPECT_EQ(p.feature, Feature::kDistalBall);
  expect_vec_near(p.hand_point, {-0.003, 0.0, 0.0}, 1e-15);
  expect_vec_near(p.normal, {1.0, 0.0, 0.0}, 1e-15);
  expect_vec_near(p.object_point, {-0.005, 0.0, 0.0}, 1e-15);
  // off the axis, penetrating the tip ball by 0.958 mm
  const Proximity q = exact_proximity(f, {{-0.012, 0.001, 0.0}, 0.01});
  EXPECT_NEAR(q.distance, std::hypot(0.012, 0.001) - 0.013, 1e-15);
  EXPECT_LT(q.distance, 0.0);
  EXPECT_EQ(q.feature, Feature::kDistalBall);
}

TEST(ExactDistance, ProximalBallBulgesOverTheSideNearItsEnd) {
  // r1 = 12 mm at D: the ball pokes r1 (1 - cos alpha) = 0.29 mm beyond the side line
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const vec3 top = vec3(0.04, 0.0, 0.0) + 0.012 * vec3(-kSin, kCos, 0.0);
  const Proximity p = exact_proximity(f, {top + vec3(-kSin, kCos, 0.0) * 0.001, 0.0});
  EXPECT_EQ(p.feature, Feature::kProximalBall);
  EXPECT_NEAR(p.distance, 0.001, 1e-15);
}

TEST(ExactDistance, CentreOnTheAxisInsideIsDeepestSideDepth) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  // depth to the side line: r(x) cos(alpha) = 7.5 mm * 40/41; caps are 2 cm away
  const Proximity p = exact_proximity(f, {{0.02, 0.0, 0.0}, 0.001});
  EXPECT_NEAR(p.distance, -0.0075 * kCos - 0.001, 1e-15);
  EXPECT_EQ(p.feature, Feature::kSide);
  EXPECT_NEAR(glm::length(p.normal), 1.0, 1e-15);
  EXPECT_NEAR(glm::dot(p.normal, f.axis), kSin, 1e-15);  // minus the side's outward normal
  EXPECT_TRUE(std::isfinite(p.hand_point.x) && std::isfinite(p.hand_point.y) &&
              std::isfinite(p.hand_point.z));
}

TEST(ExactDistance, CentreOnTheAxisBeyondTheTipIsAxialDistance) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const Proximity p = exact_proximity(f, {{-0.02, 0.0, 0.0}, 0.005});
  EXPECT_NEAR(p.distance, 0.02 - 0.003 - 0.005, 1e-15);
  expect_vec_near(p.normal, {1.0, 0.0, 0.0}, 1e-15);
}

TEST(ExactDistance, ZeroLengthSegmentIsItsLargerBall) {
  const SegmentFrame f = make_segment_frame({{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, 0.01, 0.005});
  ASSERT_TRUE(f.degenerate);
  const Proximity p = exact_proximity(f, {{0.1, 0.2, 0.33}, 0.005});
  EXPECT_NEAR(p.distance, 0.015, 1e-15);
  EXPECT_EQ(p.feature, Feature::kProximalBall);
  expect_vec_near(p.normal, {0.0, 0.0, -1.0}, 1e-15);
}

TEST(ExactDistance, PointOnTheSurfaceHasZeroGap) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  EXPECT_NEAR(exact_distance(f, {{0.02, 0.0, 0.0075}, 0.0}), 0.0, 1e-16);
  EXPECT_NEAR(exact_distance(f, {{-0.003, 0.0, 0.0}, 0.0}), 0.0, 1e-16);
  EXPECT_NEAR(exact_distance(f, {{0.052, 0.0, 0.0}, 0.0}), 0.0, 1e-16);
}

// Found by the property test (family on_axis): a centre a rounding error off an oblique
// axis (|OC| ~ 1e-18 m). radial_direction normalises the rounding residue of
// w - (w.u) u, which is not perpendicular to u (here nearly parallel to it), so the
// normal is not unit and hand_point lands millimetres inside the solid.
TEST(ExactDistance, CentreARoundingErrorOffAnObliqueAxisGivesAUnitNormal) {
  const Segment s{{0.01, 0.02, 0.03}, {0.0, 0.0, 0.0}, 0.01, 0.005};
  const SegmentFrame f = make_segment_frame(s);
  const Sphere sphere{0.5 * s.proximal, 0.001};  // on the axis up to rounding
  const Proximity p = exact_proximity(f, sphere);
  const double depth = 0.0075 * f.cos_alpha;      // r(k) cos(alpha) at k = 1/2
  EXPECT_NEAR(p.distance, -depth - 0.001, 1e-15);
  EXPECT_NEAR(glm::length(p.normal), 1.0, 1e-12);
  EXPECT_NEAR(exact_distance(f, {p.hand_point, 0.0}), 0.0, 1e-12);
  const AxialSplit split = split_axial(f, sphere.center);
  EXPECT_NEAR(glm::dot(radial_direction(f, split), f.axis), 0.0, 1e-12);
}

TEST(ExactDistance, FarOffsetGivesTheSameAnswerAsTheOriginWithinANanometre) {
  const Segment base = cone_9_40_41();
  const vec3 offset(1.0e6, -2.0e6, 1.5e6);
  const Segment moved{base.proximal + offset, base.distal + offset, base.proximal_radius,
                      base.distal_radius};
  const SegmentFrame f0 = make_segment_frame(base), f1 = make_segment_frame(moved);
  const vec3 centres[] = {{0.016707317, 0.022134146, 0.0}, {-0.015, 0.0, 0.0},
                          {0.02, 0.0, 0.0}, {0.03, 0.004, -0.011}, {0.05, 0.002, 0.001}};
  for (const vec3& c : centres) {
    const Proximity p0 = exact_proximity(f0, {c, 0.01});
    const Proximity p1 = exact_proximity(f1, {c + offset, 0.01});
    EXPECT_NEAR(p1.distance, p0.distance, 1e-9);
    EXPECT_EQ(p1.feature, p0.feature);
    expect_vec_near(p1.hand_point - offset, p0.hand_point, 1e-9);
    expect_vec_near(p1.normal, p0.normal, 1e-7);
  }
}

TEST(ExactDistance, HandPointOfHandPickedCasesLiesOnTheSurface) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const vec3 centres[] = {{0.016707317, 0.022134146, 0.0}, {-0.015, 0.0, 0.0},
                          {0.03, 0.007, -0.011}, {0.06, 0.002, 0.001}, {0.045, -0.03, 0.02}};
  for (const vec3& c : centres) {
    const Proximity p = exact_proximity(f, {c, 0.002});
    ASSERT_GT(p.distance, 0.0);
    EXPECT_NEAR(exact_distance(f, {p.hand_point, 0.0}), 0.0, 1e-16);
    EXPECT_NEAR(glm::length(p.hand_point - c), p.distance + 0.002, 1e-16);
    EXPECT_GT(glm::dot(p.hand_point - c, p.normal), 0.0);  // from the centre to the hand
  }
}

// (a) exact_proximity vs the brute-force reference, plus the invariants of its outputs.
TEST(ExactDistanceProperty, MatchesBruteForceAndItsOutputsAreConsistent) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed);
  property::PropertyLog log("exact vs brute force");
  double worst_ratio = 0.0;  // |exact - brute| / allowed, over all cases
  std::uint64_t outside = 0, inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f = make_segment_frame(c.segment);
    const Proximity p = exact_proximity(f, c.sphere);
    const reference::BruteForce b = reference::brute_force_gap(c.segment, c.sphere);
    const double eps = property::kRoundingUlps * property::case_scale(c);
    const double world_eps = property::kRoundingUlps * property::world_scale(c);
    const double allowed = b.tolerance + eps;
    worst_ratio = std::max(worst_ratio, std::fabs(p.distance - b.distance) / allowed);
    (b.outside ? outside : inside)++;

    log.check(std::fabs(p.distance - b.distance) <= allowed, "|exact - brute| <= sampling bound",
              c, [&] {
                return format("exact=%.17g brute=%.17g bound=%.3g feature=%d brute_nearest=%d",
                              p.distance, b.distance, allowed, int(p.feature), int(b.nearest));
              });
    if (b.outside)
      log.check(b.distance >= p.distance - eps, "brute (an upper bound) >= exact", c, [&] {
        return format("exact=%.17g brute=%.17g", p.distance, b.distance);
      });
    if (b.runner_up - b.distance > 2.0 * allowed)
      log.check(p.feature == b.nearest, "feature is the clearly nearest part", c, [&] {
        return format("exact feature=%d brute nearest=%d gap=%.17g runner-up=%.17g",
                      int(p.feature), int(b.nearest), b.distance, b.runner_up);
      });
    log.check(exact_distance(f, c.sphere) == p.distance, "exact_distance == exact_proximity", c,
              [&] { return std::string(); });

    // outputs: unit normal; hand_point = O + (gap + R) n; object_point = O + R n
    log.check(std::fabs(glm::length(p.normal) - 1.0) <= 1e-12, "normal is unit", c,
              [&] { return format("|n|=%.17g", glm::length(p.normal)); });
    const vec3 o = c.sphere.center;
    const double r = c.sphere.radius;
    log.check(glm::length(p.hand_point - (o + (p.distance + r) * p.normal)) <= world_eps,
              "hand_point = O + (gap + R) n", c, [&] { return std::string(); });
    log.check(glm::length(p.object_point - (o + r * p.normal)) <= world_eps,
              "object_point = O + R n", c, [&] { return std::string(); });
    // the hand point is on the solid's surface (outside) or not outside it (inside,
    // where it is on the deepest part's surface, maybe within another part)
    const double surface = exact_distance(f, {p.hand_point, 0.0});
    if (p.distance > 0.0)
      log.check(std::fabs(surface) <= world_eps, "hand_point on the surface", c,
                [&] { return format("gap of hand_point=%.17g", surface); });
    else
      log.check(surface <= world_eps, "hand_point not outside the solid", c,
                [&] { return format("gap of hand_point=%.17g", surface); });

    if (c.family == Family::kBoundary)
      log.check(std::fabs(p.distance - c.expected_gap) <= eps, "boundary case: constructed gap",
                c, [&] {
                  return format("exact=%.17g constructed=%.17g", p.distance, c.expected_gap);
                });
    if (c.family == Family::kFarOffset) {
      const Segment s0{c.segment.proximal - c.offset, c.segment.distal - c.offset,
                       c.segment.proximal_radius, c.segment.distal_radius};
      const double d0 = exact_distance(make_segment_frame(s0), {o - c.offset, r});
      log.check(std::fabs(d0 - p.distance) <= 1e-9, "far offset: same gap as at the origin", c,
                [&] { return format("offset=%.17g origin=%.17g", p.distance, d0); });
    }
  }
  log.report();
  std::printf("[ exact vs brute ] %llu cases (%llu centres outside, %llu inside); worst "
              "|exact - brute| / bound = %.3g\n",
              static_cast<unsigned long long>(n), static_cast<unsigned long long>(outside),
              static_cast<unsigned long long>(inside), worst_ratio);
  property::record("worst_error_over_bound", worst_ratio);
  if (n >= 100000) {
    for (int fam = 0; fam < scenes::kFamilyCount; ++fam)
      EXPECT_GT(log.cases(static_cast<Family>(fam)), 1000u) << scenes::family_name(fam);
  }
  EXPECT_GT(outside, n / 4);
  EXPECT_GT(inside, n / 50);
}

}  // namespace
}  // namespace frusta
