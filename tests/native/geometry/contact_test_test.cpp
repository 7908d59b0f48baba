// SPDX-License-Identifier: MIT
// The engine's conservative contact test: hand-picked cases and, over a million seeded
// cases and several margins, zero false negatives against the exact reference.
#include "geometry/contact_test.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "geometry_fixtures.h"
#include "property_support.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;
using scenes::Family;


TEST(MayTouch, SideContactAndItsMargin) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const vec3 p(0.02, 0.0075, 0.0), n(-9.0 / 41.0, 40.0 / 41.0, 0.0);
  const Sphere s{p + (0.01 + 0.0015) * n, 0.01};  // 1.5 mm from the side
  EXPECT_FALSE(may_touch(f, s, 0.0));
  EXPECT_FALSE(may_touch(f, s, 0.0014));
  EXPECT_TRUE(may_touch(f, s, 0.0016));
  EXPECT_TRUE(may_touch(f, {p + 0.0099 * n, 0.01}, 0.0));
}

TEST(MayTouch, CatchesTheTipBallThatEq5Misses) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  EXPECT_TRUE(may_touch(f, {{-0.012, 0.001, 0.0}, 0.01}, 0.0));
  // straight beyond the tip, 2 mm away
  EXPECT_FALSE(may_touch(f, {{-0.015, 0.0, 0.0}, 0.01}, 0.0019));
  EXPECT_TRUE(may_touch(f, {{-0.015, 0.0, 0.0}, 0.01}, 0.0021));
}

TEST(MayTouch, NoFalseContactNearTheTipCap) {
  // eq. 5 reports this sphere; it is 1.2 mm from the solid
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  EXPECT_FALSE(may_touch(f, {{-0.009, 0.011, 0.0}, 0.01}, 0.0));
}

TEST(MayTouch, DegenerateSegmentIsItsBalls) {
  const SegmentFrame f = make_segment_frame({{0.1, 0.2, 0.3}, {0.1, 0.2, 0.3}, 0.01, 0.005});
  EXPECT_TRUE(may_touch(f, {{0.1, 0.2, 0.3195}, 0.01}, 0.0));
  EXPECT_FALSE(may_touch(f, {{0.1, 0.2, 0.3205}, 0.01}, 0.0));
}

TEST(MayTouch, FarOffsetBehavesLikeTheOrigin) {
  const vec3 o(1.0e6, -2.0e6, 1.5e6);
  const Segment s = cone_9_40_41();
  const SegmentFrame f = make_segment_frame({s.proximal + o, s.distal + o, 0.012, 0.003});
  EXPECT_TRUE(may_touch(f, {vec3(-0.012, 0.001, 0.0) + o, 0.01}, 0.0));
  EXPECT_FALSE(may_touch(f, {vec3(-0.009, 0.011, 0.0) + o, 0.01}, 0.0));
}

TEST(MayTouchSphere, GapBetweenTwoSpheres) {
  const Sphere a{{0.0, 0.0, 0.0}, 0.01}, b{{0.025, 0.0, 0.0}, 0.01};  // 5 mm apart
  EXPECT_FALSE(may_touch_sphere(a, b, 0.0049));
  EXPECT_TRUE(may_touch_sphere(a, b, 0.0051));
  EXPECT_TRUE(may_touch_sphere(a, {{0.019, 0.0, 0.0}, 0.01}, 0.0));
}

