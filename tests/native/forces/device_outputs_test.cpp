// SPDX-License-Identifier: MIT
// What a device and the objects receive, against values worked out here: joint torques
// and the palm wrench do the virtual work of the contact forces (finite differences of
// each contact point over each joint and palm axis); the hand's forces and the objects'
// reactions cancel, forces and torques; and clamps shorten and never turn.
#include "forces/device_outputs.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <vector>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"

namespace frusta {
namespace {

constexpr int kThumb = 0;
constexpr int kIndex = 1;

HandModel right_hand() { return make_hand_model(default_hand_def()); }

// a hand away from every symmetry: turned palm, bent and spread fingers
HandState bent_hand() {
  HandState s;
  s.palm_position = vec3(0.01, -0.02, 0.03);
  s.palm_rotation = glm::angleAxis(0.4, glm::normalize(vec3(1.0, 2.0, 3.0)));
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    double* q = &s.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER)];
    q[0] = 0.05 * (f - 2);
    q[1] = 0.3 + 0.1 * f;
    q[2] = 0.5;
    q[3] = 0.25;
  }
  return s;
}

HandPose pose_of(const HandModel& model, const HandState& state) {
  HandPose pose;
  forward_kinematics(model, state, pose);
  return pose;
}

// A force on a material point of a body, given in that body's frame.
struct Push {
  int body;
  vec3 local;  // metres, in the segment's (or palm's) frame
  vec3 normal_force;
  vec3 friction;
};

vec3 material_point(const HandPose& pose, int body, const vec3& local) {
  if (body == kPalmBody) return pose.palm_position + pose.palm_rotation * local;
  return segment_point(pose, body / FRUSTA_SEGMENTS_PER_FINGER, body % FRUSTA_SEGMENTS_PER_FINGER,
                       local);
}

std::vector<ContactForce> contact_forces(const HandPose& pose, const std::vector<Push>& pushes) {
  std::vector<ContactForce> out;
  for (const Push& p : pushes) {
    ContactForce c;
    c.body = p.body;
    c.haptic_point = material_point(pose, p.body, p.local);
    c.graphic_point = c.haptic_point;
    c.normal = vec3(0.0, 0.0, 1.0);
    c.normal_force = p.normal_force;
    c.friction = p.friction;
    out.push_back(c);
  }
  return out;
}

const std::vector<Push> kPushes = {
    {kIndex * 3 + 0, vec3(0.020, 0.003, -0.008), vec3(0.3, -0.2, 0.5), vec3(0.05, 0.1, 0.0)},
    {kIndex * 3 + 1, vec3(0.010, -0.004, -0.007), vec3(-0.1, 0.4, 0.2), vec3(0.0, -0.05, 0.02)},
    {kIndex * 3 + 2, vec3(0.015, 0.000, -0.006), vec3(0.2, 0.1, 0.9), vec3(-0.1, 0.0, 0.0)},
    {kIndex * 3 + 2, vec3(0.022, 0.002, 0.004), vec3(0.0, 0.0, -0.3), vec3(0.0, 0.02, 0.0)},
    {kThumb * 3 + 0, vec3(0.030, 0.005, -0.010), vec3(0.4, 0.4, 0.1), vec3(0.0, 0.0, 0.0)},
    {kThumb * 3 + 2, vec3(0.012, -0.003, -0.006), vec3(-0.6, 0.1, 0.3), vec3(0.03, 0.0, -0.01)},
    {kPalmBody, vec3(0.050, 0.020, -0.020), vec3(0.1, -0.3, 1.2), vec3(0.2, 0.0, 0.0)},
    {kPalmBody, vec3(0.020, -0.030, -0.015), vec3(-0.2, 0.1, 0.7), vec3(0.0, 0.1, 0.05)},
};

DeviceLimits no_limits() {
  DeviceLimits l;
  l.max_fingertip_force = l.max_finger_resistance = l.max_palm_force = 1e9;
  l.max_joint_torque = l.max_palm_torque = 1e9;
  return l;
}

const SolverObject kObject{nullptr, {vec3(0.1, 0.0, -0.05), glm::dmat3(1.0)}};

