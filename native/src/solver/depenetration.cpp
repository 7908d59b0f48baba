// SPDX-License-Identifier: MIT
#include "solver/depenetration.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

bool hand_is_free(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, double tolerance,
                  CandidateSet& scratch) {
  detect_candidates(model, reach, pose, objects, object_count, 0.0, -1, scratch);
  for (int body = 0; body < kBodyCount; ++body)
    if (body_clearance(model, pose, scratch, body) < -tolerance) return false;
  return true;
}

bool depenetrate(const HandModel& model, const HandReach& reach, const SolverObject* objects,
                 int32_t object_count, double tolerance, CandidateSet& scratch, HandState& state) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  if (hand_is_free(model, reach, pose, objects, object_count, tolerance, scratch)) return true;
  // nothing free lies further than the hand's and every object's extent
  double far = 2.0 * reach.hand;
  for (int32_t o = 0; o < object_count; ++o)
    if (!objects[o].tree->empty()) far += 2.0 * object_bound(objects[o]).radius;
  const double stride = std::max(0.002, far / 256.0);

  HandState trial = state;
  auto free_at = [&](const vec3& direction, double t) {
    trial.palm_position = state.palm_position + t * direction;
    forward_kinematics(model, trial, pose);
    return hand_is_free(model, reach, pose, objects, object_count, tolerance, scratch);
  };
  vec3 directions[26];
  int count = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) directions[count++] = glm::normalize(vec3(x, y, z));

  // march all directions out together, so the search stops at the first ring with a
  // free placement instead of running some rays out to `far` (a hand a few millimetres
  // in costs a few rings, not hundreds of checks); then bisect each free ray's step
  // down to the surface and keep the nearest
  constexpr double kPrecision = 1e-6;  // metres: far below any tolerance
  double best = far;
  vec3 best_direction(0.0);
  for (double t = stride; t < far && best_direction == vec3(0.0); t += stride) {
    for (const vec3& direction : directions) {
      if (!free_at(direction, t)) continue;
      double inside = t - stride, outside = t;
      while (outside - inside > kPrecision) {
        const double mid = 0.5 * (inside + outside);
        (free_at(direction, mid) ? outside : inside) = mid;
      }
      if (outside < best) {
        best = outside;
        best_direction = direction;
      }
    }
  }
  if (best_direction == vec3(0.0)) return false;
  state.palm_position += best * best_direction;
  return true;
}

}  // namespace frusta