// (b) zero false negatives: may_touch(margin) is true whenever exact gap <= margin.
TEST(MayTouchProperty, NeverMissesAContactAtAnyMargin) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 6);
  property::PropertyLog log("may_touch");
  constexpr std::array<double, 4> kMargins = {0.0, 1e-4, 2e-3, 1e-2};
  std::array<std::array<std::uint64_t, 4>, 4> count{};  // margin x {contacts, FN, FP, cases}
  std::array<std::uint64_t, scenes::kFamilyCount> fp_by_family{};
  double worst_fp_gap = 0.0;  // largest exact gap - margin among false positives
  std::uint64_t boundary_fp = 0, boundary_cases = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f = make_segment_frame(c.segment);
    const double gap = exact_distance(f, c.sphere);
    for (size_t m = 0; m < kMargins.size(); ++m) {
      const double margin = kMargins[m];
      const bool truth = gap <= margin;
      const bool test = may_touch(f, c.sphere, margin);
      ++count[m][3];
      if (truth) ++count[m][0];
      log.check(test || !truth, "no false negative", c, [&] {
        return format("margin=%.3g exact gap=%.17g", margin, gap);
      });
      if (test && !truth) {
        ++count[m][2];
        ++fp_by_family[static_cast<size_t>(c.family)];
        worst_fp_gap = std::max(worst_fp_gap, gap - margin);
      }
      if (!test && truth) ++count[m][1];
    }
    // at the margin itself: a boundary case's known gap g is the margin that just touches
    if (c.family == Family::kBoundary && c.expected_gap > 0.0) {
      const double g = c.expected_gap;
      log.check(may_touch(f, c.sphere, g + 1e-12), "no false negative at margin = gap", c,
                [&] { return format("gap=%.17g", g); });
      // 10 pm short of touching: far beyond the rounding slack (~1e-13 of the size)
      if (may_touch(f, c.sphere, g - 1e-11)) ++boundary_fp;
      ++boundary_cases;
    }
    // the sphere-sphere test against the tip ball
    const Sphere tip{c.segment.distal, c.segment.distal_radius};
    const vec3 d = c.sphere.center - tip.center;
    const double ball_gap = std::sqrt(glm::dot(d, d)) - tip.radius - c.sphere.radius;
    log.check(may_touch_sphere(tip, c.sphere, 0.0) || ball_gap > 0.0,
              "may_touch_sphere: no false negative", c,
              [&] { return format("gap=%.17g", ball_gap); });
  }
  log.report();
  for (size_t m = 0; m < kMargins.size(); ++m) {
    const double negatives = double(count[m][3] - count[m][0]);
    const double fp_rate = negatives > 0 ? double(count[m][2]) / negatives : 0.0;
    std::printf("[ may_touch ] margin %-6g: %llu contacts, FN %llu, FP %llu (rate %.3g)\n",
                kMargins[m], static_cast<unsigned long long>(count[m][0]),
                static_cast<unsigned long long>(count[m][1]),
                static_cast<unsigned long long>(count[m][2]), fp_rate);
    property::record(format("may_touch_fp_rate_margin_%g", kMargins[m]), fp_rate);
    property::record(format("may_touch_fn_margin_%g", kMargins[m]), double(count[m][1]));
    EXPECT_EQ(count[m][1], 0u);
    EXPECT_GT(count[m][0], n / 10);
    // conservative only by rounding slack and the end bands: FP stay rare
    EXPECT_LT(fp_rate, 0.01);
  }
  std::printf("[ may_touch ] false positives by family:%s",
              worst_fp_gap > 0.0 ? "" : " none");
  for (int k = 0; k < scenes::kFamilyCount; ++k)
    if (fp_by_family[static_cast<size_t>(k)] > 0)
      std::printf(" %s=%llu", scenes::family_name(k),
                  static_cast<unsigned long long>(fp_by_family[static_cast<size_t>(k)]));
  std::printf("; largest gap beyond the margin %.3g m\n", worst_fp_gap);
  std::printf("[ may_touch ] boundary cases with the margin 1e-11 m short of the gap: %llu of %llu "
              "reported\n",
              static_cast<unsigned long long>(boundary_fp),
              static_cast<unsigned long long>(boundary_cases));
  // in exact arithmetic may_touch is exact_distance <= margin; its rounding slack is
  // ~1e-13 of the case's size
  EXPECT_LE(worst_fp_gap, 1e-11);
  EXPECT_EQ(boundary_fp, 0u);
  EXPECT_GT(boundary_cases, n / 20);
}

