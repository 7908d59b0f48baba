// SPDX-License-Identifier: MIT
// The two layouts of tracked hand joints (OpenXR's 26 joint poses, the 21 keypoints of
// camera trackers and hand datasets) and where their joints sit on a Frusta hand: the
// one definition that joints_from_hand makes joints by and the fit reads them by.
// frusta.h's "tracked hands" section states it for users.
#pragma once

#include <array>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "core/base.h"
#include "geometry/types.h"
#include "hand/hand_model.h"

namespace frusta {

// frusta_tracked_joint without the ABI's padding; flags are frusta_joint_flag bits.
struct TrackedJoint {
  vec3 position{0.0};                            // metres
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};       // OpenXR's joint axes; the fit normalises
  double radius = 0.0;                           // metres, 0: unknown
  int32_t flags = 0;
};

// The most joints a layout has (the XR layout's).
constexpr int kMaxTrackedJoints = FRUSTA_XR_JOINT_COUNT;
// A chain: the finger's first joint (MCP; the thumb's CMC), its second and third, and
// the tip: Frusta's joint[0..2] and the fingertip's end.
constexpr int kChainPoints = 4;
// Palm-rigid joints of the XR layout: palm, wrist, the thumb's metacarpal joint, four
// metacarpal and four proximal joints (the keypoints have six of them).
constexpr int kMaxPalmJoints = 11;
// A finger's metacarpal joint (the base of its metacarpal) lies on the line from the
// wrist centre to its MCP joint, this far along: where a Meta Quest 3 puts them (0.37 to
// 0.48; tests/data/tracked_hands). Placing them where the anthropometry's wrist crease
// would (0.16) left real hands' fingers clamped in half the fits.
constexpr double kCarpometacarpalFraction = 0.4;

// Joints in a layout (FRUSTA_XR_JOINT_COUNT or FRUSTA_KEYPOINT_COUNT); the layout must
// be one of frusta_joint_layout (checked at the boundary).
int joint_count(int32_t layout);
bool is_joint_layout(int32_t layout);

// The index in a layout of chain point k (0..3) of a finger, and of the wrist.
int chain_joint(int32_t layout, int finger, int k);
int wrist_joint(int32_t layout);

// OpenXR's axes of a bone from Frusta's frame of it (x along the bone towards the tip,
// z out of its back, y = z cross x): X = -y, Y = z, Z = -x. Right-handed on both hands.
glm::dmat3 xr_axes(const glm::dmat3& frame);

// A joint of a layout that moves with the palm, in the hand frame (a left hand's
// mirrored already): where it is, and (XR) its axes when they are palm-rigid too.
struct PalmJoint {
  int index = 0;               // in the layout
  vec3 position{0.0};          // metres, hand frame
  bool has_orientation = false;
  glm::dmat3 axes{1.0};        // the joint's OpenXR axes in the hand frame
  double radius = 0.0;         // metres
};

struct PalmJoints {
  std::array<PalmJoint, kMaxPalmJoints> joints{};
  int count = 0;
};

PalmJoints palm_joints(const HandModel& model, int32_t layout);

// The one check of a tracked joint from any input: known flags, and the fields they
// declare valid finite, positions within kMaxCoordinate, quaternion norms within
// [kMinQuaternionNorm, kMaxQuaternionNorm], radii within 0..kMaxHandSize. The thread's
// error names `name`[index] and the field.
frusta_result check_tracked_joint(const TrackedJoint& joint, const char* name, int index);

// One sample of a layout: the layout known, count its joint_count (checked before any
// joint is read), and each joint by check_tracked_joint.
frusta_result check_tracked_joints(const TrackedJoint* joints, int count, int32_t layout,
                                   const char* name);

// The layout known, or an error naming `field`.
frusta_result check_joint_layout(int32_t layout, const char* field);

}  // namespace frusta
