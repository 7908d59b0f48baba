// SPDX-License-Identifier: MIT
// The 2-D meridian-section distance: hand-computed points of every region, and a
// sampled reference over a million points.
#include "geometry/trapezoid_distance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "brute_force_reference.h"
#include "property_support.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;

// L = 4, r2 = 1, r1 = 4: the side rises 3 over 4, length 5, outward normal (-0.6, 0.8).
constexpr double kL = 4.0, kR2 = 1.0, kR1 = 4.0;

void expect_result(const TrapezoidDistance& t, double distance, double nx, double ny,
                   double normal_x, double normal_y) {
  EXPECT_NEAR(t.distance, distance, 1e-14);
  EXPECT_NEAR(t.nearest_x, nx, 1e-14);
  EXPECT_NEAR(t.nearest_y, ny, 1e-14);
  EXPECT_NEAR(t.normal_x, normal_x, 1e-14);
  EXPECT_NEAR(t.normal_y, normal_y, 1e-14);
}

TEST(TrapezoidDistance, OutsideTheSideIsTheDistanceAlongItsNormal) {
  // (1, 6): side line signed distance -0.6 + 0.8 * 5 = 3.4, foot at (3.04, 3.28)
  expect_result(trapezoid_distance(1.0, 6.0, kL, kR2, kR1), 3.4, 3.04, 3.28, -0.6, 0.8);
}

TEST(TrapezoidDistance, BeyondACapIsTheAxialDistance) {
  expect_result(trapezoid_distance(-2.0, 0.5, kL, kR2, kR1), 2.0, 0.0, 0.5, -1.0, 0.0);
  expect_result(trapezoid_distance(7.0, 2.0, kL, kR2, kR1), 3.0, 4.0, 2.0, 1.0, 0.0);
}

TEST(TrapezoidDistance, CornerRegionsAreDistancesToTheRims) {
  expect_result(trapezoid_distance(-3.0, 5.0, kL, kR2, kR1), 5.0, 0.0, 1.0, -0.6, 0.8);
  // beyond D's rim: (7, 8) - (4, 4) = (3, 4)
  expect_result(trapezoid_distance(7.0, 8.0, kL, kR2, kR1), 5.0, 4.0, 4.0, 0.6, 0.8);
}

TEST(TrapezoidDistance, InsideDepthIsTheNearestEdgeLine) {
  // (2, 1): side line 1.2 away, caps 2 away
  const TrapezoidDistance t = trapezoid_distance(2.0, 1.0, kL, kR2, kR1);
  EXPECT_NEAR(t.distance, -1.2, 1e-14);
  EXPECT_NEAR(t.normal_x, -0.6, 1e-14);
  EXPECT_NEAR(t.normal_y, 0.8, 1e-14);
  // (0.5, 0.5): cap E 0.5 away, side line 0.7, cap D 3.5
  const TrapezoidDistance e = trapezoid_distance(0.5, 0.5, kL, kR2, kR1);
  expect_result(e, -0.5, 0.0, 0.5, -1.0, 0.0);
  const TrapezoidDistance d = trapezoid_distance(3.8, 0.5, kL, kR2, kR1);
  expect_result(d, -0.2, 4.0, 0.5, 1.0, 0.0);
}

// The nearest point of an inside point whose nearest edge is the side lies along the
// outward normal: (2, 1) + 1.2 (-0.6, 0.8) = (1.28, 1.96), where r(1.28) = 1.96.
// Found writing this test: the code moves the other way, to (2.72, 0.04), a point
// inside. exact_proximity does not read nearest_x/y (it rebuilds the point from the
// distance and normal), so only direct callers of trapezoid_distance see it.
TEST(TrapezoidDistance, InsideNearestPointOnTheSideIsOnTheSide) {
  const TrapezoidDistance t = trapezoid_distance(2.0, 1.0, kL, kR2, kR1);
  EXPECT_NEAR(t.nearest_x, 1.28, 1e-14);
  EXPECT_NEAR(t.nearest_y, 1.96, 1e-14);
}

TEST(TrapezoidDistance, PointsOnTheBoundaryHaveZeroDistance) {
  EXPECT_NEAR(trapezoid_distance(2.0, 2.5, kL, kR2, kR1).distance, 0.0, 1e-15);
  EXPECT_NEAR(trapezoid_distance(0.0, 0.5, kL, kR2, kR1).distance, 0.0, 1e-15);
  EXPECT_NEAR(trapezoid_distance(4.0, 3.0, kL, kR2, kR1).distance, 0.0, 1e-15);
}

