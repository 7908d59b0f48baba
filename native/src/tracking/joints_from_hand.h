// SPDX-License-Identifier: MIT
// Forward kinematics to tracked joints: what a tracker would report for a Frusta hand,
// every joint valid and tracked. The fit's tests, recordings and demos start here.
#pragma once

#include "hand/kinematics.h"
#include "tracking/hand_joints.h"

namespace frusta {

// The joint_count(layout) joints of a hand posed by forward_kinematics, into out.
void joints_from_hand(const HandModel& model, const HandPose& pose, int32_t layout,
                      TrackedJoint* out);

// A chain point of a finger posed by forward_kinematics: joint[k] for k < 3, the
// fingertip's end (the tip ball's centre plus its radius along the last segment) for 3.
vec3 chain_point(const HandModel& model, const HandPose& pose, int finger, int k);

}  // namespace frusta
