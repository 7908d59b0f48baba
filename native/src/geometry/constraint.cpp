// SPDX-License-Identifier: MIT
#include "geometry/constraint.h"

#include <initializer_list>

#include <glm/geometric.hpp>

namespace frusta {

Feature endpoint_rule(const SegmentFrame& frame, const Sphere& sphere) {
  if (frame.degenerate)
    return frame.r_proximal > frame.r_distal ? Feature::kProximalBall : Feature::kDistalBall;
  const double axial = glm::dot(sphere.center - frame.distal, frame.axis);
  const double shift = sphere.radius * frame.sin_alpha;
  if (axial < -shift) return Feature::kDistalBall;
  if (axial > frame.length - shift) return Feature::kProximalBall;
  return Feature::kSide;
}

Constraint side_constraint(const SegmentFrame& f, const Sphere& sphere, ConstraintForm form) {
  // notation of method.md: w = O - E, a axial, p radial with q = |p|, t = tan(alpha)
  const AxialSplit s = split_axial(f, sphere.center);
  const vec3& u = f.axis;
  const double a = s.axial, q = s.radial_length, L = f.length, R = sphere.radius;
  const double t = f.slope, c = f.cos_alpha, sn = f.sin_alpha, r2 = f.r_distal;

  Constraint g;
  g.feature = Feature::kSide;
  vec3 grad_w, grad_d;  // with respect to w = O - E and d = D - E
  if (form == ConstraintForm::kDistance) {
    const vec3 n = radial_direction(f, s);
    g.value = (q - r2 - a * t) * c - R;
    grad_w = c * n - sn * u;
    // c, s depend on L through t: dh/dt = -c^3 ((q - r2) t + a), dt/dd = -t u / L
    grad_d = (-(c * a + sn * q) * n + c * c * c * t * ((q - r2) * t + a) * u) / L;
  } else {
    const double reach = R / c + r2 + a * t;  // the seed's |OC|_T
    g.value = q * q - reach * reach;
    grad_w = 2.0 * s.radial - 2.0 * reach * t * u;
    // d(reach)/dt = R sin(alpha) + a
    grad_d = (-2.0 * a * s.radial - 2.0 * reach * (t * s.radial - (R * sn + a) * t * u)) / L;
  }
  g.grad_center = grad_w;
  g.grad_proximal = grad_d;
  g.grad_distal = -grad_w - grad_d;
  return g;
}

SphereConstraint sphere_constraint(const Sphere& hand, const Sphere& object, ConstraintForm form,
                                   const vec3& fallback) {
  const vec3 d = hand.center - object.center;
  const double reach = hand.radius + object.radius;
  if (form == ConstraintForm::kDistance) {
    const double n = glm::length(d);
    // concentric: any direction is a subgradient; the caller's keeps it deterministic
    return {n - reach, n > 0.0 ? d / n : fallback};
  }
  return {glm::dot(d, d) - reach * reach, 2.0 * d};
}

Constraint ball_constraint(const SegmentFrame& frame, Feature ball, const Sphere& sphere,
                           ConstraintForm form) {
  const bool distal = ball == Feature::kDistalBall;
  const Sphere hand_ball{distal ? frame.distal : frame.proximal,
                         distal ? frame.r_distal : frame.r_proximal};
  const SphereConstraint c =
      sphere_constraint(hand_ball, sphere, form, distal ? frame.axis : -frame.axis);
  Constraint g;
  g.feature = ball;
  g.value = c.value;
  g.grad_center = -c.grad_hand;
  (distal ? g.grad_distal : g.grad_proximal) = c.grad_hand;
  return g;
}

namespace {

Constraint feature_constraint(const SegmentFrame& frame, Feature feature, const Sphere& sphere,
                              ConstraintForm form) {
  return feature == Feature::kSide ? side_constraint(frame, sphere, form)
                                   : ball_constraint(frame, feature, sphere, form);
}

}  // namespace

Constraint contact_constraint(const SegmentFrame& frame, const Sphere& sphere,
                              ConstraintForm form) {
  const Feature rule = endpoint_rule(frame, sphere);
  // A ball bulges past the side's line at its rim (the line is not tangent to it), and
  // the larger ball past the whole of a short segment, while the rule still names the
  // side or the other ball; the union's constraint is the tightest of the three. Compare
  // in the distance form, whose values are all signed distances, then evaluate the
  // winner in the form asked for.
  // (a ball's gradient made only where it wins: most rows' balls lose)
  Constraint tightest = feature_constraint(frame, rule, sphere, ConstraintForm::kDistance);
  for (Feature ball : {Feature::kDistalBall, Feature::kProximalBall}) {
    if (ball == rule) continue;
    const bool distal = ball == Feature::kDistalBall;
    const double value = glm::length((distal ? frame.distal : frame.proximal) - sphere.center) -
                         ((distal ? frame.r_distal : frame.r_proximal) + sphere.radius);
    if (value < tightest.value)
      tightest = ball_constraint(frame, ball, sphere, ConstraintForm::kDistance);
  }
  if (form == ConstraintForm::kDistance) return tightest;
  return feature_constraint(frame, tightest.feature, sphere, form);
}

}  // namespace frusta
