// SPDX-License-Identifier: MIT
#include "forces/grasp.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace frusta {

double squeeze_load(const BodyPushes& pushes, double mu) {
  std::array<double, kBodyCount> size{};
  for (int b = 0; b < kBodyCount; ++b) size[b] = glm::length(pushes[b]);
  double best = 0.0;
  for (int a = 0; a < kBodyCount; ++a) {
    if (!(size[a] > 0.0)) continue;
    for (int b = a + 1; b < kBodyCount; ++b) {
      if (!(size[b] > 0.0)) continue;
      const double cos = glm::dot(pushes[a], pushes[b]) / (size[a] * size[b]);
      if (cos > kOppositionCos) continue;
      best = std::max(best, 2.0 * mu * std::min(size[a], size[b]) * -cos);
    }
  }
  return best;
}

}  // namespace frusta
