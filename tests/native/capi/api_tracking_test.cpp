// SPDX-License-Identifier: MIT
// Tracked hands through the C ABI (native/src/capi/api_tracking.cpp): the fit's round
// trip, its palm and angles going straight into a world, calibration, and every entry
// point's error paths (each refused with the field named, nothing changed).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "capi_fixture.h"
#include "frusta/frusta.h"

namespace frusta {
namespace {

using capiTracking = testing::CapiTest;
using testing::Angles;
using testing::interior_angles;
using testing::random_pose;

using Joints = std::array<frusta_tracked_joint, FRUSTA_XR_JOINT_COUNT>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Owns a fitter; the test fails if creation fails.
class ScopedFitter {
 public:
  ScopedFitter(const frusta_hand_def& def, int32_t layout) {
    frusta_hand_fit_def fit_def = frusta_default_hand_fit_def();
    fit_def.layout = layout;
    EXPECT_EQ(frusta_create_hand_fitter(&def, &fit_def, &id_), FRUSTA_OK) << frusta_last_error();
  }
  ~ScopedFitter() {
    if (!FRUSTA_IS_NULL(id_)) frusta_destroy_hand_fitter(id_);
  }
  ScopedFitter(const ScopedFitter&) = delete;
  ScopedFitter& operator=(const ScopedFitter&) = delete;
  frusta_hand_fitter_id get() const { return id_; }

 private:
  frusta_hand_fitter_id id_{};
};

frusta_hand_fit blank_fit() {
  frusta_hand_fit fit;
  std::memset(&fit, 0, sizeof fit);
  fit.struct_size = sizeof fit;
  return fit;
}

frusta_hand_def sized_def(int side, double length, double breadth) {
  frusta_hand_def def = frusta_default_hand_def();
  def.side = side;
  EXPECT_EQ(frusta_hand_def_set_size(&def, length, breadth), FRUSTA_OK);
  return def;
}

Joints joints_of(const frusta_hand_def& def, int32_t layout, const frusta_pose& palm,
                 const Angles& angles) {
  Joints joints{};
  int32_t count = 0;
  EXPECT_EQ(frusta_hand_joints_from_pose(&def, layout, &palm, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                         joints.data(), FRUSTA_XR_JOINT_COUNT, &count),
            FRUSTA_OK)
      << frusta_last_error();
  EXPECT_EQ(count, layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT);
  return joints;
}

int32_t count_of(int32_t layout) {
  return layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT;
}

// |q1 - q2| up to the sign of the quaternion
double quaternion_distance(const double a[4], const double b[4]) {
  double minus = 0.0, plus = 0.0;
  for (int k = 0; k < 4; ++k) {
    minus += (a[k] - b[k]) * (a[k] - b[k]);
    plus += (a[k] + b[k]) * (a[k] + b[k]);
  }
  return std::sqrt(std::min(minus, plus));
}

TEST_F(capiTracking, JointsOfAPoseFitBackToThatPoseInBothLayoutsAndSides) {
  std::mt19937_64 rng(19);
  for (int32_t layout : {FRUSTA_JOINT_LAYOUT_XR, FRUSTA_JOINT_LAYOUT_KEYPOINTS})
    for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT}) {
      const frusta_hand_def def = sized_def(side, 0.17, 0.078);
      ScopedFitter fitter(def, layout);
      for (int trial = 0; trial < 20; ++trial) {
        const frusta_pose palm = random_pose(rng);
        const Angles angles = interior_angles(def, rng);
        const Joints joints = joints_of(def, layout, palm, angles);
        frusta_hand_fit fit = blank_fit();
        ASSERT_EQ(frusta_hand_fitter_fit(fitter.get(), joints.data(), count_of(layout), nullptr, &fit),
                  FRUSTA_OK)
            << frusta_last_error();
        EXPECT_EQ(fit.palm_flags, 0);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(fit.palm.position[k], palm.position[k], 1e-9);
        EXPECT_LT(quaternion_distance(fit.palm.rotation, palm.rotation), 1e-9);
        for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) EXPECT_NEAR(fit.angles[j], angles[j], 1e-9);
        for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
          EXPECT_EQ(fit.finger_flags[f], 0);
          EXPECT_LT(fit.finger_residual[f], 1e-9);
        }
        EXPECT_LT(fit.palm_residual, 1e-9);
      }
    }
}

