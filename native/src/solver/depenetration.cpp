// SPDX-License-Identifier: MIT
#include "solver/depenetration.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

namespace {

// How deep the hand at `pose` sinks into its deepest leaf: 0 when it touches none.
double hand_depth(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, CandidateSet& scratch) {
  detect_candidates(model, reach, pose, objects, object_count, 0.0, -1, scratch);
  double depth = 0.0;
  for (int body = 0; body < kBodyCount; ++body)
    depth = std::max(depth, -body_clearance(model, pose, scratch, body));
  return depth;
}

}  // namespace

bool hand_is_free(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, double tolerance,
                  CandidateSet& scratch) {
  return hand_depth(model, reach, pose, objects, object_count, scratch) <= tolerance;
}

bool depenetrate(const HandModel& model, const HandReach& reach, const SolverObject* objects,
                 int32_t object_count, double tolerance, CandidateSet& scratch, HandState& state) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  const double depth = hand_depth(model, reach, pose, objects, object_count, scratch);
  if (depth <= tolerance) return true;
  // nothing free lies further than the hand's and every object's extent
  double far = 2.0 * reach.hand;
  for (int32_t o = 0; o < object_count; ++o)
    if (!objects[o].tree->empty()) far += 2.0 * object_bound(objects[o]).radius;
  const double stride = std::max(0.002, far / 256.0);

  HandState trial = state;
  auto depth_at = [&](const vec3& direction, double t) {
    trial.palm_position = state.palm_position + t * direction;
    forward_kinematics(model, trial, pose);
    return hand_depth(model, reach, pose, objects, object_count, scratch);
  };
  constexpr int kDirections = 26;  // a cube's faces, edges and corners
  vec3 directions[kDirections];
  int count = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x != 0 || y != 0 || z != 0) directions[count++] = glm::normalize(vec3(x, y, z));

  // Each ray marches out from the hand, nearest trial first across all rays, until one
  // is free; then the rays that could still beat it. A move by s changes how deep any
  // point sits in a leaf by s at most, so a placement `depth` deep is at least
  // depth - tolerance from any free one: the march jumps that far (never less than the
  // stride), and a hand 1.4 cm in costs a few trials a ray, not seven rings of them.
  // The first free trial of a ray is bisected down to the surface.
  constexpr double kPrecision = 1e-6;  // metres: far below any tolerance
  const double start = std::max(stride, depth - tolerance);
  double next[kDirections], inside[kDirections];
  std::fill(std::begin(next), std::end(next), start);
  std::fill(std::begin(inside), std::end(inside), 0.0);
  double best = far;
  vec3 best_direction(0.0);
  for (;;) {
    int ray = -1;
    for (int i = 0; i < kDirections; ++i)
      if (next[i] < best && (ray < 0 || next[i] < next[ray])) ray = i;
    if (ray < 0) break;
    const double t = next[ray];
    const double d = depth_at(directions[ray], t);
    if (d > tolerance) {
      inside[ray] = t;
      next[ray] = t + std::max(stride, d - tolerance);
      continue;
    }
    double low = inside[ray], high = t;
    while (high - low > kPrecision) {
      const double mid = 0.5 * (low + high);
      (depth_at(directions[ray], mid) <= tolerance ? high : low) = mid;
    }
    if (high < best) {
      best = high;
      best_direction = directions[ray];
    }
    next[ray] = INFINITY;  // this ray's nearest free placement is known
  }
  if (best_direction == vec3(0.0)) return false;
  state.palm_position += best * best_direction;
  return true;
}

}  // namespace frusta
