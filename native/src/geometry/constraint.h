// SPDX-License-Identifier: MIT
// Non-penetration constraints g >= 0 between a segment solid and a sphere, with
// analytic gradients with respect to D, E and the sphere's centre, for the solver
// to chain through the hand's Jacobians (seed eqs. 8-10).
#pragma once

#include "geometry/segment_frame.h"
#include "geometry/types.h"

namespace frusta {

enum class ConstraintForm : int {
  kSquared = 0,   // seed eq. 9: |OC|^2 - (R / cos(alpha) + r(k))^2
  kDistance = 1,  // (|OC| - r(k)) cos(alpha) - R: same zero set, unit gradient in O
};

struct Constraint {
  double value = 0.0;
  vec3 grad_proximal{0.0};  // dg/dD
  vec3 grad_distal{0.0};    // dg/dE
  vec3 grad_center{0.0};    // dg/dO
  Feature feature = Feature::kSide;
};

// The endpoint rule (seed eqs. 10-11, generalised to both ends): the side while the
// sphere's touching point on the side lies between E and D, else the ball at the end
// it passed. A degenerate segment is its larger ball.
Feature endpoint_rule(const SegmentFrame& frame, const Sphere& sphere);

// The lateral side's constraint (undefined for a degenerate segment).
Constraint side_constraint(const SegmentFrame& frame, const Sphere& sphere, ConstraintForm form);
// Two spheres, a hand sphere (a palm sphere, a joint ball) against an object sphere,
// with the gradient with respect to the hand sphere's centre; `fallback` is that
// gradient's direction when the centres coincide.
struct SphereConstraint {
  double value = 0.0;
  vec3 grad_hand{0.0};
};
SphereConstraint sphere_constraint(const Sphere& hand, const Sphere& object, ConstraintForm form,
                                   const vec3& fallback);

// The constraint of the ball at E (kDistalBall) or at D (kProximalBall).
Constraint ball_constraint(const SegmentFrame& frame, Feature ball, const Sphere& sphere,
                           ConstraintForm form);
// The constraint of the feature endpoint_rule picks, or of an end ball where it bulges
// past that feature, so g < 0 exactly when the sphere overlaps the solid.
Constraint contact_constraint(const SegmentFrame& frame, const Sphere& sphere,
                              ConstraintForm form);

}  // namespace frusta
