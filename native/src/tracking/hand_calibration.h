// SPDX-License-Identifier: MIT
// A hand def sized from a few seconds of tracked joints: hand length and breadth
// inverted through the anthropometry's proportions from distances the palm keeps
// whatever the pose, and each bone's measured length.
#pragma once

#include "hand/hand_model.h"
#include "tracking/hand_joints.h"

namespace frusta {

// 65536 frames: twelve minutes at 90 Hz, 2 MB of distances.
constexpr int kMaxCalibrationFrames = 65536;

// Size def (side and joint limits kept) from frame_count frames of joint_count(layout)
// joints each, every frame passed check_tracked_joints. A joint counts when its
// position is valid and tracked. On failure def is unchanged and the thread's error
// says which joints were missing.
frusta_result calibrate_hand_def(const TrackedJoint* frames, int frame_count, int32_t layout,
                                 HandDef* def);

// The length a bone has when its measured lengths are samples: their median, less the
// bias noise perpendicular to the bone adds (sigma^2 / length, sigma from the samples'
// spread along it). Reorders samples.
double bone_length(double* samples, int count);

}  // namespace frusta