// A candidate's gap bounds stand in for may_touch in every pass over candidates, from
// where the body was when they were measured: may_touch must never hold at a margin
// below the least or fail at one above the most, there or after a move of the body
// (else a pass drops a sphere its body touches, or keeps one it does not), and both
// should sit close around the exact gap (else they decide nothing).
TEST(GapBoundsProperty, MayTouchHoldsBelowNeitherAndFailsAboveNeitherNearOrMoved) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 7);
  std::mt19937_64 rng(scenes::kPropertySeed + 8);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  property::PropertyLog log("gap_bounds");
  constexpr std::array<double, 5> kMargins = {0.0, 1e-5, 1e-4, 2e-3, 1e-2};
  double loosest = 0.0;  // the widest bounds around a positive exact gap, by the case's
                         // world scale (their rounding allowance grows with it)
  std::uint64_t moved_tested = 0;
  Sphere last_sphere{vec3(0.01, -0.02, 0.03), 0.005};
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    const SegmentFrame f = make_segment_frame(c.segment);
    log.seen(c);
    const GapBounds bounds = gap_bounds(f, c.sphere);
    const double gap = exact_distance(f, c.sphere);
    auto describe = [&] {
      return format("least=%.17g most=%.17g gap=%.17g", bounds.least, bounds.most, gap);
    };
    for (double margin : kMargins) {
      const bool touch = may_touch(f, c.sphere, margin);
      log.check(!touch || may_be_within(bounds, 0.0, margin), "may_touch implies may_be_within", c,
                describe);
      log.check(touch || !surely_within(bounds, 0.0, margin), "surely_within implies may_touch", c,
                describe);
    }
    // just past the bounds may_touch must fail, and hold (the least margin that holds
    // lies between them)
    if (bounds.least > 0.0)
      log.check(!may_touch(f, c.sphere, bounds.least * (1.0 - 1e-9)),
                "may_touch fails below the least", c, describe);
    log.check(may_touch(f, c.sphere, bounds.most * (1.0 + 1e-9)), "may_touch holds above the most",
              c, describe);
    // bounds of the exact gap (0 inside), which a move of m shifts by at most m
    log.check(bounds.least <= std::max(gap, 0.0) && gap <= bounds.most,
              "least <= exact gap <= most", c, describe);
    if (gap > 0.0)
      loosest = std::max(loosest, (bounds.most - bounds.least) / property::world_scale(c));
    // the body moved: each end by up to 5 mm, the same radii
    Segment moved = c.segment;
    const double size = 0.005 * std::fabs(unit(rng));
    moved.proximal += size * vec3(unit(rng), unit(rng), unit(rng));
    moved.distal += size * vec3(unit(rng), unit(rng), unit(rng));
    const double move = std::max(glm::length(moved.proximal - c.segment.proximal),
                                 glm::length(moved.distal - c.segment.distal));
    const SegmentFrame g = make_segment_frame(moved);
    for (double margin : kMargins) {
      const bool touch = may_touch(g, c.sphere, margin);
      moved_tested += touch ? 1 : 0;
      log.check(!touch || may_be_within(bounds, move, margin),
                "moved: may_touch implies may_be_within", c,
                [&] { return format("margin=%.3g move=%.17g ", margin, move) + describe(); });
      log.check(touch || !surely_within(bounds, move, margin),
                "moved: surely_within implies may_touch", c,
                [&] { return format("margin=%.3g move=%.17g ", margin, move) + describe(); });
    }
    // two at once (as a detection bounds its hits): each one's own bits, the other a
    // sphere of the last case
    GapBounds first, second;
    gap_bounds(f, c.sphere, last_sphere, first, second);
    const GapBounds alone = gap_bounds(f, last_sphere);
    log.check(std::memcmp(&first, &bounds, sizeof first) == 0 &&
                  std::memcmp(&second, &alone, sizeof second) == 0,
              "two at once: each as alone, to the bit", c, describe);
    last_sphere = c.sphere;
    // two spheres: the tip ball against the case's sphere
    const Sphere tip{c.segment.distal, c.segment.distal_radius};
    const GapBounds ball = gap_bounds_sphere(tip, c.sphere);
    for (double margin : kMargins) {
      const bool touch = may_touch_sphere(tip, c.sphere, margin);
      log.check(!touch || may_be_within(ball, 0.0, margin),
                "may_touch_sphere implies may_be_within", c,
                [&] { return format("margin=%.3g least=%.17g", margin, ball.least); });
      log.check(touch || !surely_within(ball, 0.0, margin),
                "surely_within implies may_touch_sphere", c,
                [&] { return format("margin=%.3g most=%.17g", margin, ball.most); });
    }
  }
  log.report();
  std::printf(
      "[ gap_bounds ] widest bounds around a positive exact gap %.3g of the world scale; %llu "
      "moved contacts\n",
      loosest, static_cast<unsigned long long>(moved_tested));
  property::record("gap_bounds_width_relative", loosest);
  EXPECT_LT(loosest, 1e-11);  // rounding only: the gap itself, not a looser bound of it
  EXPECT_GT(moved_tested, n / 10);
}

}  // namespace
}  // namespace frusta
