// SPDX-License-Identifier: MIT
// Random hands and what a tracker would report for them, for the hand and tracking
// tests and the tracking benchmark: hands of random sizes on either side, poses within
// the joint limits, and their joints with Gaussian noise.
#pragma once

#include <array>
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "hand/anthropometry.h"
#include "hand/kinematics.h"
#include "tracking/joints_from_hand.h"

namespace frusta::scenes {

// A def of the given side and size, by the anthropometry (frusta_hand_def_set_size's).
inline HandDef sized_hand_def(int side, double length, double breadth) {
  HandDef def = default_hand_def();
  def.side = side;
  fill_hand_geometry(def, length, breadth);
  return def;
}

// A def of a random size: length 0.14..0.23 m, breadth 0.065..0.105 m (adults' 1st to
// 99th percentiles, roughly, and a child's).
inline HandDef random_hand_def(int side, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> length(0.14, 0.23), breadth(0.065, 0.105);
  const double l = length(rng);
  return sized_hand_def(side, l, breadth(rng));
}

// Angles uniform within the limits, the palm anywhere within a metre, any orientation.
inline HandState random_hand_state(const HandModel& model, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), coordinate(-1.0, 1.0);
  std::normal_distribution<double> gauss;
  HandState s;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      const FingerModel& m = model.fingers[f];
      s.angles[f * 4 + j] = m.joint_min[j] + unit(rng) * (m.joint_max[j] - m.joint_min[j]);
    }
  // braces: the draws in order on every compiler
  s.palm_position = vec3{coordinate(rng), coordinate(rng), coordinate(rng)};
  s.palm_rotation = glm::normalize(glm::dquat{gauss(rng), gauss(rng), gauss(rng), gauss(rng)});
  return s;
}

// The joints of a layout for a hand in a state.
inline std::array<TrackedJoint, kMaxTrackedJoints> tracked_joints(const HandModel& model,
                                                                 const HandState& state,
                                                                 int32_t layout) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  std::array<TrackedJoint, kMaxTrackedJoints> joints{};
  joints_from_hand(model, pose, layout, joints.data());
  return joints;
}

// Gaussian noise of sigma metres on every coordinate of the first count positions.
inline void add_noise(TrackedJoint* joints, int count, double sigma, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, sigma);
  for (int i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) joints[i].position[k] += noise(rng);
}

// The angle of the rotation between two unit quaternions, radians (0..pi).
inline double rotation_angle(const glm::dquat& a, const glm::dquat& b) {
  const glm::dquat d = a * glm::conjugate(b);
  return 2.0 * std::atan2(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), std::fabs(d.w));
}

}  // namespace frusta::scenes
