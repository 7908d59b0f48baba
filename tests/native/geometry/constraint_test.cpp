// SPDX-License-Identifier: MIT
// Non-penetration constraints: hand-computed values, the endpoint rule, and every
// analytic gradient against central finite differences over a million seeded cases.
#include "geometry/constraint.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include <glm/geometric.hpp>

#include "geometry/exact_distance.h"
#include "geometry/segment_frame.h"
#include "property_support.h"
#include "geometry_fixtures.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using property::format;
using scenes::Case;
using scenes::Family;

constexpr ConstraintForm kSquared = ConstraintForm::kSquared;
constexpr ConstraintForm kDistance = ConstraintForm::kDistance;

Segment cylinder() { return {{0.04, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.01, 0.01}; }

TEST(EndpointRule, SideWhileTheTouchingPointIsBetweenTheEnds) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  // R = 1 cm: the touching point lies R sin(alpha) = 2.195 mm towards D from the centre
  const double shift = 0.01 * 9.0 / 41.0;
  EXPECT_EQ(endpoint_rule(f, {{-shift + 1e-6, 0.02, 0.0}, 0.01}), Feature::kSide);
  EXPECT_EQ(endpoint_rule(f, {{-shift - 1e-6, 0.02, 0.0}, 0.01}), Feature::kDistalBall);
  EXPECT_EQ(endpoint_rule(f, {{0.04 - shift - 1e-6, 0.02, 0.0}, 0.01}), Feature::kSide);
  EXPECT_EQ(endpoint_rule(f, {{0.04 - shift + 1e-6, 0.02, 0.0}, 0.01}), Feature::kProximalBall);
  // a cylinder has no shift: the band is exactly [0, L]
  const SegmentFrame cyl = make_segment_frame(cylinder());
  EXPECT_EQ(endpoint_rule(cyl, {{-1e-9, 0.02, 0.0}, 0.01}), Feature::kDistalBall);
  EXPECT_EQ(endpoint_rule(cyl, {{1e-9, 0.02, 0.0}, 0.01}), Feature::kSide);
}

TEST(EndpointRule, DegenerateSegmentIsItsLargerBall) {
  EXPECT_EQ(endpoint_rule(make_segment_frame({{}, {}, 0.01, 0.005}), {{0.1, 0.0, 0.0}, 0.01}),
            Feature::kProximalBall);
  EXPECT_EQ(endpoint_rule(make_segment_frame({{}, {}, 0.004, 0.005}), {{0.1, 0.0, 0.0}, 0.01}),
            Feature::kDistalBall);
}

TEST(SideConstraint, CylinderValuesAndGradients) {
  const SegmentFrame f = make_segment_frame(cylinder());
  const Sphere s{{0.02, 0.03, 0.0}, 0.005};
  const Constraint d = side_constraint(f, s, kDistance);
  EXPECT_NEAR(d.value, 0.015, 1e-15);
  expect_vec_near(d.grad_center, {0.0, 1.0, 0.0}, 1e-15);
  // halfway along: moving D or E up by h lowers the axis under O by h / 2
  expect_vec_near(d.grad_proximal, {0.0, -0.5, 0.0}, 1e-15);
  expect_vec_near(d.grad_distal, {0.0, -0.5, 0.0}, 1e-15);
  const Constraint q = side_constraint(f, s, kSquared);
  EXPECT_NEAR(q.value, 0.03 * 0.03 - 0.015 * 0.015, 1e-16);
  expect_vec_near(q.grad_center, {0.0, 0.06, 0.0}, 1e-15);
  expect_vec_near(q.grad_proximal, {0.0, -0.03, 0.0}, 1e-15);
  expect_vec_near(q.grad_distal, {0.0, -0.03, 0.0}, 1e-15);
}

TEST(SideConstraint, ConeDistanceFormIsTheGapToTheSide) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const vec3 outward(-9.0 / 41.0, 40.0 / 41.0, 0.0);
  const Sphere s{vec3(0.02, 0.0075, 0.0) + 0.015 * outward, 0.01};  // gap 5 mm
  const Constraint d = side_constraint(f, s, kDistance);
  EXPECT_NEAR(d.value, 0.005, 1e-15);
  expect_vec_near(d.grad_center, outward, 1e-15);  // the side's unit normal
  const Constraint q = side_constraint(f, s, kSquared);
  const double reach = 0.01 * 41.0 / 40.0 + 0.003 + s.center.x * 9.0 / 40.0;  // |OC|_T
  EXPECT_NEAR(q.value, s.center.y * s.center.y - reach * reach, 1e-16);
  EXPECT_GT(q.value, 0.0);
}

