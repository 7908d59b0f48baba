// SPDX-License-Identifier: MIT
// What a force-feedback glove is to the engine, whatever wire it speaks: what it can
// do, what it reports (joint angles, perhaps a palm pose) and what it is sent (the
// subset of the world's device outputs it renders).
#pragma once

#include <array>
#include <cstdint>

#include <glm/gtc/quaternion.hpp>

#include "core/base.h"
#include "geometry/types.h"

namespace frusta {

// Which of the world's device outputs a glove renders (bits of DeviceCapabilities).
enum DeviceOutput : uint32_t {
  kOutputFingerResistance = 1u << 0,  // a brake per finger (LucidGloves' servos)
  kOutputFingertipForce = 1u << 1,    // a force vector per fingertip, palm frame
  kOutputJointTorque = 1u << 2,       // a torque per finger joint (exoskeletons)
};

struct DeviceCapabilities {
  int32_t fingers = FRUSTA_FINGER_COUNT;  // thumb first; the rest get no input
  uint32_t outputs = kOutputFingerResistance;
  bool has_palm_pose = false;  // a tracker on the glove reports the palm
  double max_finger_resistance = 10.0;  // newtons, per finger
  double max_fingertip_force = 10.0;    // newtons, per fingertip
  double max_joint_torque = 0.5;        // newton-metres, per joint
  double input_rate_hz = 100.0;   // what the glove sends at (nominal)
  double output_rate_hz = 100.0;  // the most commands per second it takes
  uint32_t protocol_version = 0;  // the wire's (0: none announced)
};

// One reading of the glove, already in the engine's units.
struct DeviceSample {
  // finger-major like HandState::angles: abduction, flexion 1-3; radians
  std::array<double, FRUSTA_HAND_JOINT_COUNT> angles{};
  bool has_palm_pose = false;
  vec3 palm_position{0.0};                             // metres, tracking frame
  glm::dquat palm_rotation{1.0, 0.0, 0.0, 0.0};        // unit
  int64_t device_time_us = -1;  // the glove's own clock, when it says (-1: it does not)
  int64_t sequence = -1;        // the glove's count of its samples, when it says (-1: it does not)
};

// What a glove is told to render: the world's device outputs clamped to the glove's
// limits and rate-limited. Frames: fingertip forces in the haptic palm's frame.
struct DeviceCommand {
  std::array<double, FRUSTA_FINGER_COUNT> finger_resistance{};  // newtons, >= 0
  std::array<vec3, FRUSTA_FINGER_COUNT> fingertip_force{};       // newtons
  std::array<double, FRUSTA_HAND_JOINT_COUNT> joint_torque{};    // newton-metres
};

}  // namespace frusta
