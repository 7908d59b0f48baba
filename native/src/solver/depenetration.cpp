// SPDX-License-Identifier: MIT
#include "solver/depenetration.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta {

namespace {

// How deep the hand at `pose` sinks into its deepest leaf (or node where `cut` stops): 0
// when it touches none.
double hand_depth(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, TreeCut cut,
                  CandidateSet& scratch) {
  detect_candidates(model, reach, pose, objects, object_count, 0.0, cut, scratch);
  double depth = 0.0;
  for (int body = 0; body < kBodyCount; ++body)
    depth = std::max(depth, -body_clearance(model, pose, scratch, body));
  return depth;
}

vec3 direction(int ray) {
  // the rays in the order x, y, z over -1..1, the centre skipped
  const int index = ray < 13 ? ray : ray + 1;
  return glm::normalize(vec3(index / 9 - 1, index / 3 % 3 - 1, index % 3 - 1));
}

constexpr double kPrecision = 1e-6;  // metres: far below any tolerance

}  // namespace

bool hand_is_free(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, double tolerance,
                  TreeCut cut, CandidateSet& scratch) {
  return hand_depth(model, reach, pose, objects, object_count, cut, scratch) <= tolerance;
}

double PlacementSearch::depth_at(const HandModel& model, const HandReach& reach,
                                 const SolverObject* objects, int32_t object_count, TreeCut cut,
                                 CandidateSet& scratch, const HandState& state, int ray, double t) {
  HandState trial = state;
  trial.palm_position = state.palm_position + t * direction(ray);
  HandPose pose;
  forward_kinematics(model, trial, pose);
  return hand_depth(model, reach, pose, objects, object_count, cut, scratch);
}

PlacementSearch::Result PlacementSearch::run(const HandModel& model, const HandReach& reach,
                                             const SolverObject* objects, int32_t object_count,
                                             double tolerance, TreeCut cut, CandidateSet& scratch,
                                             Clock::time_point deadline, HandState* state) {
  if (phase_ == Phase::kIdle) {
    HandPose pose;
    forward_kinematics(model, *state, pose);
    const double depth = hand_depth(model, reach, pose, objects, object_count, cut, scratch);
    if (depth <= tolerance) return Result::kFound;
    // nothing free lies further than the hand's and every object's extent
    best_ = 2.0 * reach.hand;
    for (int32_t o = 0; o < object_count; ++o)
      if (!objects[o].tree->empty()) best_ += 2.0 * object_bound(objects[o]).radius;
    stride_ = std::max(0.002, best_ / 256.0);
    // Each ray marches out from the hand, nearest trial first across all rays, until one
    // is free; then the rays that could still beat it. A move by s changes how deep any
    // point sits in a leaf by s at most, so a placement `depth` deep is at least
    // depth - tolerance from any free one: the march jumps that far (never less than the
    // stride), and a hand 1.4 cm in costs a few trials a ray, not seven rings of them.
    // The first free trial of a ray is bisected down to the surface.
    std::fill(std::begin(next_), std::end(next_), std::max(stride_, depth - tolerance));
    std::fill(std::begin(inside_), std::end(inside_), 0.0);
    best_ray_ = -1;
    phase_ = Phase::kMarching;
  }
  // a run stops where its next trial would pass the deadline (judged by the dearest
  // trial so far), after one trial at least
  Clock::time_point before = Clock::now();
  for (bool first = true;; first = false) {
    if (!first) {
      const Clock::time_point now = Clock::now();
      trial_cost_ = std::max(trial_cost_, now - before);
      before = now;
      if (now + trial_cost_ > deadline) return Result::kPending;
    }
    if (phase_ == Phase::kBisecting) {
      if (high_ - low_ > kPrecision) {
        const double mid = 0.5 * (low_ + high_);
        (depth_at(model, reach, objects, object_count, cut, scratch, *state, ray_, mid) <= tolerance ? high_ : low_) = mid;
        continue;
      }
      if (high_ < best_) {
        best_ = high_;
        best_ray_ = ray_;
      }
      next_[ray_] = INFINITY;  // this ray's nearest free placement is known
      phase_ = Phase::kMarching;
    }
    int ray = -1;
    for (int i = 0; i < kDirections; ++i)
      if (next_[i] < best_ && (ray < 0 || next_[i] < next_[ray])) ray = i;
    if (ray < 0) break;
    const double t = next_[ray];
    const double d = depth_at(model, reach, objects, object_count, cut, scratch, *state, ray, t);
    if (d > tolerance) {
      inside_[ray] = t;
      next_[ray] = t + std::max(stride_, d - tolerance);
      continue;
    }
    phase_ = Phase::kBisecting;
    ray_ = ray;
    low_ = inside_[ray];
    high_ = t;
  }
  phase_ = Phase::kIdle;
  if (best_ray_ < 0) return Result::kNone;
  state->palm_position += best_ * direction(best_ray_);
  return Result::kFound;
}

}  // namespace frusta
