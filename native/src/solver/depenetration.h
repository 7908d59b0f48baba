// SPDX-License-Identifier: MIT
// Where a graphic hand starts when its haptic hand starts inside objects: the haptic
// hand moved out along the shortest of 26 directions (a cube's faces, edges and
// corners). Run when a solver has no graphic hand yet; later steps keep it out.
#pragma once

#include <chrono>

#include "solver/detection.h"

namespace frusta {

// True when no part of the hand at `pose` sinks deeper than `tolerance` into any object,
// as the solver sees it: its leaves, or the nodes where `cut` stops (the solver's level
// of detail, which keeps the hand clear of those).
bool hand_is_free(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, double tolerance,
                  TreeCut cut, CandidateSet& scratch);

// The search for the nearest free placement, resumable: a hand deep in a large object
// takes tens of trials (each a detection of the whole hand: 40 and 11.6 ms in all for
// the start_inside scenario), more than a step's budget, so a step runs trials until
// its deadline and the next goes on where it stopped. The trials are the same, in the
// same order, however the search is cut: so is the placement found.
class PlacementSearch {
 public:
  using Clock = std::chrono::steady_clock;
  enum class Result {
    kFound,    // *state moved to the nearest free placement (or left: it was free)
    kNone,     // nothing free lies within the objects' reach; *state unchanged
    kPending,  // the deadline came first (after one trial at least): run again
  };

  // Search from scratch for the hand at *state, or go on with the search begun for it
  // (while pending, *state must stay the same and the objects and cut the search's).
  // Free: as hand_is_free with `cut`.
  Result run(const HandModel& model, const HandReach& reach, const SolverObject* objects,
             int32_t object_count, double tolerance, TreeCut cut, CandidateSet& scratch,
             Clock::time_point deadline, HandState* state);
  bool pending() const { return phase_ != Phase::kIdle; }

 private:
  static constexpr int kDirections = 26;  // a cube's faces, edges and corners
  enum class Phase { kIdle, kMarching, kBisecting };

  double depth_at(const HandModel& model, const HandReach& reach, const SolverObject* objects,
                  int32_t object_count, TreeCut cut, CandidateSet& scratch,
                  const HandState& state, int ray, double t);

  Phase phase_ = Phase::kIdle;
  double stride_ = 0.0;
  double next_[kDirections] = {}, inside_[kDirections] = {};
  double best_ = 0.0;
  int best_ray_ = -1;
  int ray_ = -1;                      // the ray being bisected
  double low_ = 0.0, high_ = 0.0;     // its bracket: inside at low_, free at high_
  Clock::duration trial_cost_{0};     // the dearest trial yet
};

}  // namespace frusta
