// SPDX-License-Identifier: MIT
// Sphere/segment queries through the C ABI (native/src/capi/api_geometry.cpp): the
// same numbers as the internal geometry, and the right geometry on cases worked out
// by hand, by an independent distance reference and by finite differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <random>

#include "capi_fixture.h"
#include "frusta/frusta.h"
#include "geometry/constraint.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/patent_test.h"
#include "geometry/segment_frame.h"

namespace frusta {
namespace {

// suite names start with "capi" so that `ctest -R capi` selects them
using capiGeometry = testing::CapiTest;

vec3 v(const double p[3]) { return vec3(p[0], p[1], p[2]); }
void put(const vec3& value, double out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = value[k];
}

frusta_segment make_segment(const vec3& d, const vec3& e, double r1, double r2) {
  frusta_segment s{};
  put(d, s.proximal);
  put(e, s.distal);
  s.proximal_radius = r1;
  s.distal_radius = r2;
  return s;
}

frusta_sphere make_sphere(const vec3& c, double r) {
  frusta_sphere s{};
  put(c, s.center);
  s.radius = r;
  return s;
}

frusta_contact_query query(const frusta_segment& segment, const frusta_sphere& sphere) {
  frusta_contact_query q{};
  q.struct_size = sizeof q;
  EXPECT_EQ(frusta_query_contact(&segment, &sphere, &q), FRUSTA_OK) << frusta_last_error();
  return q;
}

frusta_constraint constraint(const frusta_segment& segment, const frusta_sphere& sphere, int form) {
  frusta_constraint c{};
  c.struct_size = sizeof c;
  EXPECT_EQ(frusta_constraint_eval(&segment, &sphere, form, &c), FRUSTA_OK) << frusta_last_error();
  return c;
}

Segment internal(const frusta_segment& s) {
  return {v(s.proximal), v(s.distal), s.proximal_radius, s.distal_radius};
}
Sphere internal(const frusta_sphere& s) { return {v(s.center), s.radius}; }

// Hand-sized random inputs: segments of 0 to 6 cm with radii up to 1.5 cm (a tenth
// exactly degenerate, some with zero radii, tapering either way), spheres near them.
struct Case {
  frusta_segment segment;
  frusta_sphere sphere;
};
Case random_case(std::mt19937_64& rng, int trial) {
  std::uniform_real_distribution<double> coord(-0.06, 0.06), radius(0.0, 0.015), unit(0.0, 1.0);
  const vec3 e(coord(rng), coord(rng), coord(rng));
  vec3 d = e + 0.5 * vec3(coord(rng), coord(rng), coord(rng));
  if (trial % 10 == 0) d = e;
  double r1 = radius(rng), r2 = radius(rng);
  if (trial % 7 == 0) r1 = 0.0;
  if (trial % 11 == 0) r2 = 0.0;
  vec3 c = 0.5 * (d + e) + vec3(coord(rng), coord(rng), coord(rng));
  if (trial % 3 == 1) {  // centre inside or near the solid: penetration
    const vec3 offset = glm::normalize(vec3(coord(rng), coord(rng), coord(rng)) + vec3(1e-9));
    // (off the axis: a centre exactly on it is covered by NormalOfACentreOnTheAxis...)
    c = e + unit(rng) * (d - e) + (0.001 + unit(rng) * std::max(r1, r2)) * offset;
  }
  const double r = trial % 13 == 0 ? 0.0 : 0.03 * unit(rng);
  return {make_segment(d, e, r1, r2), make_sphere(c, r)};
}

// Independent reference: signed distance from a point to the solid, by the solid's
// meridian section. The frustum part is the trapezoid (0,0) (0,r2) (L,r1) (L,0) in
// (axial from E, radial) coordinates; the balls are plain spheres.
double point_to_segment_2d(double px, double py, double ax, double ay, double bx, double by) {
  const double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
  const double t = len2 > 0 ? std::clamp(((px - ax) * ex + (py - ay) * ey) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - (ax + t * ex), py - (ay + t * ey));
}
double reference_signed_distance(const frusta_segment& s, const vec3& o) {
  const vec3 d = v(s.proximal), e = v(s.distal);
  double best =
      std::min(glm::length(o - d) - s.proximal_radius, glm::length(o - e) - s.distal_radius);
  const double length = glm::length(d - e);
  if (length > 0.0) {
    const vec3 u = (d - e) / length;
    const double a = glm::dot(o - e, u), q = glm::length((o - e) - a * u);
    const double r1 = s.proximal_radius, r2 = s.distal_radius;
    const double side = point_to_segment_2d(a, q, 0.0, r2, length, r1);
    const double cap_e = point_to_segment_2d(a, q, 0.0, 0.0, 0.0, r2);
    const double cap_d = point_to_segment_2d(a, q, length, 0.0, length, r1);
    // inside: below the side's line, between the caps
    const double line = (q - r2) * length - a * (r1 - r2);  // > 0 above the side
    const bool inside = a >= 0.0 && a <= length && line <= 0.0;
    const double frustum =
        inside ? -std::min({side, cap_e, cap_d}) : std::min({side, cap_e, cap_d});
    best = std::min(best, frustum);
  }
  return best;
}

// ---------------------------------------------------------------- worked cases

TEST_F(capiGeometry, SphereTouchingACylindersSideIsAtDistanceZero) {
  std::mt19937_64 rng(21);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> along(0.1, 0.9), size(0.005, 0.05);
  for (int trial = 0; trial < 100; ++trial) {
    // a cylinder of radius r from E to D along a random axis, a sphere of radius R
    // touching it from a random perpendicular direction
    const vec3 e(gauss(rng), gauss(rng), gauss(rng));
    const vec3 axis = glm::normalize(vec3(gauss(rng), gauss(rng), gauss(rng)));
    const vec3 perp = glm::normalize(glm::cross(axis, vec3(gauss(rng), gauss(rng), gauss(rng))));
    const double length = 0.05, r = size(rng), big_r = size(rng), k = along(rng);
    const vec3 d = e + length * axis;
    const vec3 foot = e + k * length * axis;
    const frusta_segment cylinder = make_segment(d, e, r, r);
    const frusta_sphere sphere = make_sphere(foot + (r + big_r) * perp, big_r);
    const frusta_contact_query q = query(cylinder, sphere);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    EXPECT_NEAR(q.distance, 0.0, 1e-12);
    EXPECT_EQ(q.feature, FRUSTA_FEATURE_SIDE);
    EXPECT_EQ(q.contact, 1);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(q.normal[i], -perp[i], 1e-12) << "normal points from the sphere to the hand";
      EXPECT_NEAR(q.hand_point[i], foot[i] + r * perp[i], 1e-12);
      EXPECT_NEAR(q.object_point[i], foot[i] + r * perp[i], 1e-12);
    }
    EXPECT_NEAR(q.axial, k, 1e-12) << "k is 0 at E and 1 at D";
    for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
      const frusta_constraint c = constraint(cylinder, sphere, form);
      EXPECT_EQ(c.feature, FRUSTA_FEATURE_SIDE);
      EXPECT_NEAR(c.value, 0.0, 1e-12) << "form " << form;
    }
    // moved out by 1 mm: distance 1 mm, no contact, distance form 1 mm
    const frusta_sphere apart = make_sphere(foot + (r + big_r + 0.001) * perp, big_r);
    const frusta_contact_query qa = query(cylinder, apart);
    EXPECT_NEAR(qa.distance, 0.001, 1e-12);
    EXPECT_EQ(qa.contact, 0);
    EXPECT_EQ(qa.patent_contact, 0) << "the published test is exact on a cylinder's side";
    EXPECT_NEAR(constraint(cylinder, apart, FRUSTA_CONSTRAINT_DISTANCE).value, 0.001, 1e-12);
    // moved in by 1 mm: penetration depth 1 mm
    const frusta_sphere into = make_sphere(foot + (r + big_r - 0.001) * perp, big_r);
    const frusta_contact_query qi = query(cylinder, into);
    EXPECT_NEAR(qi.distance, -0.001, 1e-12);
    EXPECT_EQ(qi.contact, 1);
    EXPECT_EQ(qi.patent_contact, 1);
    EXPECT_NEAR(constraint(cylinder, into, FRUSTA_CONSTRAINT_DISTANCE).value, -0.001, 1e-12);
  }
}