TEST(TrapezoidDistance, ConeAndCylinder) {
  // cone r2 = 0: beyond the apex on the axis the apex is nearest
  EXPECT_NEAR(trapezoid_distance(-2.0, 0.0, 4.0, 0.0, 3.0).distance, 2.0, 1e-15);
  // cylinder: radial distance
  expect_result(trapezoid_distance(1.0, 3.0, 4.0, 1.0, 1.0), 2.0, 1.0, 1.0, 0.0, 1.0);
}

// Reference: the boundary (side, cap at E, cap at D; the axis is not a boundary of the
// solid of revolution) is three segments; the distance to each is convex and
// 1-Lipschitz in arc length, minimised by the refined sampling of minimise_convex.
struct Reference {
  double distance, tolerance;
};

Reference sampled(double x, double y, double L, double r2, double r1) {
  struct Edge {
    double ax, ay, bx, by;
  };
  const Edge edges[3] = {{0.0, r2, L, r1}, {0.0, 0.0, 0.0, r2}, {L, 0.0, L, r1}};
  double best = HUGE_VAL, tol = 0.0;
  for (const Edge& e : edges) {
    const double len = std::hypot(e.bx - e.ax, e.by - e.ay);
    if (len == 0.0) {
      best = std::min(best, std::hypot(x - e.ax, y - e.ay));
      continue;
    }
    auto f = [&](double s) {
      const double px = e.ax + (e.bx - e.ax) * (s / len), py = e.ay + (e.by - e.ay) * (s / len);
      return std::sqrt((x - px) * (x - px) + (y - py) * (y - py));
    };
    const reference::ConvexMinimum m = reference::minimise_convex(f, 0.0, len, 1.0, 1e-11 * len);
    if (m.value < best) best = m.value;
    tol = std::max(tol, m.tolerance);
  }
  const bool inside = x >= 0.0 && x <= L && y <= r2 + (r1 - r2) * (x / L);
  return {inside ? -best : best, tol};
}

TEST(TrapezoidDistanceProperty, MatchesSampledBoundaryDistance) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 2);
  property::PropertyLog log("trapezoid vs sampled boundary");
  std::uint64_t inside = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    const vec3 d = c.segment.proximal - c.segment.distal;
    const double L = std::sqrt(glm::dot(d, d));
    if (L == 0.0) continue;  // no trapezoid
    log.seen(c);
    // the case's meridian coordinates, computed here rather than by split_axial
    const vec3 w = c.sphere.center - c.segment.distal;
    const double x = glm::dot(w, d) / L;
    const double y = std::sqrt(std::max(0.0, glm::dot(w, w) - x * x));
    const double r1 = c.segment.proximal_radius, r2 = c.segment.distal_radius;
    const TrapezoidDistance t = trapezoid_distance(x, y, L, r2, r1);
    const Reference ref = sampled(x, y, L, r2, r1);
    const double eps = property::kRoundingUlps * (std::fabs(x) + y + L + r1 + r2);
    if (ref.distance < 0.0) ++inside;
    log.check(std::fabs(t.distance - ref.distance) <= ref.tolerance + eps, "distance", c, [&] {
      return format("x=%.17g y=%.17g: distance=%.17g reference=%.17g", x, y, t.distance, ref.distance);
    });
    log.check(std::fabs(std::hypot(t.normal_x, t.normal_y) - 1.0) <= 1e-12, "normal is unit", c,
              [&] { return format("n=(%.17g, %.17g)", t.normal_x, t.normal_y); });
    // p = nearest + distance * normal, inside and out
    log.check(std::hypot(x - (t.nearest_x + t.distance * t.normal_x),
                         y - (t.nearest_y + t.distance * t.normal_y)) <= eps,
              t.distance >= 0.0 ? "outside: p = nearest + distance * normal"
                                : "inside: p = nearest + distance * normal",
              c, [&] {
                return format("x=%.17g y=%.17g distance=%.17g nearest=(%.17g, %.17g)", x, y,
                              t.distance, t.nearest_x, t.nearest_y);
              });
  }
  log.report();
  EXPECT_GT(inside, n / 100);
}

}  // namespace
}  // namespace frusta
