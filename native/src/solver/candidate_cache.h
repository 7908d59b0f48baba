// SPDX-License-Identifier: MIT
// Detection with room to spare: the trees are walked a little further than a sub-step
// needs, and later sub-steps and steps take a body's candidates from that walk while the
// body has moved less than the room. A hand pressed into an object moves microns a step
// while its margins cover the millimetres it may move, and walking the trees again each
// step was a quarter of a closing grasp's time.
#pragma once

#include <cstdint>

#include "hand/kinematics.h"
#include "solver/detection.h"

namespace frusta {

class CandidateCache {
 public:
  // Fill `out` with every leaf (or cut node) within needs.body[b] of body b at `pose`,
  // as detect_candidates would (up to spheres within rounding of the margin; in the order
  // of their gap bounds where the walk looked from): from the cache where the body moved
  // less than the room it was walked with, else from a walk `room` metres further, kept
  // for later calls. The objects must be those of the last call unless clear() came
  // between; `only` as for detect_candidates, holding every object within the largest
  // need plus room.
  void detect(const HandModel& model, const HandReach& reach, const HandPose& pose,
              const SolverObject* objects, int32_t object_count, const DetectionMargins& needs,
              double room, TreeCut cut, CandidateSet& out, const int32_t* only = nullptr,
              int32_t only_count = 0);
  // The objects moved or changed: nothing cached holds.
  void clear() { valid_ = false; }

 private:
  // each body's last walk (where it looked from: its placed) and how far it looked
  CandidateSet wide_, spare_;
  DetectionMargins margins_;
  bool valid_ = false;  // a walk of every body is cached (the first call makes one)
};

}  // namespace frusta