TEST_F(capiTracking, TheFitGoesStraightIntoAWorldHand) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world{};
  ASSERT_EQ(frusta_create_world(&world_def, &world), FRUSTA_OK);
  frusta_hand_id hand{};
  ASSERT_EQ(frusta_create_world_hand(world, &def, &hand), FRUSTA_OK);
  ScopedFitter fitter(def, FRUSTA_JOINT_LAYOUT_XR);
  std::mt19937_64 rng(20);
  const frusta_pose palm = random_pose(rng);
  const Angles angles = interior_angles(def, rng);
  const Joints joints = joints_of(def, FRUSTA_JOINT_LAYOUT_XR, palm, angles);
  // the joints' frame is 2 m above the world's origin
  const frusta_pose frame = {{0.0, 0.0, 2.0}, {0.0, 0.0, 0.0, 1.0}};
  frusta_hand_fit fit = blank_fit();
  ASSERT_EQ(frusta_hand_fitter_fit(fitter.get(), joints.data(), FRUSTA_XR_JOINT_COUNT, &frame, &fit),
            FRUSTA_OK);
  ASSERT_EQ(frusta_world_set_haptic(world, hand, &fit.palm, fit.angles, FRUSTA_HAND_JOINT_COUNT),
            FRUSTA_OK)
      << frusta_last_error();
  ASSERT_EQ(frusta_world_step(world), FRUSTA_OK);
  frusta_world_state state;
  state.struct_size = sizeof state;
  ASSERT_EQ(frusta_world_read(world, &state), FRUSTA_OK);
  frusta_world_hand out;
  out.struct_size = sizeof out;
  ASSERT_EQ(frusta_world_get_hand(world, hand, &out), FRUSTA_OK);
  EXPECT_NEAR(out.haptic_palm.position[2], palm.position[2] + 2.0, 1e-9);
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) EXPECT_NEAR(out.haptic_angles[j], angles[j], 1e-9);
  EXPECT_EQ(frusta_destroy_world(world), FRUSTA_OK);
}

TEST_F(capiTracking, CalibrationSizesADefFromJointsItsSideAndLimitsKept) {
  const frusta_hand_def truth = sized_def(FRUSTA_HAND_LEFT, 0.21, 0.095);
  std::mt19937_64 rng(21);
  std::vector<frusta_tracked_joint> frames;
  for (int i = 0; i < 10; ++i) {
    const Joints joints = joints_of(truth, FRUSTA_JOINT_LAYOUT_KEYPOINTS, random_pose(rng),
                                    interior_angles(truth, rng));
    frames.insert(frames.end(), joints.begin(), joints.begin() + FRUSTA_KEYPOINT_COUNT);
  }
  frusta_hand_def def = frusta_default_hand_def();
  def.side = FRUSTA_HAND_LEFT;
  def.joint_max[0][0] = 1.0;
  ASSERT_EQ(frusta_calibrate_hand_def(frames.data(), 10, FRUSTA_JOINT_LAYOUT_KEYPOINTS, &def), FRUSTA_OK)
      << frusta_last_error();
  EXPECT_NEAR(def.hand_length, 0.21, 1e-9);
  EXPECT_NEAR(def.hand_breadth, 0.095, 1e-9);
  EXPECT_EQ(def.side, FRUSTA_HAND_LEFT);
  EXPECT_EQ(def.joint_max[0][0], 1.0);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
      EXPECT_NEAR(def.segment_length[f][s], truth.segment_length[f][s], 1e-9);
  frusta_hand_id hand{};
  ASSERT_EQ(frusta_create_hand(&def, &hand), FRUSTA_OK);
  EXPECT_EQ(frusta_destroy_hand(hand), FRUSTA_OK);
}

// ---------------------------------------------------------------- error paths