TEST(BallConstraint, ValuesAndGradientsOfBothBalls) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const Sphere s{{-0.015, 0.0, 0.0}, 0.01};
  const Constraint d = ball_constraint(f, Feature::kDistalBall, s, kDistance);
  EXPECT_EQ(d.feature, Feature::kDistalBall);
  EXPECT_NEAR(d.value, 0.002, 1e-15);
  expect_vec_near(d.grad_center, {-1.0, 0.0, 0.0}, 1e-15);
  expect_vec_near(d.grad_distal, {1.0, 0.0, 0.0}, 1e-15);
  expect_vec_near(d.grad_proximal, {0.0, 0.0, 0.0}, 0.0);
  const Constraint q = ball_constraint(f, Feature::kDistalBall, s, kSquared);
  EXPECT_NEAR(q.value, 0.015 * 0.015 - 0.013 * 0.013, 1e-16);
  expect_vec_near(q.grad_center, {-0.03, 0.0, 0.0}, 1e-15);
  const Constraint p = ball_constraint(f, Feature::kProximalBall, s, kDistance);
  EXPECT_NEAR(p.value, 0.055 - 0.012 - 0.01, 1e-15);
  expect_vec_near(p.grad_proximal, {1.0, 0.0, 0.0}, 1e-15);
  expect_vec_near(p.grad_distal, {0.0, 0.0, 0.0}, 0.0);
}

TEST(BallConstraint, ConcentricSphereGetsAUnitSubgradient) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const Constraint d = ball_constraint(f, Feature::kDistalBall, {{0.0, 0.0, 0.0}, 0.001}, kDistance);
  EXPECT_NEAR(d.value, -0.004, 1e-15);
  EXPECT_NEAR(glm::length(d.grad_center), 1.0, 1e-15);
}

TEST(ContactConstraint, FollowsTheEndpointRule) {
  const SegmentFrame f = make_segment_frame(cone_9_40_41());
  const Sphere tip{{-0.012, 0.001, 0.0}, 0.01};  // penetrates the tip ball, eq. 5 misses it
  const Constraint c = contact_constraint(f, tip, kSquared);
  EXPECT_EQ(c.feature, Feature::kDistalBall);
  EXPECT_NEAR(c.value, 0.012 * 0.012 + 0.001 * 0.001 - 0.013 * 0.013, 1e-16);
  EXPECT_LT(c.value, 0.0);
  const Sphere side{{0.02, 0.02, 0.0}, 0.005};
  EXPECT_EQ(contact_constraint(f, side, kDistance).feature, Feature::kSide);
  EXPECT_EQ(contact_constraint(f, side, kDistance).value,
            side_constraint(f, side, kDistance).value);
}

// ---------------------------------------------------------------------------------
// (d) gradients vs central differences.

enum Fn : int {
  kSideSquared, kSideDistance, kDistalSquared, kDistalDistance,
  kProximalSquared, kProximalDistance, kContactSquared, kContactDistance, kFnCount
};
const char* const kFnNames[kFnCount] = {"side/squared",     "side/distance",
                                        "distal/squared",   "distal/distance",
                                        "proximal/squared", "proximal/distance",
                                        "contact/squared",  "contact/distance"};

Constraint evaluate(int fn, const SegmentFrame& f, const Sphere& s) {
  const ConstraintForm form = fn % 2 == 0 ? kSquared : kDistance;
  switch (fn / 2) {
    case 0: return side_constraint(f, s, form);
    case 1: return ball_constraint(f, Feature::kDistalBall, s, form);
    case 2: return ball_constraint(f, Feature::kProximalBall, s, form);
    default: return contact_constraint(f, s, form);
  }
}

double component(const Constraint& g, int var) {
  const vec3& v = var < 3 ? g.grad_proximal : var < 6 ? g.grad_distal : g.grad_center;
  return v[var % 3];
}

double norm(const vec3& v) { return std::sqrt(glm::dot(v, v)); }

// Smoothness length l (the length over which the function bends; picks the step) and
// the magnitude M of the terms it sums (its rounding is ~ eps M), per function and case.
struct Scales {
  double length, magnitude;
};

