// SPDX-License-Identifier: MIT
// The last step before a glove: limits, rise rate, frames, and zero at once.
#include "devices/output_guard.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/quaternion.hpp>

namespace frusta {
namespace {

DeviceCapabilities all_outputs() {
  DeviceCapabilities c;
  c.outputs = kOutputFingerResistance | kOutputFingertipForce | kOutputJointTorque;
  c.max_finger_resistance = 4.0;
  c.max_fingertip_force = 3.0;
  c.max_joint_torque = 0.2;
  return c;
}

TEST(outputGuard, ClampsToTheGlovesLimitsWithoutTurningAForce) {
  OutputGuard guard(all_outputs(), OutputRates{1e9, 1e9});
  DeviceOutputs in;
  in.finger_resistance = {1.0, 9.0, -2.0, std::nan(""), 4.0};
  in.fingertip_force[1] = vec3(0.0, 6.0, 8.0);  // 10 N: scaled to 3 N along itself
  in.joint_torque[5] = -0.7;
  const DeviceCommand& c = guard.shape(in, glm::dquat(1, 0, 0, 0), 0.001);
  EXPECT_DOUBLE_EQ(c.finger_resistance[0], 1.0);
  EXPECT_DOUBLE_EQ(c.finger_resistance[1], 4.0);
  EXPECT_DOUBLE_EQ(c.finger_resistance[2], 0.0);
  EXPECT_DOUBLE_EQ(c.finger_resistance[3], 0.0);  // NaN: released
  EXPECT_NEAR(c.fingertip_force[1].y, 1.8, 1e-12);
  EXPECT_NEAR(c.fingertip_force[1].z, 2.4, 1e-12);
  EXPECT_DOUBLE_EQ(c.joint_torque[5], -0.2);
}

TEST(outputGuard, RisesAtItsRateAndFallsAtOnce) {
  OutputGuard guard(all_outputs(), OutputRates{100.0, 1.0});  // 0.1 N and 1 mN m per ms
  DeviceOutputs in;
  in.finger_resistance[2] = 4.0;
  in.joint_torque[0] = 0.2;
  double previous = 0.0;
  for (int tick = 1; tick <= 50; ++tick) {
    const DeviceCommand& c = guard.shape(in, glm::dquat(1, 0, 0, 0), 0.001);
    EXPECT_NEAR(c.finger_resistance[2], std::min(0.1 * tick, 4.0), 1e-9) << tick;
    EXPECT_NEAR(c.joint_torque[0], std::min(0.001 * tick, 0.2), 1e-12) << tick;
    previous = c.finger_resistance[2];
  }
  EXPECT_DOUBLE_EQ(previous, 4.0);
  in.finger_resistance[2] = 0.5;
  EXPECT_DOUBLE_EQ(guard.shape(in, glm::dquat(1, 0, 0, 0), 0.001).finger_resistance[2], 0.5);
  EXPECT_DOUBLE_EQ(guard.zero().finger_resistance[2], 0.0);
  EXPECT_NEAR(guard.shape(in, glm::dquat(1, 0, 0, 0), 0.001).finger_resistance[2], 0.1, 1e-12);
}

TEST(outputGuard, FingertipForcesGoOutInThePalmFrameAndMissingOutputsStayZero) {
  DeviceCapabilities caps = all_outputs();
  caps.outputs = kOutputFingertipForce;
  caps.fingers = 3;  // no ring or little finger on this glove
  OutputGuard guard(caps, OutputRates{1e9, 1e9});
  DeviceOutputs in;
  in.fingertip_force[0] = vec3(1.0, 0.0, 0.0);
  in.fingertip_force[4] = vec3(1.0, 0.0, 0.0);
  in.finger_resistance[0] = 2.0;
  // the palm turned 90 degrees about z: world x is the palm's -y
  const glm::dquat palm = glm::angleAxis(std::acos(-1.0) / 2, vec3(0, 0, 1));
  const DeviceCommand& c = guard.shape(in, palm, 0.001);
  EXPECT_NEAR(c.fingertip_force[0].x, 0.0, 1e-12);
  EXPECT_NEAR(c.fingertip_force[0].y, -1.0, 1e-12);
  EXPECT_EQ(c.fingertip_force[4], vec3(0.0));
  EXPECT_DOUBLE_EQ(c.finger_resistance[0], 0.0);
}

}  // namespace
}  // namespace frusta