TEST_F(capiGeometry, SphereBeyondAnEndTouchesThatEndsBall) {
  const vec3 e(0.0, 0.0, 0.0), d(0.04, 0.0, 0.0);
  const frusta_segment cone = make_segment(d, e, 0.01, 0.006);
  // beyond D along the axis, 2 cm from the ball's surface
  const frusta_contact_query qd =
      query(cone, make_sphere(vec3(0.04 + 0.01 + 0.02 + 0.005, 0, 0), 0.005));
  EXPECT_EQ(qd.feature, FRUSTA_FEATURE_PROXIMAL);
  EXPECT_NEAR(qd.distance, 0.02, 1e-15);
  EXPECT_NEAR(qd.normal[0], -1.0, 1e-15);
  EXPECT_NEAR(qd.hand_point[0], 0.05, 1e-15);
  EXPECT_NEAR(qd.axial, (0.075) / 0.04, 1e-12);
  // beyond E diagonally: the distal ball
  const vec3 dir = glm::normalize(vec3(-1.0, 1.0, 1.0));
  const frusta_sphere s = make_sphere(e + (0.006 + 0.003 + 0.004) * dir, 0.004);
  const frusta_contact_query qe = query(cone, s);
  EXPECT_EQ(qe.feature, FRUSTA_FEATURE_DISTAL);
  EXPECT_NEAR(qe.distance, 0.003, 1e-15);
  for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE})
    EXPECT_EQ(constraint(cone, s, form).feature, FRUSTA_FEATURE_DISTAL);
  EXPECT_NEAR(constraint(cone, s, FRUSTA_CONSTRAINT_DISTANCE).value, 0.003, 1e-15);
  EXPECT_NEAR(constraint(cone, s, FRUSTA_CONSTRAINT_SQUARED).value, 0.013 * 0.013 - 0.01 * 0.01,
              1e-15);
}

