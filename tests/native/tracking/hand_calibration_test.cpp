// SPDX-License-Identifier: MIT
#include "tracking/hand_calibration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "core/error.h"
#include "scenes/random_hands.h"

namespace frusta {
namespace {

constexpr int32_t kXr = FRUSTA_JOINT_LAYOUT_XR;
constexpr int32_t kKeypoints = FRUSTA_JOINT_LAYOUT_KEYPOINTS;

// seconds x rate frames of a hand moving through random poses, each joint with
// Gaussian noise of sigma metres
std::vector<TrackedJoint> recording(const HandDef& def, int32_t layout, int frames, double sigma,
                                    std::uint64_t seed) {
  const HandModel model = make_hand_model(def);
  std::mt19937_64 rng(seed);
  const int count = joint_count(layout);
  std::vector<TrackedJoint> out;
  for (int i = 0; i < frames; ++i) {
    auto joints = scenes::tracked_joints(model, scenes::random_hand_state(model, rng), layout);
    scenes::add_noise(joints.data(), count, sigma, rng);
    out.insert(out.end(), joints.begin(), joints.begin() + count);
  }
  return out;
}

frusta_result calibrate(const std::vector<TrackedJoint>& frames, int32_t layout, HandDef* def) {
  const int count = joint_count(layout);
  const int n = static_cast<int>(frames.size()) / count;
  HandCalibration calibration(layout, n);
  for (int i = 0; i < n; ++i) calibration.add_frame(frames.data() + i * count);
  return calibration.size(def);
}

struct Size {
  double length, breadth;
};

// Acceptance: 2 s of tracking at 90 Hz with 2 mm noise size the hand within 2 %.
TEST(HandCalibration, TwoSecondsOfNoisyTrackingSizeTheHandWithinTwoPercent) {
  const Size sizes[] = {{0.15, 0.068}, {0.175, 0.08}, {0.19, 0.085}, {0.21, 0.095}, {0.23, 0.105}};
  std::uint64_t seed = 100;
  for (int32_t layout : {kXr, kKeypoints})
    for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT})
      for (const Size& size : sizes) {
        const HandDef truth = scenes::sized_hand_def(side, size.length, size.breadth);
        const std::vector<TrackedJoint> frames = recording(truth, layout, 180, 0.002, ++seed);
        HandDef def = default_hand_def();
        def.side = side;
        ASSERT_EQ(calibrate(frames, layout, &def), FRUSTA_OK) << last_error_message();
        const double length_error = def.hand_length / size.length - 1.0;
        const double breadth_error = def.hand_breadth / size.breadth - 1.0;
        std::printf("%s %s %.3f x %.3f m: length %+.2f %%, breadth %+.2f %%\n",
                    layout == kXr ? "xr" : "keypoints", side ? "left" : "right", size.length,
                    size.breadth, 100.0 * length_error, 100.0 * breadth_error);
        EXPECT_LT(std::fabs(length_error), 0.02);
        EXPECT_LT(std::fabs(breadth_error), 0.02);
        EXPECT_EQ(def.side, side);
        EXPECT_EQ(check_hand_def(def), FRUSTA_OK);
        for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
          for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
            EXPECT_NEAR(def.segment_length[f][s], truth.segment_length[f][s], 0.0015)
                << "finger " << f << " segment " << s;
      }
}

TEST(HandCalibration, ExactJointsGiveTheExactDef) {
  const HandDef truth = scenes::sized_hand_def(FRUSTA_HAND_LEFT, 0.2, 0.09);
  for (int32_t layout : {kXr, kKeypoints}) {
    const std::vector<TrackedJoint> frames = recording(truth, layout, 3, 0.0, 7);
    HandDef def = default_hand_def();
    def.side = FRUSTA_HAND_LEFT;
    def.joint_max[1][1] = 1.0;  // limits are kept
    ASSERT_EQ(calibrate(frames, layout, &def), FRUSTA_OK);
    EXPECT_NEAR(def.hand_length, 0.2, 1e-12);
    EXPECT_NEAR(def.hand_breadth, 0.09, 1e-12);
    EXPECT_EQ(def.joint_max[1][1], 1.0);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
        EXPECT_NEAR(def.segment_length[f][s], truth.segment_length[f][s], 1e-12);
  }
}

