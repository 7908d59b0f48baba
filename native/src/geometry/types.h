// SPDX-License-Identifier: MIT
// Geometric primitives shared by every contact query. Double precision: the
// constraint gradients difference nearly equal lengths (see geometry_benchmark).
#pragma once

#include <glm/vec3.hpp>

namespace frusta {

using vec3 = glm::dvec3;

struct Sphere {
  vec3 center{0.0};
  double radius = 0.0;
};

// A frustum with a ball at each end; D (proximal) and E (distal) as in the seed.
struct Segment {
  vec3 proximal{0.0};  // D
  vec3 distal{0.0};    // E
  double proximal_radius = 0.0;  // r1
  double distal_radius = 0.0;    // r2
};

// Which part of a segment solid a query is about.
enum class Feature : int { kSide = 0, kDistalBall = 1, kProximalBall = 2 };

}  // namespace frusta