Scales scales_of(int fn, Feature feature, const SegmentFrame& f, const Sphere& s) {
  const AxialSplit sp = split_axial(f, s.center);
  const double a = sp.axial, q = sp.radial_length, w = norm(sp.w), R = s.radius;
  if (fn >= kContactSquared) {
    const int base = feature == Feature::kSide ? 0 : feature == Feature::kDistalBall ? 2 : 4;
    return scales_of(base + (fn % 2), feature, f, s);
  }
  if (fn <= kSideDistance) {
    const double L = f.length;
    if (fn == kSideSquared) {
      // the terms of |OC|_T = R / cos + r2 + a tan can be large and cancel (short segments)
      const double reach = R / f.cos_alpha + f.r_distal + std::fabs(a * f.slope);
      return {L, q * q + reach * reach + w * w};
    }
    // near the axis the radial direction turns fast: with D moved by h the axis under O
    // moves by h |a| / L
    const double l = std::min({L, q, q * L / (std::fabs(a) + L)});
    return {l, w + f.r_distal + f.r_proximal + R + std::fabs(a * f.slope) * f.cos_alpha};
  }
  const bool distal = fn <= kDistalDistance;
  const double reach = R + (distal ? f.r_distal : f.r_proximal);
  const double d = norm(s.center - (distal ? f.distal : f.proximal));
  if (fn % 2 == 0) return {d + reach, (d + reach) * (d + reach)};  // quadratic: no truncation
  return {d, d + reach};
}

// Central difference of function fn in coordinate var (0-2 D, 3-5 E, 6-8 O) with step
// h; the steps actually taken are measured, so rounding of x +- h costs nothing.
struct Central {
  double derivative;
  bool switched;  // the feature differs from `feature` at a stencil point
};

// The case with coordinate var (0-2 D, 3-5 E, 6-8 O) moved by step, and the step taken.
struct Perturbed {
  Segment segment;
  Sphere sphere;
  double actual;
};

Perturbed perturb(const Case& c, int var, double step) {
  Perturbed p{c.segment, c.sphere, 0.0};
  double& x = var < 3 ? p.segment.proximal[var] : var < 6 ? p.segment.distal[var - 3] : p.sphere.center[var - 6];
  const double x0 = x;
  x = x0 + step;
  p.actual = std::fabs(x - x0);
  return p;
}

Central central(int fn, int var, double h, const Case& c, const SegmentFrame& f0, Feature feature) {
  double value[2], actual[2];
  bool switched = false;
  for (int point = 0; point < 2; ++point) {
    const Perturbed p = perturb(c, var, point == 0 ? h : -h);
    actual[point] = p.actual;
    const Constraint g = evaluate(fn, var < 6 ? make_segment_frame(p.segment) : f0, p.sphere);
    value[point] = g.value;
    switched = switched || g.feature != feature;
  }
  return {(value[0] - value[1]) / (actual[0] + actual[1]), switched};
}

