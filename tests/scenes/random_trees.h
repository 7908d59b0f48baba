// SPDX-License-Identifier: MIT
// Random leaf sets for the sphere-tree tests: clouds, thin shells (a surface-fitted
// object) and duplicates, which stress the median split; and a large rough plate.
#pragma once

#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "geometry/types.h"

namespace frusta::testing {

inline std::vector<Sphere> random_leaves(std::mt19937_64& rng, int count, int kind) {
  std::uniform_real_distribution<double> u(-0.1, 0.1), radius(0.0005, 0.01);
  std::normal_distribution<double> g;
  std::vector<Sphere> leaves;
  for (int i = 0; i < count; ++i) {
    vec3 c(u(rng), u(rng), u(rng));
    if (kind == 1) c = 0.08 * glm::normalize(vec3(g(rng), g(rng), g(rng)));  // a shell
    if (kind == 2 && i % 3 == 0 && !leaves.empty()) c = leaves.back().center;  // duplicates
    leaves.push_back({c, kind == 3 ? 0.0 : radius(rng)});
  }
  return leaves;
}

// A plate of nx * ny leaves in the z = 0 plane around the origin, `spacing` apart, each
// centre jittered by up to a tenth of the spacing (z too: a rough surface) and each
// radius by up to a tenth of `radius`: a tree far larger than any baked object that a
// hand can lie on (the hostile ABI test's 10^6 leaves), made without baking.
inline std::vector<Sphere> plate_leaves(std::mt19937_64& rng, int nx, int ny, double spacing,
                                        double radius) {
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  std::vector<Sphere> leaves;
  leaves.reserve(static_cast<size_t>(nx) * static_cast<size_t>(ny));
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const vec3 c((i - 0.5 * (nx - 1) + jitter(rng)) * spacing,
                   (j - 0.5 * (ny - 1) + jitter(rng)) * spacing, jitter(rng) * spacing);
      leaves.push_back({c, radius * (1.0 + jitter(rng))});
    }
  }
  return leaves;
}

}  // namespace frusta::testing
