// SPDX-License-Identifier: MIT
// Random leaf sets for the sphere-tree tests: clouds, thin shells (a surface-fitted
// object) and duplicates, which stress the median split.
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

}  // namespace frusta::testing
