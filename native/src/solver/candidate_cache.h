// SPDX-License-Identifier: MIT
// Detection with room to spare: the trees are walked a little further than a sub-step
// needs, and later sub-steps and steps take a body's candidates from that walk while the
// body has moved less than the room. A hand pressed into an object moves microns a step
// while its margins cover the millimetres it may move, and walking the trees again each
// step was a quarter of a closing grasp's time.
#pragma once

#include <array>
#include <cstdint>

#include "hand/kinematics.h"
#include "solver/detection.h"

namespace frusta {

class CandidateCache {
 public:
  // Make `set` hold, for body b at `pose`, every leaf (or cut node) within needs.body[b]
  // as detect_candidates would (up to spheres within rounding of the margin), and some
  // a little further (CandidateSet::need), in the order of their gap bounds where the
  // walk looked from: the walk it held from the last call where the body moved less than
  // the room it was walked with, else a walk `room` metres further. `set` is the cache's
  // store: it must be as the last call left it, and the objects those of that call,
  // unless clear() came between; `only` as for detect_candidates, holding every object
  // within the largest need plus room.
  void detect(const HandModel& model, const HandReach& reach, const HandPose& pose,
              const SolverObject* objects, int32_t object_count, const DetectionMargins& needs,
              double room, TreeCut cut, CandidateSet& set, const int32_t* only = nullptr,
              int32_t only_count = 0);
  // The objects moved or changed, or the set served as scratch: nothing cached holds.
  void clear() { valid_ = false; }

 private:
  // how far each body's last walk looked (from where the set placed it), and where its
  // spheres end in the set
  DetectionMargins margins_;
  std::array<int32_t, kBodyCount> walked_end_{};
  bool valid_ = false;  // the set holds a walk of every body (the first call makes one)
};

}  // namespace frusta