TEST_F(capiTracking, CreateRefusesEachBadArgumentByName) {
  const frusta_hand_def def = frusta_default_hand_def();
  frusta_hand_fit_def fit_def = frusta_default_hand_fit_def();
  frusta_hand_fitter_id id{};
  ExpectError(frusta_create_hand_fitter(nullptr, &fit_def, &id), FRUSTA_ERROR_NULL_POINTER, "def");
  ExpectError(frusta_create_hand_fitter(&def, nullptr, &id), FRUSTA_ERROR_NULL_POINTER, "fit_def");
  ExpectError(frusta_create_hand_fitter(&def, &fit_def, nullptr), FRUSTA_ERROR_NULL_POINTER, "out_fitter");
  frusta_hand_def bad_hand = def;
  bad_hand.segment_length[1][2] = kNaN;
  ExpectError(frusta_create_hand_fitter(&bad_hand, &fit_def, &id), FRUSTA_ERROR_NOT_FINITE,
              "hand_def.segment_length[1][2]");
  frusta_hand_fit_def bad = fit_def;
  bad.struct_size = 0;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_STRUCT_SIZE, "frusta_hand_fit_def");
  bad = fit_def;
  bad.internal_value = 0;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_DEF_NOT_DEFAULTED,
              "frusta_hand_fit_def");
  bad = fit_def;
  bad.layout = 2;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_OUT_OF_RANGE, "hand_fit_def.layout");
  bad = fit_def;
  bad.require_tracked = 2;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_OUT_OF_RANGE,
              "hand_fit_def.require_tracked");
  bad = fit_def;
  bad.max_iterations = 0;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_OUT_OF_RANGE,
              "hand_fit_def.max_iterations");
  bad = fit_def;
  bad.orientation_weight = -0.1;
  ExpectError(frusta_create_hand_fitter(&def, &bad, &id), FRUSTA_ERROR_OUT_OF_RANGE,
              "hand_fit_def.orientation_weight");
  EXPECT_TRUE(FRUSTA_IS_NULL(id));
}

TEST_F(capiTracking, AStaleOrNullFitterIsRefusedAndNeverValid) {
  const frusta_hand_def def = frusta_default_hand_def();
  const frusta_hand_fit_def fit_def = frusta_default_hand_fit_def();
  frusta_hand_fitter_id id{};
  ASSERT_EQ(frusta_create_hand_fitter(&def, &fit_def, &id), FRUSTA_OK);
  EXPECT_EQ(frusta_hand_fitter_is_valid(id), 1);
  ASSERT_EQ(frusta_destroy_hand_fitter(id), FRUSTA_OK);
  EXPECT_EQ(frusta_hand_fitter_is_valid(id), 0);
  ExpectError(frusta_destroy_hand_fitter(id), FRUSTA_ERROR_STALE_ID, "hand fitter");
  const Joints joints{};
  frusta_hand_fit fit = blank_fit();
  ExpectError(frusta_hand_fitter_fit(id, joints.data(), FRUSTA_XR_JOINT_COUNT, nullptr, &fit),
              FRUSTA_ERROR_STALE_ID, "hand fitter");
  ExpectError(frusta_hand_fitter_fit(frusta_hand_fitter_id{}, joints.data(), FRUSTA_XR_JOINT_COUNT,
                                     nullptr, &fit),
              FRUSTA_ERROR_NULL_ID, "hand fitter");
  EXPECT_EQ(frusta_hand_fitter_is_valid(frusta_hand_fitter_id{}), 0);
}