TEST(DeviceOutputs, JointTorquesAndPalmWrenchDoTheVirtualWorkOfTheContactForces) {
  const HandModel model = right_hand();
  const HandState state = bent_hand();
  const HandPose pose = pose_of(model, state);
  const std::vector<ContactForce> forces = contact_forces(pose, kPushes);
  DeviceOutputs out;
  ObjectWrench reaction;
  compute_device_outputs(pose, forces.data(), static_cast<int32_t>(forces.size()), &kObject, 1,
                         no_limits(), &out, &reaction);

  // tau_j = sum of (F + f) . dP/dq_j, each contact point moved with its segment
  const double h = 1e-6;
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
      HandState plus = state, minus = state;
      plus.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)] += h;
      minus.angles[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)] -= h;
      const HandPose up = pose_of(model, plus), down = pose_of(model, minus);
      double work = 0.0;
      for (const Push& p : kPushes) {
        if (p.body == kPalmBody || p.body / FRUSTA_SEGMENTS_PER_FINGER != f) continue;
        const vec3 velocity =
            (material_point(up, p.body, p.local) - material_point(down, p.body, p.local)) / (2 * h);
        work += glm::dot(p.normal_force + p.friction, velocity);
      }
      EXPECT_NEAR(out.joint_torque[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)], work,
                  1e-9)
          << "finger " << f << " joint " << j;
    }
  }

  // the palm: its force, and its torque as the work per radian of turning the palm about
  // each world axis through its origin
  vec3 palm_force(0.0);
  for (const Push& p : kPushes)
    if (p.body == kPalmBody) palm_force += p.normal_force + p.friction;
  EXPECT_NEAR(glm::length(out.palm_force - palm_force), 0.0, 1e-15);
  for (int k = 0; k < 3; ++k) {
    vec3 axis(0.0);
    axis[k] = 1.0;
    HandState plus = state, minus = state;
    plus.palm_rotation = glm::angleAxis(h, axis) * state.palm_rotation;
    minus.palm_rotation = glm::angleAxis(-h, axis) * state.palm_rotation;
    const HandPose up = pose_of(model, plus), down = pose_of(model, minus);
    double work = 0.0;
    for (const Push& p : kPushes) {
      if (p.body != kPalmBody) continue;
      const vec3 velocity =
          (material_point(up, p.body, p.local) - material_point(down, p.body, p.local)) / (2 * h);
      work += glm::dot(p.normal_force + p.friction, velocity);
    }
    EXPECT_NEAR(out.palm_torque[k], work, 1e-9) << "palm axis " << k;
  }
}

TEST(DeviceOutputs, FingertipForceAndResistanceSumTheirContacts) {
  const HandModel model = right_hand();
  const HandPose pose = pose_of(model, bent_hand());
  const std::vector<ContactForce> forces = contact_forces(pose, kPushes);
  DeviceOutputs out;
  ObjectWrench reaction;
  compute_device_outputs(pose, forces.data(), static_cast<int32_t>(forces.size()), &kObject, 1,
                         no_limits(), &out, &reaction);
  // index tip: the two distal pushes; index: all three segments
  const vec3 index_tip =
      vec3(0.2, 0.1, 0.9) + vec3(-0.1, 0.0, 0.0) + vec3(0.0, 0.0, -0.3) + vec3(0.0, 0.02, 0.0);
  const vec3 index_all = index_tip + vec3(0.3, -0.2, 0.5) + vec3(0.05, 0.1, 0.0) +
                         vec3(-0.1, 0.4, 0.2) + vec3(0.0, -0.05, 0.02);
  EXPECT_NEAR(glm::length(out.fingertip_force[kIndex] - index_tip), 0.0, 1e-15);
  EXPECT_NEAR(out.finger_resistance[kIndex], glm::length(index_all), 1e-15);
  const vec3 thumb_tip = vec3(-0.6, 0.1, 0.3) + vec3(0.03, 0.0, -0.01);
  EXPECT_NEAR(glm::length(out.fingertip_force[kThumb] - thumb_tip), 0.0, 1e-15);
  for (int f = 2; f < FRUSTA_FINGER_COUNT; ++f) {
    EXPECT_EQ(out.fingertip_force[f], vec3(0.0)) << "finger " << f << " touches nothing";
    EXPECT_EQ(out.finger_resistance[f], 0.0);
    for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
      EXPECT_EQ(out.joint_torque[static_cast<size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)], 0.0);
  }
}

