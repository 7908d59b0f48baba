// SPDX-License-Identifier: MIT
// How far the points of a finger can move while its angles change along a straight line
// (its palm held): the bounds that motion caps, detection margins and row reaches of the
// solver stand on.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "solver/detection.h"

namespace frusta {

using FingerAngles = std::array<double, FRUSTA_JOINTS_PER_FINGER>;

// The levers' bound, for any pose: no point of the finger moves further than the sum of
// each joint's turn times the most of the finger that joint can carry round.
double finger_lever_motion(const HandReach& reach, int finger, const FingerAngles& from,
                           const FingerAngles& to);
// ... of one of its segments: no point of that segment moves further.
double segment_lever_motion(const HandReach& reach, int finger, int segment,
                            const FingerAngles& from, const FingerAngles& to);

// Every segment of a finger, as a mask (bit s: segment s).
constexpr uint32_t kEverySegment = (1u << FRUSTA_SEGMENTS_PER_FINGER) - 1u;

// A finger's first-order motion at a pose: the velocity of each segment's two joint
// centres per unit turn of each joint (dD/dq and dE/dq; a joint beyond the segment: 0),
// made for the segments in a mask (bit s: segment s; the others are left as they were).
// (Left unset until made: a stage holds two, and clearing them cost a held grasp 3 %.)
struct FingerJacobian {
  std::array<std::array<vec3, FRUSTA_JOINTS_PER_FINGER>, FRUSTA_SEGMENTS_PER_FINGER> proximal,
      distal;
  vec3 abduction_axis, flexion_axis;
};
void finger_jacobian(const FingerPose& pose, uint32_t segments, FingerJacobian& jacobian);

// The motion bound of the turn `turn` of a finger's joints from the pose `jacobian` was
// made at, over the segments in `segments` (bit s: segment s): no point of such a segment
// s moves further than reach.segment_share[finger][s] times it (the fingertip's segment,
// whose share is 1, no further than it). Per segment, the lesser of the levers' bound and
// the pose's own: the segment's first-order motion (a rigid velocity field, largest over
// the hull of its end balls on one of them) plus what its levers can turn and stretch
// along the move. A closing fingertip's levers' bound is 2-2.3 times its joints' move,
// the pose's 1.2-1.4 times (its surface moves more).
double finger_motion(const HandModel& model, const HandReach& reach, const FingerJacobian& jacobian,
                     int finger, const FingerAngles& turn, uint32_t segments);

// How far a finger may move from where a stage starts: no further than `levers` by the
// levers' bound (the unit of the continuity budget), nor than `pose` by the pose's
// (Delta_r less what the palm moved: what a sub-step's detection covers, and what keeps a
// sub-step from passing through a sphere).
struct FingerCap {
  double levers = INFINITY;
  double pose = INFINITY;
};

// finger_motion over every segment of the straight move from `from` (posed at `pose`) to `to`.
double finger_motion(const HandModel& model, const HandReach& reach, const FingerPose& pose,
                     int finger, const FingerAngles& from, const FingerAngles& to);

// The fraction of the straight move from `from` (posed at `pose`) to `to` that keeps
// within `cap`: 1 for all of it. Both bounds grow at most in proportion along a move, so
// that fraction of it keeps within the cap. The pose's bound is worked out only where
// the levers' exceeds its cap.
double within_cap(const HandModel& model, const HandReach& reach, const FingerPose& pose,
                  int finger, const FingerAngles& from, const FingerAngles& to,
                  const FingerCap& cap);
// ... from the finger's Jacobian at `from`, made for every segment.
double within_cap(const HandModel& model, const HandReach& reach, const FingerJacobian& jacobian,
                  int finger, const FingerAngles& from, const FingerAngles& to,
                  const FingerCap& cap);

}  // namespace frusta