// Inside, the depth is that of the deepest single part (frustum or end ball).
TEST_F(capiGeometry, PenetrationDepthIsThatOfTheDeepestPart) {
  // a fat cylinder, radius 5 cm, 10 cm long from E at the origin along +x
  const frusta_segment fat = make_segment(vec3(0.1, 0, 0), vec3(0, 0, 0), 0.05, 0.05);
  // 18 mm from cap E, 20 mm from the side: the frustum's depth is 18 mm, deeper
  // than ball E's 50 - |(18, 30)| = 15.0 mm
  const frusta_contact_query q = query(fat, make_sphere(vec3(0.018, 0.03, 0.0), 0.001));
  EXPECT_NEAR(q.distance, -0.018 - 0.001, 1e-15);
  EXPECT_EQ(q.feature, FRUSTA_FEATURE_SIDE) << "the frustum part names the contact";
  EXPECT_NEAR(q.normal[0], 1.0, 1e-15) << "out through cap E";
  // 5 mm from cap E near the axis: ball E (depth 45 mm) is the deepest part
  const frusta_contact_query qe = query(fat, make_sphere(vec3(0.005, 0.0, 0.0), 0.0));
  EXPECT_NEAR(qe.distance, -0.045, 1e-15);
  EXPECT_EQ(qe.feature, FRUSTA_FEATURE_DISTAL);
  // the middle of the axis: 50 mm from the side, deeper than either ball (0)
  const frusta_contact_query qm = query(fat, make_sphere(vec3(0.05, 0.0, 0.0), 0.0));
  EXPECT_NEAR(qm.distance, -0.05, 1e-15);
  EXPECT_EQ(qm.feature, FRUSTA_FEATURE_SIDE);
}