// (d) Every analytic gradient of the functions in `fns` against central differences.
// Step h = 4e-6 of the shortest smoothness length (at least 32 ulps of the largest
// coordinate). Allowed error: 1000 times the rounding, ~ eps M / h, plus, where that is
// exceeded, 6 times the truncation error measured from a second step 2h (the error of
// D(h) is about |D(2h) - D(h)| / 3 since it is O(h^2)). Non-smooth points are skipped
// and counted: the distance forms on the axis or concentric with a ball, a feature
// switch of contact_constraint within the step, the side of a degenerate segment.
void check_gradients(const char* property_name, std::initializer_list<int> fns, std::uint64_t seed) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(seed);
  property::PropertyLog log(property_name);
  std::array<double, kFnCount> worst{};  // max |fd - analytic| / tolerance
  std::array<std::uint64_t, kFnCount> compared{}, second_step{};
  std::array<std::string, kFnCount> worst_case;
  constexpr double kEps = DBL_EPSILON;

  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f0 = make_segment_frame(c.segment);
    const AxialSplit sp = split_axial(f0, c.sphere.center);
    const double w = norm(sp.w);

    std::array<Constraint, kFnCount> an;
    std::array<Scales, kFnCount> sc;
    std::array<bool, kFnCount> use{};
    for (int fn : fns) {
      if (fn <= kSideDistance && f0.degenerate) {
        log.skip("side: degenerate segment", c);
        continue;
      }
      an[fn] = evaluate(fn, f0, c.sphere);
      sc[fn] = scales_of(fn, an[fn].feature, f0, c.sphere);
      use[fn] = true;
      if (fn % 2 == 1) {  // distance forms: kinks on the axis and at a ball's centre
        const bool side = fn <= kSideDistance || (fn >= kContactSquared && an[fn].feature == Feature::kSide);
        const double kink = side ? sp.radial_length : sc[fn].length;
        if (!(kink > 1e-7 * (w + f0.length))) {
          use[fn] = false;
          log.skip(side ? "distance form on the axis (q ~ 0)" : "distance form concentric with a ball", c);
        }
      }
    }
    double l = HUGE_VAL;
    for (int fn : fns)
      if (use[fn]) l = std::min(l, sc[fn].length);
    if (!(l < HUGE_VAL) || !(l > 0.0)) continue;
    const double big = property::world_scale(c);
    const double h = std::max(4e-6 * l, 32.0 * (std::nextafter(big, HUGE_VAL) - big));

    // first pass: all functions share each perturbed frame
    std::array<std::array<double, 9>, kFnCount> fd{};
    std::array<bool, kFnCount> switched{};
    for (int var = 0; var < 9; ++var) {
      double value[2][kFnCount] = {};
      double actual[2];
      for (int point = 0; point < 2; ++point) {
        const Perturbed p = perturb(c, var, point == 0 ? h : -h);
        const Sphere& sph = p.sphere;
        actual[point] = p.actual;
        const SegmentFrame f = var < 6 ? make_segment_frame(p.segment) : f0;
        for (int fn : fns) {
          if (!use[fn]) continue;
          // a ball's constraint does not read the other end: its derivative there is 0
          if ((fn == kDistalSquared || fn == kDistalDistance) && var < 3) continue;
          if ((fn == kProximalSquared || fn == kProximalDistance) && var >= 3 && var < 6) continue;
          const Constraint g = evaluate(fn, f, sph);
          value[point][fn] = g.value;
          if (g.feature != an[fn].feature) switched[fn] = true;
        }
      }
      for (int fn : fns)
        if (use[fn]) fd[fn][var] = (value[0][fn] - value[1][fn]) / (actual[0] + actual[1]);
    }

    for (int fn : fns) {
      if (!use[fn]) continue;
      if (switched[fn]) {
        log.skip("contact: feature switch within the step", c);
        continue;
      }
      ++compared[fn];
      const double rounding = 1e3 * kEps * sc[fn].magnitude / h;
      bool used_second = false;
      for (int var = 0; var < 9; ++var) {
        const double analytic = component(an[fn], var);
        const double err = std::fabs(fd[fn][var] - analytic);
        double tol = rounding;
        if (err > tol) {  // second opinion: measure the truncation error
          const Central twice = central(fn, var, 2.0 * h, c, f0, an[fn].feature);
          used_second = true;
          if (twice.switched) {
            log.skip("contact: feature switch within the step", c);
            continue;
          }
          tol += 2.0 * std::fabs(twice.derivative - fd[fn][var]);
        }
        if (err / tol > worst[fn]) {
          worst[fn] = err / tol;
          worst_case[fn] = scenes::describe(c) + format(" var=%d analytic=%.17g central=%.17g",
                                                        var, analytic, fd[fn][var]);
        }
        log.check(err <= tol, kFnNames[fn], c, [&] {
          return format("d/d%s[%d]: analytic=%.17g central=%.17g tol=%.3g h=%.3g feature=%d",
                        var < 3 ? "D" : var < 6 ? "E" : "O", var % 3, analytic, fd[fn][var],
                        tol, h, int(an[fn].feature));
        });
      }
      if (used_second) ++second_step[fn];
    }
  }
  log.report();
  for (int fn : fns) {
    std::printf("[ gradients ] %-18s compared on %8llu cases (%llu needed the 2h step), worst "
                "error / tolerance %.3g\n    at %s\n",
                kFnNames[fn], static_cast<unsigned long long>(compared[fn]),
                static_cast<unsigned long long>(second_step[fn]), worst[fn], worst_case[fn].c_str());
    property::record(std::string("worst_") + kFnNames[fn], worst[fn]);
    EXPECT_GT(compared[fn], n / 2) << kFnNames[fn];
  }
}

TEST(ConstraintProperty, SideAndContactGradientsMatchCentralDifferences) {
  check_gradients("side and contact gradients",
                  {kSideSquared, kSideDistance, kContactSquared, kContactDistance},
                  scenes::kPropertySeed + 4);
}

TEST(ConstraintProperty, BallGradientsMatchCentralDifferences) {
  check_gradients("ball gradients",
                  {kDistalSquared, kDistalDistance, kProximalSquared, kProximalDistance},
                  scenes::kPropertySeed + 4);
}

