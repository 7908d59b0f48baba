// SPDX-License-Identifier: MIT
// A hand def sized from a few seconds of tracked joints: the palm's length and breadth
// fitted through the anthropometry's proportions to the distances between its joints
// (they do not change with the pose), and each bone's measured length.
#pragma once

#include <vector>

#include "hand/hand_model.h"
#include "tracking/hand_joints.h"

namespace frusta {

// 65536 frames: twelve minutes at 90 Hz, 16 MB of distances.
constexpr int kMaxCalibrationFrames = 65536;

// Sizes a hand def from frames of tracked joints, given one at a time (they need not
// be kept): per frame, the distances that do not change with the pose.
class HandCalibration {
 public:
  // frames: how many will be added (at most kMaxCalibrationFrames), for the storage.
  HandCalibration(int32_t layout, int frames);

  // joint_count(layout) joints that passed check_tracked_joint. A joint counts when its
  // position is valid and tracked.
  void add_frame(const TrackedJoint* joints);

  // Size def from the frames added (side and joint limits kept); once, as it reuses
  // their storage. On failure def is unchanged and the thread's error says which joints
  // were missing.
  frusta_result size(HandDef* def);

 private:
  // distances between two joints over the frames where both count
  class Distances {
   public:
    void reserve(int frames) { samples_.reserve(static_cast<size_t>(frames)); }
    void add(const TrackedJoint& a, const TrackedJoint& b);
    bool empty() const { return samples_.empty(); }
    // once: it reuses the samples
    double length();

   private:
    std::vector<double> samples_;
  };

  // the wrist and each finger's first joint (the thumb's CMC, the MCPs): the palm's
  // joints both layouts have, where the anthropometry puts them
  static constexpr int kPalmPoints = 1 + FRUSTA_FINGER_COUNT;
  static constexpr int kPalmPairs = kPalmPoints * (kPalmPoints - 1) / 2;
  int palm_joint(int point) const;

  int32_t layout_;
  int frames_ = 0;
  Distances bones_[FRUSTA_FINGER_COUNT][FRUSTA_SEGMENTS_PER_FINGER];
  Distances palm_[kPalmPairs];  // point pairs in order (0, 1), (0, 2), ..., (4, 5)
};

// The length a bone has when its measured lengths are samples: their interquartile
// mean, less the bias noise perpendicular to the bone adds (sigma^2 / length, sigma from
// the samples' spread along it). Reorders and overwrites samples.
double bone_length(double* samples, int count);

}  // namespace frusta