// A sphere centred on the segment's axis, between the ends, is deepest below the
// side: the normal is radial (any radial direction will do) and unit, and the hand
// point lies on the lateral surface. Points computed on a slanted axis carry rounding
// noise of ~1e-18 m in their radial part; that noise must not pick the direction.
TEST_F(capiGeometry, NormalOfACentreOnTheAxisIsRadialAndUnit) {
  const vec3 d(0.04, 0.035, 0.01), e(0.01, 0.02, 0.03);
  const vec3 axis = glm::normalize(d - e);
  for (double r2 : {0.01, 0.008}) {  // a cylinder, then a frustum
    const frusta_segment s = make_segment(d, e, 0.01, r2);
    for (double t : {0.3, 0.4, 0.5, 0.6, 0.7}) {
      frusta_sphere sphere = make_sphere(vec3(0.0), 0.002);
      for (int k = 0; k < 3; ++k)  // E + t (D - E), as a caller would compute it
        sphere.center[k] = s.distal[k] + t * (s.proximal[k] - s.distal[k]);
      const frusta_contact_query q = query(s, sphere);
      SCOPED_TRACE(::testing::Message() << "r2 " << r2 << " t " << t << " normal (" << q.normal[0]
                                        << ", " << q.normal[1] << ", " << q.normal[2] << ")");
      EXPECT_EQ(q.feature, FRUSTA_FEATURE_SIDE);
      EXPECT_NEAR(glm::length(v(q.normal)), 1.0, 1e-12);
      const double along = glm::dot(v(q.normal), axis);
      const double sin_a = (0.01 - r2) / std::hypot(glm::distance(d, e), 0.01 - r2);
      EXPECT_NEAR(along, sin_a, 1e-9) << "the side's normal leans by alpha, no more";
      EXPECT_NEAR(reference_signed_distance(s, v(q.hand_point)), 0.0, 1e-12)
          << "hand point off the surface";
    }
  }
}

// Beside the rim, ball and frustum are equally near: the ball (which contains the
// rim) names the contact.
TEST_F(capiGeometry, OnATieTheEndBallNamesTheContact) {
  const frusta_segment cylinder = make_segment(vec3(0.04, 0, 0), vec3(0, 0, 0), 0.01, 0.01);
  const frusta_contact_query qe = query(cylinder, make_sphere(vec3(0.0, 0.0, 0.02), 0.005));
  EXPECT_EQ(qe.distance, 0.005);
  EXPECT_EQ(qe.feature, FRUSTA_FEATURE_DISTAL);
  const frusta_contact_query qd = query(cylinder, make_sphere(vec3(0.04, -0.02, 0.0), 0.005));
  EXPECT_EQ(qd.distance, 0.005);
  EXPECT_EQ(qd.feature, FRUSTA_FEATURE_PROXIMAL);
}

// The endpoint rule: the side while the sphere's touching point on the side's line lies
// between E and D, else the ball at the end it passed. On a tapered segment the centre
// sits R sin(alpha) behind its touching point, so the two can fall on either side of E.
// Near the larger end D its ball bulges past the side: a sphere touching the side's line
// there overlaps that ball, and the ball's (negative) constraint wins.
TEST_F(capiGeometry, EndpointRuleFollowsTheTouchingPointOnTheSide) {
  const double length = 0.04, r1 = 0.012, r2 = 0.008, radius = 0.01;
  const frusta_segment cone = make_segment(vec3(length, 0, 0), vec3(0, 0, 0), r1, r2);
  const double side = std::hypot(length, r1 - r2);
  const double sin_a = (r1 - r2) / side, cos_a = length / side;
  const vec3 n(-sin_a, cos_a, 0.0);   // the side's outward normal in the x-y meridian
  auto touching_at = [&](double x) {  // a sphere touching the side's line at axial x
    return make_sphere(vec3(x, r2 + x * (r1 - r2) / length, 0.0) + radius * n, radius);
  };
  const double behind = radius * sin_a;  // the centre's axial lag: 1 mm
  ASSERT_GT(behind, 0.0009);
  struct Row {
    double x;
    int feature;
    bool overlaps;
  } rows[] = {{0.5 * behind, FRUSTA_FEATURE_SIDE, false},  // centre behind E, touch past it
              {-0.5 * behind, FRUSTA_FEATURE_DISTAL, false},
              {0.5 * length, FRUSTA_FEATURE_SIDE, false},
              {length - 0.5 * behind, FRUSTA_FEATURE_PROXIMAL, true},  // inside D's bulge
              {length + 0.5 * behind, FRUSTA_FEATURE_PROXIMAL, false}};
  for (const Row& row : rows)
    for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
      const frusta_constraint g = constraint(cone, touching_at(row.x), form);
      EXPECT_EQ(g.feature, row.feature) << "touching point at axial " << row.x << ", form " << form;
      if (row.feature == FRUSTA_FEATURE_SIDE) {
        EXPECT_NEAR(g.value, 0.0, 1e-12) << "touching";
      }
      if (row.overlaps) {
        EXPECT_LT(g.value, 0.0) << "overlaps the ball at D";
      }
    }
}

