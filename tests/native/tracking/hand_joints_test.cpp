// SPDX-License-Identifier: MIT
#include "tracking/hand_joints.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/error.h"
#include "scenes/random_hands.h"
#include "tracking/joints_from_hand.h"

namespace frusta {
namespace {

constexpr int32_t kXr = FRUSTA_JOINT_LAYOUT_XR;
constexpr int32_t kKeypoints = FRUSTA_JOINT_LAYOUT_KEYPOINTS;

TEST(HandJoints, ChainsFollowXrHandJointExtAndMediaPipesOrder) {
  // XR_HAND_JOINT_THUMB_METACARPAL_EXT = 2 .. THUMB_TIP = 5, INDEX_PROXIMAL = 7,
  // MIDDLE_INTERMEDIATE = 13, RING_DISTAL = 19, LITTLE_TIP = 25
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_THUMB, 0), 2);
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_THUMB, 3), 5);
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_INDEX, 0), 7);
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_MIDDLE, 1), 13);
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_RING, 2), 19);
  EXPECT_EQ(chain_joint(kXr, FRUSTA_FINGER_LITTLE, 3), 25);
  EXPECT_EQ(wrist_joint(kXr), 1);
  // MediaPipe: THUMB_CMC 1, THUMB_TIP 4, INDEX_FINGER_MCP 5, MIDDLE_FINGER_PIP 10,
  // RING_FINGER_DIP 15, PINKY_TIP 20
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_THUMB, 0), 1);
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_THUMB, 3), 4);
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_INDEX, 0), 5);
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_MIDDLE, 1), 10);
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_RING, 2), 15);
  EXPECT_EQ(chain_joint(kKeypoints, FRUSTA_FINGER_LITTLE, 3), 20);
  EXPECT_EQ(wrist_joint(kKeypoints), 0);
  EXPECT_EQ(joint_count(kXr), 26);
  EXPECT_EQ(joint_count(kKeypoints), 21);
}

class HandJointsSide : public ::testing::TestWithParam<int> {
 protected:
  HandModel model() const { return make_hand_model(scenes::sized_hand_def(GetParam(), 0.19, 0.085)); }
};

// OpenXR: -Z along the bone a joint starts, towards the tip; +Y out of the back of the
// finger; X = Y cross Z (a proper rotation)
TEST_P(HandJointsSide, XrAxesRunAlongTheBonesWithYOutOfTheBack) {
  const HandModel m = model();
  std::mt19937_64 rng(5);
  const HandState state = scenes::random_hand_state(m, rng);
  HandPose pose;
  forward_kinematics(m, state, pose);
  const auto joints = scenes::tracked_joints(m, state, kXr);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    for (int k = 0; k < kChainPoints; ++k) {
      const TrackedJoint& j = joints[static_cast<size_t>(chain_joint(kXr, f, k))];
      const glm::dmat3 axes = glm::mat3_cast(j.rotation);
      const int s = std::min(k, 2);
      const vec3 bone = glm::normalize(chain_point(m, pose, f, s + 1) - chain_point(m, pose, f, s));
      EXPECT_NEAR(glm::dot(-axes[2], bone), 1.0, 1e-12) << "finger " << f << " joint " << k;
      // the back of the finger: the segment frame's z, the side the palm is not on
      EXPECT_NEAR(glm::dot(axes[1], pose.fingers[f].segment_rotation[s][2]), 1.0, 1e-12);
      EXPECT_EQ(j.flags, 15);
    }
  }
  // the wrist: -Z towards the fingers (+x of the hand frame), +Y its back (+z)
  const glm::dmat3 wrist = glm::mat3_cast(joints[1].rotation);
  EXPECT_NEAR(glm::dot(-wrist[2], pose.palm_rotation[0]), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(wrist[1], pose.palm_rotation[2]), 1.0, 1e-12);
  EXPECT_LT(glm::length(joints[1].position - pose.palm_position), 1e-12);
}

TEST_P(HandJointsSide, TipIsTheFingertipsEndAndAStraightMiddleFingerReachesHandLength) {
  const HandModel m = model();
  HandState rest;
  for (int32_t layout : {kXr, kKeypoints}) {
    const auto joints = scenes::tracked_joints(m, rest, layout);
    const TrackedJoint& tip = joints[static_cast<size_t>(chain_joint(layout, FRUSTA_FINGER_MIDDLE, 3))];
    EXPECT_NEAR(tip.position.x, 0.19, 1e-12);
    EXPECT_EQ(tip.radius, m.fingers[FRUSTA_FINGER_MIDDLE].radius[3]);
  }
}