TEST(DeviceOutputs, HandForcesAndObjectReactionsCancel) {
  // three objects, turned and apart; the last one touched by nothing
  const HandModel model = right_hand();
  const HandPose pose = pose_of(model, bent_hand());
  std::vector<ContactForce> forces = contact_forces(pose, kPushes);
  const std::array<SolverObject, 3> objects = {
      SolverObject{nullptr,
                   {vec3(0.12, 0.02, -0.04), glm::mat3_cast(glm::angleAxis(0.7, vec3(0, 0, 1)))}},
      SolverObject{nullptr,
                   {vec3(-0.05, 0.10, 0.02), glm::mat3_cast(glm::angleAxis(-1.1, vec3(1, 0, 0)))}},
      SolverObject{nullptr, {vec3(0.3, 0.3, 0.3), glm::dmat3(1.0)}}};
  for (size_t i = 0; i < forces.size(); ++i) {
    forces[i].object = static_cast<int32_t>(i % 2);
    forces[i].graphic_point =
        forces[i].haptic_point + vec3(0.0, 0.0, 0.001 * static_cast<double>(i));
  }
  DeviceOutputs out;
  std::array<ObjectWrench, 3> reactions;
  compute_device_outputs(pose, forces.data(), static_cast<int32_t>(forces.size()), objects.data(),
                         3, no_limits(), &out, reactions.data());

  // about one point for all: each object's torque moved there from its pose position
  const vec3 common(0.3, -0.2, 0.1);
  vec3 hand_force(0.0), hand_torque(0.0), object_force(0.0), object_torque(0.0);
  for (const ContactForce& c : forces) {
    hand_force += c.normal_force + c.friction;
    hand_torque += glm::cross(c.graphic_point - common, c.normal_force + c.friction);
  }
  for (size_t o = 0; o < objects.size(); ++o) {
    object_force += reactions[o].force;
    object_torque +=
        reactions[o].torque + glm::cross(objects[o].pose.position - common, reactions[o].force);
  }
  EXPECT_NEAR(glm::length(hand_force + object_force), 0.0, 1e-14);
  EXPECT_NEAR(glm::length(hand_torque + object_torque), 0.0, 1e-14);
  EXPECT_GT(glm::length(hand_force), 1.0) << "a case with forces in it";
  EXPECT_EQ(reactions[2].force, vec3(0.0)) << "untouched";
  EXPECT_EQ(reactions[2].torque, vec3(0.0));
}

TEST(DeviceOutputs, ClampingShortensEveryOutputWithoutTurningIt) {
  const HandModel model = right_hand();
  const HandPose pose = pose_of(model, bent_hand());
  const DeviceLimits limits;              // 10 N tip and finger, 0.5 N m joint, 20 N and 1 N m palm
  const vec3 tip_force(30.0, 40.0, 0.0);  // 50 N
  const vec3 palm_local(0.05, 0.02, -0.02);
  const vec3 palm_push(0.0, 0.0, 50.0);
  const std::vector<Push> pushes = {
      {kIndex * 3 + 2, vec3(0.015, 0.0, -0.006), tip_force, vec3(0.0)},
      {kPalmBody, palm_local, palm_push, vec3(0.0)}};
  const std::vector<ContactForce> forces = contact_forces(pose, pushes);
  DeviceOutputs out;
  ObjectWrench reaction;
  compute_device_outputs(pose, forces.data(), 2, &kObject, 1, limits, &out, &reaction);

  EXPECT_NEAR(glm::length(out.fingertip_force[kIndex] - vec3(6.0, 8.0, 0.0)), 0.0, 1e-14);
  EXPECT_EQ(out.finger_resistance[kIndex], 10.0);

  // the index's torques, J^T F unclamped, then one factor that brings the largest to 0.5
  double jacobian[3 * kJacobianColumns];
  point_jacobian(pose, kIndex, 2, forces[0].haptic_point, jacobian);
  std::array<double, FRUSTA_JOINTS_PER_FINGER> tau{};
  double largest = 0.0;
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
    for (int r = 0; r < 3; ++r) tau[j] += jacobian[r * kJacobianColumns + j] * tip_force[r];
    largest = std::max(largest, std::fabs(tau[j]));
  }
  ASSERT_GT(largest, limits.max_joint_torque) << "the case is meant to clamp";
  for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j)
    EXPECT_NEAR(out.joint_torque[static_cast<size_t>(kIndex * 4 + j)],
                tau[j] * limits.max_joint_torque / largest, 1e-14)
        << "joint " << j;

  // the palm: force and torque shortened by one factor, the smaller of the two limits'
  const vec3 arm = pose.palm_rotation * palm_local;
  const vec3 torque = glm::cross(arm, palm_push);
  const double scale = std::min(limits.max_palm_force / glm::length(palm_push),
                                limits.max_palm_torque / glm::length(torque));
  ASSERT_LT(scale, 1.0);
  EXPECT_NEAR(glm::length(out.palm_force - scale * palm_push), 0.0, 1e-13);
  EXPECT_NEAR(glm::length(out.palm_torque - scale * torque), 0.0, 1e-13);
  EXPECT_LE(glm::length(out.palm_force), limits.max_palm_force * (1 + 1e-15));
  EXPECT_LE(glm::length(out.palm_torque), limits.max_palm_torque * (1 + 1e-15));

  // the object still receives the whole force: the limits are the glove's
  EXPECT_NEAR(glm::length(reaction.force + tip_force + palm_push), 0.0, 1e-13);

  // under every limit nothing is scaled
  const std::vector<ContactForce> small = contact_forces(
      pose, {{kIndex * 3 + 2, vec3(0.015, 0.0, -0.006), tip_force * 0.01, vec3(0.0)}});
  compute_device_outputs(pose, small.data(), 1, &kObject, 1, limits, &out, &reaction);
  EXPECT_EQ(out.fingertip_force[kIndex], tip_force * 0.01);
  EXPECT_EQ(out.finger_resistance[kIndex], glm::length(tip_force * 0.01));
}

}  // namespace
}  // namespace frusta