TEST_F(capiTracking, FitRefusesBadSamplesByJointAndFieldAndKeepsItsHistory) {
  const frusta_hand_def def = frusta_default_hand_def();
  ScopedFitter fitter(def, FRUSTA_JOINT_LAYOUT_KEYPOINTS);
  std::mt19937_64 rng(22);
  const frusta_pose palm = random_pose(rng);
  const Joints good = joints_of(def, FRUSTA_JOINT_LAYOUT_KEYPOINTS, palm, interior_angles(def, rng));
  frusta_hand_fit first = blank_fit();
  ASSERT_EQ(frusta_hand_fitter_fit(fitter.get(), good.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &first),
            FRUSTA_OK);

  frusta_hand_fit out = blank_fit();
  out.palm_flags = 12345;
  ExpectError(frusta_hand_fitter_fit(fitter.get(), nullptr, FRUSTA_KEYPOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_NULL_POINTER, "joints");
  ExpectError(frusta_hand_fitter_fit(fitter.get(), good.data(), FRUSTA_KEYPOINT_COUNT, nullptr, nullptr),
              FRUSTA_ERROR_NULL_POINTER, "out");
  // a keypoint fitter given OpenXR's 26 joints
  ExpectError(frusta_hand_fitter_fit(fitter.get(), good.data(), FRUSTA_XR_JOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_OUT_OF_RANGE, "count is 26, must be 21");
  frusta_hand_fit wrong_size = blank_fit();
  wrong_size.struct_size = sizeof wrong_size - 8;
  ExpectError(frusta_hand_fitter_fit(fitter.get(), good.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &wrong_size),
              FRUSTA_ERROR_STRUCT_SIZE, "frusta_hand_fit");
  const frusta_pose bad_frame = {{0.0, kNaN, 0.0}, {0.0, 0.0, 0.0, 1.0}};
  ExpectError(frusta_hand_fitter_fit(fitter.get(), good.data(), FRUSTA_KEYPOINT_COUNT, &bad_frame, &out),
              FRUSTA_ERROR_NOT_FINITE, "frame.position");
  Joints bad = good;
  bad[7].position[2] = kNaN;
  ExpectError(frusta_hand_fitter_fit(fitter.get(), bad.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_NOT_FINITE, "joints[7].position");
  bad = good;
  bad[20].position[0] = 2e6;
  ExpectError(frusta_hand_fitter_fit(fitter.get(), bad.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_OUT_OF_RANGE, "joints[20].position");
  bad = good;
  bad[3].flags = 0x40;
  ExpectError(frusta_hand_fitter_fit(fitter.get(), bad.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_OUT_OF_RANGE, "joints[3].flags");
  bad = good;
  bad[4].flags |= FRUSTA_JOINT_ORIENTATION_VALID;
  std::memset(bad[4].rotation, 0, sizeof bad[4].rotation);
  ExpectError(frusta_hand_fitter_fit(fitter.get(), bad.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &out),
              FRUSTA_ERROR_OUT_OF_RANGE, "joints[4].rotation");
  EXPECT_EQ(out.palm_flags, 12345);  // nothing written

  // nothing changed: a sample without joints gives the first fit back, held
  const Joints none{};
  ASSERT_EQ(frusta_hand_fitter_fit(fitter.get(), none.data(), FRUSTA_KEYPOINT_COUNT, nullptr, &out),
            FRUSTA_OK);
  EXPECT_EQ(out.palm_flags, FRUSTA_FIT_HELD);
  EXPECT_EQ(std::memcmp(&out.palm, &first.palm, sizeof out.palm), 0);
  EXPECT_EQ(std::memcmp(out.angles, first.angles, sizeof out.angles), 0);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) EXPECT_EQ(out.finger_flags[f], FRUSTA_FIT_HELD);
}

TEST_F(capiTracking, JointsFromPoseFollowsTheOutputArrayRuleAndRefusesByName) {
  const frusta_hand_def def = frusta_default_hand_def();
  const frusta_pose palm = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}};
  const Angles angles{};
  Joints out{};
  int32_t count = -1;
  ASSERT_EQ(frusta_hand_joints_from_pose(&def, FRUSTA_JOINT_LAYOUT_XR, &palm, angles.data(),
                                         FRUSTA_HAND_JOINT_COUNT, nullptr, 0, &count),
            FRUSTA_OK);
  EXPECT_EQ(count, FRUSTA_XR_JOINT_COUNT);
  ASSERT_EQ(frusta_hand_joints_from_pose(&def, FRUSTA_JOINT_LAYOUT_KEYPOINTS, &palm, angles.data(),
                                         FRUSTA_HAND_JOINT_COUNT, out.data(), 3, &count),
            FRUSTA_OK);
  EXPECT_EQ(count, FRUSTA_KEYPOINT_COUNT);
  EXPECT_EQ(out[3].flags, 0);  // only three written
  EXPECT_EQ(out[0].flags, FRUSTA_JOINT_POSITION_VALID | FRUSTA_JOINT_POSITION_TRACKED);
  ExpectError(frusta_hand_joints_from_pose(&def, 5, &palm, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                           out.data(), 26, &count),
              FRUSTA_ERROR_OUT_OF_RANGE, "layout is 5");
  ExpectError(frusta_hand_joints_from_pose(&def, 0, nullptr, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                           out.data(), 26, &count),
              FRUSTA_ERROR_NULL_POINTER, "palm");
  ExpectError(frusta_hand_joints_from_pose(&def, 0, &palm, angles.data(), 19, out.data(), 26, &count),
              FRUSTA_ERROR_OUT_OF_RANGE, "count");
  ExpectError(frusta_hand_joints_from_pose(&def, 0, &palm, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                           nullptr, 26, &count),
              FRUSTA_ERROR_NULL_POINTER, "out");
  ExpectError(frusta_hand_joints_from_pose(&def, 0, &palm, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                           out.data(), -1, &count),
              FRUSTA_ERROR_OUT_OF_RANGE, "capacity");
  ExpectError(frusta_hand_joints_from_pose(&def, 0, &palm, angles.data(), FRUSTA_HAND_JOINT_COUNT,
                                           out.data(), 26, nullptr),
              FRUSTA_ERROR_NULL_POINTER, "out_count");
}

TEST_F(capiTracking, CalibrationRefusesByNameAndLeavesTheDefAsItWas) {
  const frusta_hand_def before = frusta_default_hand_def();
  frusta_hand_def def = before;
  std::mt19937_64 rng(23);
  const Joints joints = joints_of(def, FRUSTA_JOINT_LAYOUT_XR, random_pose(rng), interior_angles(def, rng));
  ExpectError(frusta_calibrate_hand_def(nullptr, 1, 0, &def), FRUSTA_ERROR_NULL_POINTER, "frames");
  ExpectError(frusta_calibrate_hand_def(joints.data(), 1, 0, nullptr), FRUSTA_ERROR_NULL_POINTER, "def");
  ExpectError(frusta_calibrate_hand_def(joints.data(), 0, 0, &def), FRUSTA_ERROR_OUT_OF_RANGE,
              "frame_count is 0, must be 1..65536");
  ExpectError(frusta_calibrate_hand_def(joints.data(), 1, -1, &def), FRUSTA_ERROR_OUT_OF_RANGE, "layout");
  Joints bad = joints;
  bad[12].position[1] = std::numeric_limits<double>::infinity();
  ExpectError(frusta_calibrate_hand_def(bad.data(), 1, 0, &def), FRUSTA_ERROR_NOT_FINITE,
              "frames[12].position");
  bad = joints;
  for (int i : {1, 12}) bad[static_cast<size_t>(i)].flags = 0;  // the wrist and the middle MCP
  ExpectError(frusta_calibrate_hand_def(bad.data(), 1, 0, &def), FRUSTA_ERROR_OUT_OF_RANGE,
              "the middle finger's MCP and PIP joints");
  // the palm's joints (wrist, thumb CMC, MCPs) all missing: neither its length nor breadth
  bad = joints;
  for (int i : {1, 2, 7, 17, 22}) bad[static_cast<size_t>(i)].flags = 0;
  ExpectError(frusta_calibrate_hand_def(bad.data(), 1, 0, &def), FRUSTA_ERROR_OUT_OF_RANGE,
              "the palm's joints");
  frusta_hand_def hand_built = def;
  hand_built.internal_value = 0;
  ExpectError(frusta_calibrate_hand_def(joints.data(), 1, 0, &hand_built), FRUSTA_ERROR_DEF_NOT_DEFAULTED,
              "frusta_hand_def");
  EXPECT_EQ(std::memcmp(&def, &before, sizeof def), 0);
}

}  // namespace
}  // namespace frusta
