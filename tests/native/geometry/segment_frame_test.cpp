// SPDX-License-Identifier: MIT
// The per-segment precomputation and the axial split every pair test builds on.
#include "geometry/segment_frame.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "property_support.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;
using scenes::Family;

TEST(SegmentFrame, ThreeFourFiveConeHasExactAngles) {
  // L = 4 cm along -y from E, r1 - r2 = 3 cm: side 5 cm, cos 0.8, sin 0.6, tan 0.75
  const SegmentFrame f = make_segment_frame({{1.0, 1.96, 3.0}, {1.0, 2.0, 3.0}, 0.035, 0.005});
  EXPECT_FALSE(f.degenerate);
  EXPECT_NEAR(f.length, 0.04, 1e-15);
  EXPECT_NEAR(f.axis.x, 0.0, 0.0);
  EXPECT_NEAR(f.axis.y, -1.0, 1e-15);
  EXPECT_NEAR(f.axis.z, 0.0, 0.0);
  EXPECT_NEAR(f.slope, 0.75, 1e-13);
  EXPECT_NEAR(f.cos_alpha, 0.8, 1e-13);
  EXPECT_NEAR(f.sin_alpha, 0.6, 1e-13);
  EXPECT_EQ(f.r_proximal, 0.035);
  EXPECT_EQ(f.r_distal, 0.005);
  EXPECT_EQ(f.distal, vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(f.proximal, vec3(1.0, 1.96, 3.0));
}

TEST(SegmentFrame, CylinderHasExactlyZeroAngle) {
  const SegmentFrame f = make_segment_frame({{0.013, -0.02, 0.07}, {0.001, 0.002, 0.003}, 0.008, 0.008});
  EXPECT_EQ(f.sin_alpha, 0.0);
  EXPECT_EQ(f.cos_alpha, 1.0);
  EXPECT_EQ(f.slope, 0.0);
}

TEST(SegmentFrame, InvertedRadiiGiveANegativeAngle) {
  const SegmentFrame f = make_segment_frame({{0.04, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.003, 0.012});
  EXPECT_NEAR(f.sin_alpha, -9.0 / 41.0, 1e-15);
  EXPECT_NEAR(f.cos_alpha, 40.0 / 41.0, 1e-15);
  EXPECT_NEAR(f.slope, -0.225, 1e-15);
}

TEST(SegmentFrame, CoincidentEndsAreDegenerateWithADefaultAxis) {
  const SegmentFrame f = make_segment_frame({{0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 0.01, 0.005});
  EXPECT_TRUE(f.degenerate);
  EXPECT_EQ(f.length, 0.0);
  EXPECT_EQ(f.axis, vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(f.slope, 0.0);
  EXPECT_EQ(f.cos_alpha, 1.0);
  EXPECT_EQ(f.sin_alpha, 0.0);
  // a length of 1e-15 m beside centimetre radii is below the threshold too
  EXPECT_TRUE(make_segment_frame({{1e-15, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.01, 0.005}).degenerate);
  EXPECT_FALSE(make_segment_frame({{1e-9, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.01, 0.005}).degenerate);
}

TEST(SegmentFrame, SplitAxialGivesAxialAndRadialParts) {
  const SegmentFrame f = make_segment_frame({{0.0, 0.0, 0.05}, {0.0, 0.0, 0.01}, 0.01, 0.006});
  const AxialSplit s = split_axial(f, {0.03, -0.04, 0.02});
  EXPECT_NEAR(s.axial, 0.01, 1e-16);
  EXPECT_NEAR(s.radial_length, 0.05, 1e-16);
  EXPECT_NEAR(s.radial.z, 0.0, 1e-17);
  const vec3 n = radial_direction(f, s);
  EXPECT_NEAR(n.x, 0.6, 1e-15);
  EXPECT_NEAR(n.y, -0.8, 1e-15);
}

TEST(SegmentFrame, RadialDirectionOnTheAxisIsAUnitPerpendicular) {
  for (const vec3& d : {vec3(0.0, 0.0, 0.04), vec3(0.04, 0.0, 0.0), vec3(0.01, 0.02, -0.03)}) {
    const SegmentFrame f = make_segment_frame({d, vec3(0.0), 0.01, 0.006});
    AxialSplit s;  // exactly on the axis: radial part zero
    s.w = 0.5 * d;
    s.axial = 0.5 * f.length;
    const vec3 n = radial_direction(f, s);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-15);
    EXPECT_NEAR(glm::dot(n, f.axis), 0.0, 1e-15);
  }
}

// Every case: the frame's fields against their definitions, the split's parts.
TEST(SegmentFrameProperty, FieldsMatchTheirDefinitions) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 1);
  property::PropertyLog log("segment frame");
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f = make_segment_frame(c.segment);
    const vec3 d = c.segment.proximal - c.segment.distal;
    const double L = std::sqrt(glm::dot(d, d));
    const double scale = property::case_scale(c);
    const double eps = property::kRoundingUlps * scale;
    const double dr = c.segment.proximal_radius - c.segment.distal_radius;
    log.check(f.degenerate == (c.family == Family::kZeroLength), "degenerate iff D == E", c,
              [&] { return format("L=%.17g", L); });
    log.check(std::fabs(f.length - L) <= eps, "length = |D - E|", c,
              [&] { return format("length=%.17g |D-E|=%.17g", f.length, L); });
    if (f.degenerate) continue;
    log.check(std::fabs(glm::length(f.axis) - 1.0) <= 1e-14 &&
                  glm::length(f.axis * L - d) <= 1e-14 * L,
              "axis = (D - E) / L", c, [&] { return std::string(); });
    log.check(std::fabs(f.slope * L - dr) <= 1e-14 * (std::fabs(dr) + L), "tan = (r1 - r2) / L", c,
              [&] { return format("slope=%.17g", f.slope); });
    log.check(std::fabs(f.cos_alpha * f.cos_alpha + f.sin_alpha * f.sin_alpha - 1.0) <= 1e-14 &&
                  std::fabs(f.sin_alpha - f.slope * f.cos_alpha) <= 1e-14 &&
                  f.cos_alpha > 0.0 && (f.sin_alpha >= 0.0) == (dr >= 0.0),
              "cos, sin of alpha", c, [&] {
                return format("cos=%.17g sin=%.17g tan=%.17g", f.cos_alpha, f.sin_alpha, f.slope);
              });
    const AxialSplit s = split_axial(f, c.sphere.center);
    const double w = glm::length(s.w);
    log.check(glm::length(s.axial * f.axis + s.radial - s.w) <= eps &&
                  std::fabs(glm::dot(s.radial, f.axis)) <= eps &&
                  std::fabs(s.radial_length - glm::length(s.radial)) <= eps,
              "w = a u + p with p perpendicular to u", c, [&] { return std::string(); });
    const vec3 m = radial_direction(f, s);
    log.check(std::fabs(glm::length(m) - 1.0) <= 1e-12 && std::fabs(glm::dot(m, f.axis)) <= 1e-9,
              "radial_direction is a unit perpendicular of the axis", c, [&] {
                return format("|m|=%.17g m.u=%.3g q=%.3g |w|=%.3g", glm::length(m),
                              glm::dot(m, f.axis), s.radial_length, w);
              });
    if (s.radial_length > 1e-9 * w)
      log.check(glm::length(m * s.radial_length - s.radial) <= eps, "radial_direction = p / |p|", c,
                [&] { return std::string(); });
  }
  log.report();
}

}  // namespace
}  // namespace frusta