// A hand is not its proportions: a palm a tenth longer than the anthropometry's is
// measured as it is, and the hand's length with it.
TEST(HandCalibration, APalmLongerThanTheProportionsIsMeasuredAsItIs) {
  HandDef truth = scenes::sized_hand_def(FRUSTA_HAND_RIGHT, 0.19, 0.085);
  for (auto& base : truth.base_position) base[0] *= 1.1;
  const std::vector<TrackedJoint> frames = recording(truth, kXr, 4, 0.0, 11);
  HandDef def = default_hand_def();
  ASSERT_EQ(calibrate(frames, kXr, &def), FRUSTA_OK) << last_error_message();
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(def.base_position[f][k], truth.base_position[f][k], 1e-12);
  EXPECT_NEAR(def.hand_length, 0.19 + 0.1 * truth.base_position[FRUSTA_FINGER_MIDDLE][0] / 1.1, 1e-12);
  EXPECT_NEAR(def.hand_breadth, 0.085, 1e-12);
  EXPECT_NEAR(def.palm_length, truth.base_position[FRUSTA_FINGER_MIDDLE][0], 1e-12);
}

TEST(HandCalibration, AHandWhoseSizeCannotBeMeasuredLeavesTheDefUnchanged) {
  const HandDef truth = scenes::sized_hand_def(FRUSTA_HAND_RIGHT, 0.19, 0.085);
  std::vector<TrackedJoint> frames = recording(truth, kXr, 10, 0.0, 8);
  // the middle finger's tip never tracked
  for (int i = 0; i < 10; ++i) frames[static_cast<size_t>(i * 26 + chain_joint(kXr, 2, 3))].flags = 0;
  HandDef def = default_hand_def();
  const HandDef before = def;
  EXPECT_EQ(calibrate(frames, kXr, &def), FRUSTA_ERROR_OUT_OF_RANGE);
  EXPECT_NE(std::string(last_error_message()).find("the middle finger's DIP joint and tip"),
            std::string::npos) << last_error_message();
  EXPECT_EQ(def.hand_length, before.hand_length);
  // positions valid but inferred, not tracked, do not count either
  frames = recording(truth, kXr, 10, 0.0, 8);
  for (TrackedJoint& j : frames) j.flags &= ~FRUSTA_JOINT_POSITION_TRACKED;
  EXPECT_EQ(calibrate(frames, kXr, &def), FRUSTA_ERROR_OUT_OF_RANGE);
}

TEST(HandCalibration, ABoneNoFrameMeasuresKeepsItsProportionalLength) {
  const HandDef truth = scenes::sized_hand_def(FRUSTA_HAND_RIGHT, 0.2, 0.09);
  std::vector<TrackedJoint> frames = recording(truth, kKeypoints, 5, 0.0, 9);
  for (int i = 0; i < 5; ++i) frames[static_cast<size_t>(i * 21 + chain_joint(kKeypoints, 4, 3))].flags = 0;
  HandDef def = default_hand_def();
  ASSERT_EQ(calibrate(frames, kKeypoints, &def), FRUSTA_OK);
  EXPECT_NEAR(def.segment_length[4][2], truth.segment_length[4][2], 1e-12);  // proportional
  EXPECT_NEAR(def.segment_length[4][1], truth.segment_length[4][1], 1e-12);  // measured
}

// the mean of the middle half of three is the middle one (it was their mean once: one
// joint a kilometre off made a 670 km hand)
TEST(HandCalibration, OneBadFrameOfThreeIsOutvoted) {
  double samples[3] = {0.0401, 1e3, 0.0399};
  EXPECT_NEAR(bone_length(samples, 3), 0.0401, 1e-5);  // less a bias of sigma^2 / length
  double two[2] = {0.04, 0.041};
  EXPECT_NEAR(bone_length(two, 2), 0.0405, 0.0005);
}

TEST(HandCalibration, BoneLengthRemovesTheBiasOfNoiseAcrossTheBone) {
  std::mt19937_64 rng(10);
  std::normal_distribution<double> noise(0.0, 0.002);
  const double length = 0.02;  // a short bone: the bias is sigma^2 / length = 0.2 mm
  std::vector<double> raw;
  for (int i = 0; i < 20000; ++i) {
    const vec3 d(length + noise(rng) - noise(rng), noise(rng) - noise(rng), noise(rng) - noise(rng));
    raw.push_back(glm::length(d));
  }
  std::vector<double> sorted = raw;
  std::nth_element(sorted.begin(), sorted.begin() + 10000, sorted.end());
  EXPECT_GT(sorted[10000] - length, 0.00015);  // the plain median is biased
  EXPECT_NEAR(bone_length(raw.data(), static_cast<int>(raw.size())), length, 0.0001);
}

}  // namespace
}  // namespace frusta