TEST_F(capiGeometry, DegenerateSegmentIsItsLargerBall) {
  const frusta_segment dot = make_segment(vec3(0.1, 0.2, 0.3), vec3(0.1, 0.2, 0.3), 0.004, 0.01);
  const frusta_sphere s = make_sphere(vec3(0.1, 0.2, 0.3 + 0.05), 0.01);
  const frusta_contact_query q = query(dot, s);
  EXPECT_NEAR(q.distance, 0.03, 1e-15);
  EXPECT_EQ(q.axial, 0.0);
  EXPECT_EQ(q.patent_contact, 0) << "the published test is undefined for L = 0";
  EXPECT_NEAR(q.normal[2], -1.0, 1e-15);
  const frusta_constraint c = constraint(dot, s, FRUSTA_CONSTRAINT_DISTANCE);
  EXPECT_EQ(c.feature, FRUSTA_FEATURE_DISTAL);
  EXPECT_NEAR(c.value, 0.03, 1e-15);
}

// ---------------------------------------------------------------- against internals

TEST_F(capiGeometry, QueryEqualsInternalExactProximity) {
  std::mt19937_64 rng(22);
  for (int trial = 0; trial < 2000; ++trial) {
    const Case c = random_case(rng, trial);
    const frusta_contact_query q = query(c.segment, c.sphere);
    const SegmentFrame frame = make_segment_frame(internal(c.segment));
    const Sphere ball = internal(c.sphere);
    const Proximity p = exact_proximity(frame, ball);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    EXPECT_EQ(q.struct_size, static_cast<int32_t>(sizeof q));
    EXPECT_EQ(q.feature, static_cast<int32_t>(p.feature));
    EXPECT_EQ(q.distance, p.distance);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(q.hand_point[k], p.hand_point[k]);
      EXPECT_EQ(q.object_point[k], p.object_point[k]);
      EXPECT_EQ(q.normal[k], p.normal[k]);
    }
    EXPECT_EQ(q.contact, may_touch(frame, ball, 0.0) ? 1 : 0);
    EXPECT_EQ(q.patent_contact, patent_contact(frame, ball) ? 1 : 0);
    EXPECT_EQ(q.axial, axial_fraction(frame, ball.center));
  }
}

TEST_F(capiGeometry, ConstraintEqualsInternalConstraint) {
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 2000; ++trial) {
    const Case c = random_case(rng, trial);
    const SegmentFrame frame = make_segment_frame(internal(c.segment));
    for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
      const frusta_constraint got = constraint(c.segment, c.sphere, form);
      const Constraint want =
          contact_constraint(frame, internal(c.sphere), static_cast<ConstraintForm>(form));
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " form " << form);
      EXPECT_EQ(got.struct_size, static_cast<int32_t>(sizeof got));
      EXPECT_EQ(got.feature, static_cast<int32_t>(want.feature));
      EXPECT_EQ(got.value, want.value);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(got.grad_proximal[k], want.grad_proximal[k]);
        EXPECT_EQ(got.grad_distal[k], want.grad_distal[k]);
        EXPECT_EQ(got.grad_center[k], want.grad_center[k]);
      }
    }
  }
}

// ---------------------------------------------------------------- geometry

TEST_F(capiGeometry, DistanceMatchesAnIndependentReference) {
  std::mt19937_64 rng(24);
  for (int trial = 0; trial < 5000; ++trial) {
    const Case c = random_case(rng, trial);
    const frusta_contact_query q = query(c.segment, c.sphere);
    const double want = reference_signed_distance(c.segment, v(c.sphere.center)) - c.sphere.radius;
    EXPECT_NEAR(q.distance, want, 1e-12) << "trial " << trial;
  }
}