TEST_P(HandJointsSide, PalmJointsMoveWithThePalmAloneAndMirrorOnALeftHand) {
  const HandModel m = model();
  const double side = GetParam() == FRUSTA_HAND_LEFT ? -1.0 : 1.0;
  std::mt19937_64 rng(6);
  HandState a = scenes::random_hand_state(m, rng), b = scenes::random_hand_state(m, rng);
  b.palm_position = a.palm_position;
  b.palm_rotation = a.palm_rotation;
  for (int32_t layout : {kXr, kKeypoints}) {
    const auto ja = scenes::tracked_joints(m, a, layout), jb = scenes::tracked_joints(m, b, layout);
    const PalmJoints palm = palm_joints(m, layout);
    EXPECT_EQ(palm.count, layout == kXr ? 11 : 6);
    for (int i = 0; i < palm.count; ++i) {
      const PalmJoint& p = palm.joints[static_cast<size_t>(i)];
      const size_t index = static_cast<size_t>(p.index);
      EXPECT_LT(glm::length(ja[index].position - jb[index].position), 1e-12) << "joint " << p.index;
      if (p.has_orientation) {
        EXPECT_LT(scenes::rotation_angle(ja[index].rotation, jb[index].rotation), 1e-12);
      }
      const vec3 expected = a.palm_position + glm::mat3_cast(a.palm_rotation) * p.position;
      EXPECT_LT(glm::length(ja[index].position - expected), 1e-12);
    }
  }
  // the metacarpal joints on the way from the wrist to the MCP joints; the palm halfway
  // along the middle one
  const PalmJoints xr = palm_joints(m, kXr);
  auto at = [&](int index) {
    for (const PalmJoint& p : xr.joints)
      if (p.index == index) return p.position;
    return vec3(std::nan(""));
  };
  const vec3 middle_mcp = at(12), middle_cmc = at(11);
  EXPECT_LT(glm::length(middle_cmc - kCarpometacarpalFraction * middle_mcp), 1e-15);
  EXPECT_LT(glm::length(at(0) - 0.5 * (middle_cmc + middle_mcp)), 1e-15);
  EXPECT_EQ(middle_mcp.y, side * m.fingers[FRUSTA_FINGER_MIDDLE].base_position.y);
}

std::string side_name(const ::testing::TestParamInfo<int>& side) {
  return side.param == FRUSTA_HAND_LEFT ? "left" : "right";
}
INSTANTIATE_TEST_SUITE_P(Sides, HandJointsSide,
                         ::testing::Values(FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT), side_name);

// ---------------------------------------------------------------- the check

class TrackedJointCheck : public ::testing::Test {
 protected:
  TrackedJointCheck() {
    HandState rest;
    joints_ = scenes::tracked_joints(make_hand_model(scenes::sized_hand_def(0, 0.19, 0.085)), rest, kXr);
  }
  frusta_result check(int count = FRUSTA_XR_JOINT_COUNT, int32_t layout = kXr) {
    return check_tracked_joints(joints_.data(), count, layout, "joints");
  }
  std::string message() const { return last_error_message(); }
  std::array<TrackedJoint, kMaxTrackedJoints> joints_{};
};

TEST_F(TrackedJointCheck, ExactJointsPass) { EXPECT_EQ(check(), FRUSTA_OK); }

TEST_F(TrackedJointCheck, NonFiniteValidFieldsAreRefusedNamingJointAndField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  joints_[7].position.y = nan;
  EXPECT_EQ(check(), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(message().find("joints[7].position"), std::string::npos) << message();
  joints_[7].position.y = 0.0;
  joints_[9].rotation.w = std::numeric_limits<double>::infinity();
  EXPECT_EQ(check(), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(message().find("joints[9].rotation"), std::string::npos) << message();
  joints_[9].rotation = glm::dquat(1, 0, 0, 0);
  joints_[3].radius = nan;
  EXPECT_EQ(check(), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_NE(message().find("joints[3].radius"), std::string::npos) << message();
}

TEST_F(TrackedJointCheck, FieldsNoFlagDeclaresValidAreNotRead) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  joints_[4].flags = FRUSTA_JOINT_ORIENTATION_VALID;  // position not valid
  joints_[4].position = vec3(nan);
  joints_[4].radius = -1.0;
  joints_[5].flags = FRUSTA_JOINT_POSITION_VALID;  // orientation not valid
  joints_[5].rotation = glm::dquat(nan, 0, 0, 0);
  EXPECT_EQ(check(), FRUSTA_OK);
}

TEST_F(TrackedJointCheck, AbsurdValuesAreRefused) {
  joints_[2].position.x = 1e7;
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(message().find("joints[2].position"), std::string::npos) << message();
  joints_[2].position.x = 0.0;
  joints_[2].rotation = glm::dquat(0, 0, 0, 0);
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(message().find("joints[2].rotation has norm 0"), std::string::npos) << message();
  joints_[2].rotation = glm::dquat(3, 0, 0, 0);
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
  joints_[2].rotation = glm::dquat(1.5, 0, 0, 0);  // within [0.5, 2]: normalised
  EXPECT_EQ(check(), FRUSTA_OK);
  joints_[2].radius = -0.001;
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
  joints_[2].radius = 0.0;
  joints_[2].flags = 16;
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(message().find("joints[2].flags"), std::string::npos) << message();
  joints_[2].flags = -1;
  EXPECT_EQ(check(), FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST_F(TrackedJointCheck, CountMustBeTheLayoutsAndTheLayoutKnown) {
  EXPECT_EQ(check(FRUSTA_KEYPOINT_COUNT), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(message().find("count is 21, must be 26"), std::string::npos) << message();
  EXPECT_EQ(check(FRUSTA_XR_JOINT_COUNT, kKeypoints), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_EQ(check(FRUSTA_KEYPOINT_COUNT, kKeypoints), FRUSTA_OK);
  EXPECT_EQ(check(0, 2), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(message().find("layout is 2"), std::string::npos) << message();
}

}  // namespace
}  // namespace frusta
