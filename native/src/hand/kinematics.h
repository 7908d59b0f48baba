// SPDX-License-Identifier: MIT
// Forward kinematics of the hand (seed eq. 7) and Jacobians of its material points.
#pragma once

#include <array>

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "core/base.h"
#include "geometry/types.h"
#include "hand/hand_model.h"

namespace frusta {

// What a glove (haptic hand) or the solver (graphic hand) sets.
struct HandState {
  vec3 palm_position{0.0};
  glm::dquat palm_rotation{1.0, 0.0, 0.0, 0.0};  // unit
  std::array<double, FRUSTA_HAND_JOINT_COUNT> angles{};  // finger-major: abduction, flex 1-3
};

// World geometry of one finger.
struct FingerPose {
  std::array<vec3, 4> joint{};  // first, second, third joint centre, tip centre
  // segment frames: x along the segment, y the flexion axis, z = x cross y
  std::array<glm::dmat3, FRUSTA_SEGMENTS_PER_FINGER> segment_rotation{};
  vec3 abduction_axis{0.0};  // world axes as they move points: dP/dtheta = axis x (P - J)
  vec3 flexion_axis{0.0};
};

struct HandPose {
  vec3 palm_position{0.0};
  glm::dmat3 palm_rotation{1.0};
  std::array<FingerPose, FRUSTA_FINGER_COUNT> fingers{};
};

// Columns of a point Jacobian: the finger's four joints, then the palm's 6 DOF.
constexpr int kJacobianColumns = FRUSTA_JOINTS_PER_FINGER + FRUSTA_PALM_DOF;

// The one check of a hand state from any input (C ABI, World::set_haptic, gloves):
// positions within kMaxCoordinate, a rotation of norm within [kMinQuaternionNorm,
// kMaxQuaternionNorm] (normalised by whoever uses it), angles within kMaxJointAngle
// (clamped to the limits later). The thread's error names `name`'s field.
frusta_result check_hand_state(const HandState& state, const char* name);

// Clamp every angle of state into the model's limits.
void clamp_to_limits(const HandModel& model, HandState& state);

// The state a fraction t of the way from a to b: palm and angles straight, the palm's
// rotation along the shorter arc.
HandState interpolate(const HandState& a, const HandState& b, double t);

// Seed eq. 7: P = M0(palm) Ms(abduction) M1 M2 M3 P_local for every finger.
void forward_kinematics(const HandModel& model, const HandState& state, HandPose& pose);

// One finger of it, on the palm already in pose (after a change of that finger's angles).
void finger_kinematics(const HandModel& model, const HandState& state, int finger, HandPose& pose);

// The segment solid between joint s and s + 1 of a finger.
Segment finger_segment(const HandModel& model, const HandPose& pose, int finger, int segment);

// Palm sphere i in world coordinates.
Sphere palm_sphere(const HandModel& model, const HandPose& pose, int index);

// World position of a point given in a segment's frame (origin at its proximal joint).
vec3 segment_point(const HandPose& pose, int finger, int segment, const vec3& local);

// dP/d(finger joints, palm translation, palm rotation vector in world), row-major
// 3 x kJacobianColumns. Joints distal to the segment have zero columns.
void point_jacobian(const HandPose& pose, int finger, int segment, const vec3& world_point,
                    double jacobian[3 * kJacobianColumns]);

}  // namespace frusta
