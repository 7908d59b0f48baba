// SPDX-License-Identifier: MIT
#include "tracking/joints_from_hand.h"

#include <glm/gtc/quaternion.hpp>

namespace frusta {

namespace {

constexpr int32_t kAllFlags = FRUSTA_JOINT_ORIENTATION_VALID | FRUSTA_JOINT_POSITION_VALID |
                              FRUSTA_JOINT_ORIENTATION_TRACKED | FRUSTA_JOINT_POSITION_TRACKED;

TrackedJoint joint_at(const vec3& position, const glm::dmat3& axes, double radius, bool xr) {
  TrackedJoint j;
  j.position = position;
  // keypoints carry positions only
  if (xr) j.rotation = glm::normalize(glm::quat_cast(axes));
  j.radius = radius;
  j.flags = xr ? kAllFlags : FRUSTA_JOINT_POSITION_VALID | FRUSTA_JOINT_POSITION_TRACKED;
  return j;
}

}  // namespace

vec3 chain_point(const HandModel& model, const HandPose& pose, int finger, int k) {
  const FingerPose& p = pose.fingers[finger];
  if (k < kChainPoints - 1) return p.joint[k];
  const glm::dmat3& last = p.segment_rotation[FRUSTA_SEGMENTS_PER_FINGER - 1];
  return p.joint[3] + model.fingers[finger].radius[3] * last[0];
}

void joints_from_hand(const HandModel& model, const HandPose& pose, int32_t layout,
                      TrackedJoint* out) {
  const bool xr = layout == FRUSTA_JOINT_LAYOUT_XR;
  // the palm-rigid joints, carried by the palm
  const PalmJoints palm = palm_joints(model, layout);
  for (int i = 0; i < palm.count; ++i) {
    const PalmJoint& j = palm.joints[static_cast<size_t>(i)];
    out[j.index] = joint_at(pose.palm_position + pose.palm_rotation * j.position,
                            pose.palm_rotation * j.axes, j.radius, xr);
  }
  // the chains, each joint oriented as the bone it starts (a tip as the last bone);
  // their first joints are palm-rigid too and written again, the same
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    const FingerPose& p = pose.fingers[f];
    for (int k = 0; k < kChainPoints; ++k) {
      const int segment = k < FRUSTA_SEGMENTS_PER_FINGER ? k : FRUSTA_SEGMENTS_PER_FINGER - 1;
      out[chain_joint(layout, f, k)] =
          joint_at(chain_point(model, pose, f, k), xr_axes(p.segment_rotation[segment]),
                   model.fingers[f].radius[k], xr);
    }
  }
}

}  // namespace frusta