// The reported points and normal are consistent with the distance: the hand point is
// on the solid's surface, the object point on the sphere's, and they are `distance`
// apart along the unit normal.
TEST_F(capiGeometry, PointsAndNormalAgreeWithTheDistance) {
  std::mt19937_64 rng(25);
  for (int trial = 0; trial < 2000; ++trial) {
    const Case c = random_case(rng, trial);
    const frusta_contact_query q = query(c.segment, c.sphere);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    const vec3 n = v(q.normal), hand = v(q.hand_point), object = v(q.object_point);
    const vec3 center = v(c.sphere.center);
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    EXPECT_NEAR(glm::distance(object, center + c.sphere.radius * n), 0.0, 1e-12);
    EXPECT_NEAR(glm::distance(hand - object, q.distance * n), 0.0, 1e-12);
    // outside, the hand point is on the solid's surface; with the centre inside, on the
    // surface of the deepest part, which may lie inside another part (a lower bound)
    const double hand_depth = reference_signed_distance(c.segment, hand);
    if (q.distance + c.sphere.radius > 0.0) {
      EXPECT_NEAR(hand_depth, 0.0, 1e-12) << "hand point off the surface";
    } else {
      EXPECT_LE(hand_depth, 1e-12) << "hand point outside the solid";
    }
  }
}

// The engine's contact flag never misses a contact and, away from rounding, never
// reports one that is not there: it equals distance <= 0.
TEST_F(capiGeometry, ContactFlagEqualsDistanceAtMostZero) {
  std::mt19937_64 rng(26);
  int checked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Case c = random_case(rng, trial);
    const frusta_contact_query far = query(c.segment, c.sphere);
    if (far.distance <= 1e-4) continue;  // need room to grow the sphere
    // grow the sphere about its centre until its gap is exactly `gap`; the nearest
    // point of the hand stays the same
    const double reach = far.distance + c.sphere.radius;
    for (double gap : {1e-6, 1e-9, 0.0, -1e-9, -1e-6, -1e-3}) {
      c.sphere.radius = reach - gap;
      const frusta_contact_query q = query(c.segment, c.sphere);
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " gap " << gap);
      EXPECT_NEAR(q.distance, gap, 1e-12);
      if (gap <= 0.0) {
        EXPECT_EQ(q.contact, 1) << "missed contact";
      } else if (gap > 1e-10) {
        EXPECT_EQ(q.contact, 0) << "phantom contact";
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

// ---------------------------------------------------------------- constraints

// Where the endpoint rule and the exact query name the same feature and the sphere
// is clear of the hand, the distance form is the exact gap; both forms share its sign.
TEST_F(capiGeometry, DistanceFormIsTheGapWhenTheFeaturesAgree) {
  std::mt19937_64 rng(27);
  int agreed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Case c = random_case(rng, trial);
    const frusta_contact_query q = query(c.segment, c.sphere);
    const frusta_constraint g = constraint(c.segment, c.sphere, FRUSTA_CONSTRAINT_DISTANCE);
    const frusta_constraint g2 = constraint(c.segment, c.sphere, FRUSTA_CONSTRAINT_SQUARED);
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    EXPECT_EQ(g.feature, g2.feature) << "both forms use the same endpoint rule";
    if (std::fabs(g.value) > 1e-12) {
      EXPECT_EQ(g.value > 0, g2.value > 0) << "same zero set";
    }
    if (q.distance <= 0.0 || g.feature != q.feature) continue;
    EXPECT_NEAR(g.value, q.distance, 1e-12);
    ++agreed;
  }
  EXPECT_GT(agreed, 1000);
}

// frusta.h: "A constraint value g >= 0 (non-penetrating)". A sphere that sinks into
// an end ball where the ball bulges out of the frustum's side (by r (1 - cos alpha))
// must therefore get g < 0, whichever feature the endpoint rule picks.
TEST_F(capiGeometry, ConstraintIsNegativeWheneverTheSpherePenetrates) {
  // 1. The default hand's thumb metacarpal: a sphere of 5 mm sunk 10 um into the
  //    CMC ball (D) where it stands out most beyond the side.
  const frusta_hand_def def = frusta_default_hand_def();
  const double r1 = def.joint_radius[0][0], r2 = def.joint_radius[0][1];
  const double length = def.segment_length[0][0];
  const double side = std::hypot(length, r1 - r2);
  const double sin_a = (r1 - r2) / side, cos_a = length / side;
  const vec3 d(length, 0.0, 0.0), e(0.0, 0.0, 0.0);
  const vec3 n(-sin_a, cos_a, 0.0);  // the side's outward normal
  const double radius = 0.005, depth = 10e-6;
  const frusta_segment thumb = make_segment(d, e, r1, r2);
  const frusta_sphere sunk = make_sphere(d + (r1 + radius - depth) * n, radius);
  const frusta_contact_query q = query(thumb, sunk);
  EXPECT_NEAR(q.distance, -depth, 1e-12);
  EXPECT_EQ(q.feature, FRUSTA_FEATURE_PROXIMAL);
  for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
    const frusta_constraint g = constraint(thumb, sunk, form);
    EXPECT_LT(g.value, 0.0) << "form " << form << ": a sphere 10 um inside the thumb's CMC "
                            << "ball is reported clear (feature " << g.feature << ")";
  }
  // 2. A segment narrowing towards D (valid: "any radii >= 0"): 1 mm inside ball E.
  const frusta_segment cone = make_segment(vec3(0.03, 0, 0), vec3(0, 0, 0), 0.0, 0.015);
  const double s2 = std::hypot(0.03, 0.015);
  const vec3 n2(0.015 / s2, 0.03 / s2, 0.0);
  const frusta_sphere into = make_sphere((0.015 + 0.005 - 0.001) * n2, 0.005);
  EXPECT_NEAR(query(cone, into).distance, -0.001, 1e-12);
  for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
    const frusta_constraint g = constraint(cone, into, form);
    EXPECT_LT(g.value, 0.0) << "form " << form << ": a sphere 1 mm inside ball E is reported "
                            << "clear (feature " << g.feature << ", g " << g.value << ")";
  }
}

