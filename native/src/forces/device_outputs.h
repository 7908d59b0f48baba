// SPDX-License-Identifier: MIT
// What a force-feedback device receives from the contact forces (seed [0083], [0166]):
// a force per fingertip, a scalar resistance per finger, a torque per finger joint
// (tau = J^T F), or a wrench on the palm, whichever it can render; each scaled down to
// the device's limits, never turned. And what the objects receive: the reaction wrench
// of every contact on each object, -(F + f) at the contact point.
#pragma once

#include <array>
#include <cstdint>

#include "forces/contact_forces.h"
#include "forces/force_params.h"
#include "hand/kinematics.h"
#include "solver/detection.h"

namespace frusta {

// Everything a device may render, from one step's contacts. World frame.
struct DeviceOutputs {
  // the force on each finger's distal segment (body finger * 3 + 2), newtons
  std::array<vec3, FRUSTA_FINGER_COUNT> fingertip_force{};
  // the magnitude of the total force on each finger's three segments, newtons
  std::array<double, FRUSTA_FINGER_COUNT> finger_resistance{};
  // tau = J^T (F + f) over each finger's contacts, finger-major like HandState::angles
  // (abduction, flexion 1-3): the torque the contacts put on each joint of the haptic
  // hand, newton-metres
  std::array<double, FRUSTA_HAND_JOINT_COUNT> joint_torque{};
  // the palm contacts' total force, newtons, and torque about the haptic palm origin,
  // newton-metres
  vec3 palm_force{0.0};
  vec3 palm_torque{0.0};
};

// What one object receives from the hand: the sum of -(F + f) at every contact point
// (newtons) and its torque about the object's pose position (newton-metres). Unclamped:
// the device's limits are the glove's, not the contact's.
struct ObjectWrench {
  vec3 force{0.0};
  vec3 torque{0.0};
};

// Far above any device, and low enough that every output product stays finite.
constexpr double kMaxDeviceLimit = 1e9;

// Each limit in [0, kMaxDeviceLimit]; the thread's error names the field.
frusta_result check_device_limits(const DeviceLimits& limits);

// `count` (>= 0) forces as ContactForces makes them against `object_count` objects: ids
// in range, points within kMaxPointCoordinate, forces finite and of bounded size; the
// thread's error names the field.
frusta_result check_contact_forces(const ContactForce* forces, int32_t count, int32_t object_count);

// From `forces` (a ContactForces' forces() after an update) and the haptic pose that
// update used: fill `out`, and `reactions` (object_count entries, one per object of
// `objects`): the entries of the objects a force names; the others are left as they
// are (a caller that keeps them zero reads zero there).
// Preconditions, which the world's own output meets and debug builds assert: out not
// null, counts >= 0 (reactions not null when object_count > 0); `limits` pass
// check_device_limits, `haptic` check_hand_pose, `forces` check_contact_forces, the
// objects check_force_objects.
void compute_device_outputs(const HandPose& haptic, const ContactForce* forces, int32_t force_count,
                            const SolverObject* objects, int32_t object_count,
                            const DeviceLimits& limits, DeviceOutputs* out,
                            ObjectWrench* reactions);

}  // namespace frusta