// Values: the forms agree in sign, the distance form is the exact gap where the side
// is nearest, balls are |O - X| - r - R, contact_constraint is the rule's function.
TEST(ConstraintProperty, ValuesAgreeWithTheExactReferenceAndEachOther) {
  const std::uint64_t n = scenes::property_case_count();
  scenes::CaseGenerator gen(scenes::kPropertySeed + 5);
  property::PropertyLog log("constraint values");
  std::uint64_t side_exact = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const Case c = gen.next();
    log.seen(c);
    const SegmentFrame f = make_segment_frame(c.segment);
    const double eps = property::kRoundingUlps * property::case_scale(c);
    const Sphere& s = c.sphere;
    for (Feature ball : {Feature::kDistalBall, Feature::kProximalBall}) {
      const bool distal = ball == Feature::kDistalBall;
      const vec3 x = distal ? c.segment.distal : c.segment.proximal;
      const double r = distal ? c.segment.distal_radius : c.segment.proximal_radius;
      const double dist = norm(s.center - x);
      const Constraint d = ball_constraint(f, ball, s, kDistance);
      const Constraint q = ball_constraint(f, ball, s, kSquared);
      log.check(std::fabs(d.value - (dist - r - s.radius)) <= eps, "ball distance form", c,
                [&] { return format("value=%.17g", d.value); });
      log.check(std::fabs(q.value - (dist * dist - (r + s.radius) * (r + s.radius))) <=
                    4.0 * eps * property::case_scale(c),
                "ball squared form", c, [&] { return format("value=%.17g", q.value); });
      log.check(std::fabs(norm(d.grad_center) - 1.0) <= 1e-12, "ball distance gradient unit", c,
                [&] { return std::string(); });
    }
    const double exact = exact_distance(f, s);
    for (ConstraintForm form : {kSquared, kDistance}) {
      const Constraint g = contact_constraint(f, s, form);
      const Feature rule = endpoint_rule(f, s);
      const Constraint e = g.feature == Feature::kSide ? side_constraint(f, s, form)
                                                       : ball_constraint(f, g.feature, s, form);
      // the rule's feature, or an end ball where it bulges past that
      log.check((g.feature == rule || g.feature != Feature::kSide) && g.value == e.value &&
                    g.grad_center == e.grad_center && g.grad_proximal == e.grad_proximal &&
                    g.grad_distal == e.grad_distal,
                "contact_constraint is the rule's or the bulging ball's constraint", c,
                [&] { return std::string(); });
      // the point of the rule: g < 0 exactly when the sphere overlaps the solid
      if (std::fabs(exact) > eps)
        log.check((g.value < 0.0) == (exact < 0.0), "constraint sign is the overlap's", c,
                  [&] { return format("g=%.17g exact=%.17g", g.value, exact); });
    }
    if (f.degenerate) continue;
    const Constraint d = side_constraint(f, s, kDistance);
    const Constraint q = side_constraint(f, s, kSquared);
    const AxialSplit sp = split_axial(f, s.center);
    const double reach = s.radius / f.cos_alpha + f.r_distal + sp.axial * f.slope;
    if (reach >= 0.0 && std::fabs(d.value) > eps)
      log.check((d.value > 0.0) == (q.value > 0.0), "squared and distance forms agree in sign", c,
                [&] { return format("distance=%.17g squared=%.17g", d.value, q.value); });
    if (sp.radial_length > 0.0)
      log.check(std::fabs(norm(d.grad_center) - 1.0) <= 1e-9, "side distance gradient wrt O is unit",
                c, [&] { return format("|grad|=%.17g q=%.3g", norm(d.grad_center), sp.radial_length); });
    // where the nearest point is inside the side (not at a rim or a cone's apex, which
    // tie with a ball) the side line's distance is the exact gap
    const Proximity p = exact_proximity(f, s);
    const double along = glm::dot(p.hand_point - f.distal, f.axis);
    if (p.feature == Feature::kSide && p.distance > 0.0 && along > 1e-9 * f.length &&
        along < (1.0 - 1e-9) * f.length) {
      ++side_exact;
      log.check(std::fabs(d.value - p.distance) <= eps, "distance form == exact gap (side nearest)",
                c, [&] { return format("distance form=%.17g exact=%.17g", d.value, p.distance); });
    }
  }
  log.report();
  EXPECT_GT(side_exact, n / 10);
}

}  // namespace
}  // namespace frusta