// The analytic gradients equal central differences of the value through the ABI.
TEST_F(capiGeometry, ConstraintGradientsMatchFiniteDifferences) {
  std::mt19937_64 rng(28);
  constexpr double h = 1e-7;
  int checked = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Case c = random_case(rng, trial);
    const vec3 d = v(c.segment.proximal), e = v(c.segment.distal), o = v(c.sphere.center);
    if (glm::distance(d, e) < 0.01) continue;
    // |O - axis| and |O - ball centre| have kinks where they vanish: no derivative there
    const vec3 u = glm::normalize(d - e);
    const double radial = glm::length((o - e) - glm::dot(o - e, u) * u);
    if (radial < 1e-4 || glm::distance(o, d) < 1e-4 || glm::distance(o, e) < 1e-4) continue;
    for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
      const frusta_constraint g = constraint(c.segment, c.sphere, form);
      // which point, coordinate; 0: D, 1: E, 2: O
      for (int which = 0; which < 3; ++which)
        for (int k = 0; k < 3; ++k) {
          Case plus = c, minus = c;
          double* p = which == 0   ? plus.segment.proximal
                      : which == 1 ? plus.segment.distal
                                   : plus.sphere.center;
          double* m = which == 0   ? minus.segment.proximal
                      : which == 1 ? minus.segment.distal
                                   : minus.sphere.center;
          p[k] += h;
          m[k] -= h;
          const frusta_constraint gp = constraint(plus.segment, plus.sphere, form);
          const frusta_constraint gm = constraint(minus.segment, minus.sphere, form);
          if (gp.feature != g.feature || gm.feature != g.feature) continue;  // a switch
          const double numeric = (gp.value - gm.value) / (2.0 * h);
          const double analytic = which == 0   ? g.grad_proximal[k]
                                  : which == 1 ? g.grad_distal[k]
                                               : g.grad_center[k];
          EXPECT_NEAR(analytic, numeric, 1e-6 * (1.0 + std::fabs(numeric)))
              << "trial " << trial << " form " << form << " feature " << g.feature
              << (which == 0   ? " dg/dD"
                  : which == 1 ? " dg/dE"
                               : " dg/dO")
              << "[" << k << "]";
          ++checked;
        }
    }
  }
  EXPECT_GT(checked, 5000);
}

// Translating everything moves nothing relative: dg/dD + dg/dE + dg/dO = 0.
TEST_F(capiGeometry, ConstraintIsTranslationInvariant) {
  std::mt19937_64 rng(29);
  for (int trial = 0; trial < 1000; ++trial) {
    const Case c = random_case(rng, trial);
    for (int form : {FRUSTA_CONSTRAINT_SQUARED, FRUSTA_CONSTRAINT_DISTANCE}) {
      const frusta_constraint g = constraint(c.segment, c.sphere, form);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(g.grad_proximal[k] + g.grad_distal[k] + g.grad_center[k], 0.0, 1e-12)
            << "trial " << trial << " form " << form;
    }
  }
}

}  // namespace
}  // namespace frusta
