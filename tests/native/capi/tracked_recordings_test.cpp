// SPDX-License-Identifier: MIT
// Real tracked hands (tests/data/tracked_hands: a Meta Quest 3's OpenXR joints, and
// MediaPipe's keypoints of six photographs) through the C ABI as a host would take them:
// a def calibrated from them, each sample fit (the Quest's in its target ray's frame),
// and the fits driving a world hand. Everything finite, no input refused, and the
// residuals printed: how far real hands lie from Frusta's hand model.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "capi_fixture.h"
#include "frusta/frusta.h"

namespace frusta {
namespace {

using capiTrackedRecordings = testing::CapiTest;

constexpr int32_t kAllFlags = FRUSTA_JOINT_ORIENTATION_VALID | FRUSTA_JOINT_POSITION_VALID |
                              FRUSTA_JOINT_ORIENTATION_TRACKED | FRUSTA_JOINT_POSITION_TRACKED;

// The data lines of a CSV file ('#' starts a comment line), each split at commas.
std::vector<std::vector<std::string>> read_csv(const std::string& name) {
  std::ifstream in(std::string(FRUSTA_TRACKED_HANDS_DIR) + "/" + name);
  EXPECT_TRUE(in) << name;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream s(line);
    std::string field;
    while (std::getline(s, field, ',')) fields.push_back(field);
    rows.push_back(fields);
  }
  return rows;
}

struct Sample {
  frusta_pose frame{{0, 0, 0}, {0, 0, 0, 1}};  // the joints' frame in the world
  std::array<frusta_tracked_joint, FRUSTA_XR_JOINT_COUNT> joints{};
};

// The Quest's frames: the target ray's pose, then 25 WebXR joints, which are OpenXR's
// 1..25 (the palm, 0, is missing)
std::vector<Sample> quest_samples() {
  std::vector<Sample> samples;
  for (const auto& row : read_csv("quest3_right_hand.csv")) {
    EXPECT_EQ(row.size(), 1u + 7u + 25u * 8u);
    if (row.size() != 208) continue;
    Sample s;
    auto at = [&](size_t i) { return std::stod(row[i]); };
    for (int k = 0; k < 3; ++k) s.frame.position[k] = at(1 + k);
    for (int k = 0; k < 4; ++k) s.frame.rotation[k] = at(4 + k);
    for (int j = 0; j < 25; ++j) {
      frusta_tracked_joint& out = s.joints[static_cast<size_t>(j + 1)];
      const size_t base = 8 + 8 * static_cast<size_t>(j);
      for (int k = 0; k < 3; ++k) out.position[k] = at(base + k);
      for (int k = 0; k < 4; ++k) out.rotation[k] = at(base + 3 + k);
      out.radius = at(base + 7);
      out.flags = kAllFlags;
    }
    samples.push_back(s);
  }
  return samples;
}

std::vector<Sample> mediapipe_samples() {
  std::vector<Sample> samples;
  for (const auto& row : read_csv("mediapipe_world_landmarks.csv")) {
    EXPECT_EQ(row.size(), 1u + 21u * 3u);
    if (row.size() != 64) continue;
    Sample s;
    for (int j = 0; j < FRUSTA_KEYPOINT_COUNT; ++j) {
      for (int k = 0; k < 3; ++k)
        s.joints[static_cast<size_t>(j)].position[k] = std::stod(row[1 + 3 * static_cast<size_t>(j) + k]);
      s.joints[static_cast<size_t>(j)].flags = FRUSTA_JOINT_POSITION_VALID | FRUSTA_JOINT_POSITION_TRACKED;
    }
    samples.push_back(s);
  }
  return samples;
}

struct Replay {
  frusta_hand_def def{};
  std::vector<frusta_hand_fit> fits;
  double mean_residual = 0.0;  // metres, over every finger of every sample
};

// A def of `side` calibrated from the samples, and every sample's fit.
Replay fit_all(const std::vector<Sample>& samples, int32_t layout, int side) {
  const int32_t count = layout == FRUSTA_JOINT_LAYOUT_XR ? FRUSTA_XR_JOINT_COUNT : FRUSTA_KEYPOINT_COUNT;
  Replay r;
  r.def = frusta_default_hand_def();
  r.def.side = side;
  std::vector<frusta_tracked_joint> frames;
  for (const Sample& s : samples) frames.insert(frames.end(), s.joints.begin(), s.joints.begin() + count);
  EXPECT_EQ(frusta_calibrate_hand_def(frames.data(), static_cast<int32_t>(samples.size()), layout, &r.def),
            FRUSTA_OK)
      << frusta_last_error();
  frusta_hand_fit_def fit_def = frusta_default_hand_fit_def();
  fit_def.layout = layout;
  frusta_hand_fitter_id fitter{};
  EXPECT_EQ(frusta_create_hand_fitter(&r.def, &fit_def, &fitter), FRUSTA_OK) << frusta_last_error();
  double sum = 0.0;
  for (const Sample& s : samples) {
    frusta_hand_fit fit;
    fit.struct_size = sizeof fit;
    EXPECT_EQ(frusta_hand_fitter_fit(fitter, s.joints.data(), count, &s.frame, &fit), FRUSTA_OK)
        << frusta_last_error();
    r.fits.push_back(fit);
    for (double residual : fit.finger_residual) sum += residual;
  }
  r.mean_residual = sum / (FRUSTA_FINGER_COUNT * static_cast<double>(samples.size()));
  EXPECT_EQ(frusta_destroy_hand_fitter(fitter), FRUSTA_OK);
  return r;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[static_cast<size_t>(p * static_cast<double>(v.size() - 1))];
}

// The fits drive a world hand, each held for `steps` steps: accepted, used, finite.
void drive_world(const Replay& r, int steps) {
  const frusta_world_def world_def = frusta_default_world_def();
  frusta_world_id world{};
  ASSERT_EQ(frusta_create_world(&world_def, &world), FRUSTA_OK);
  frusta_hand_id hand{};
  ASSERT_EQ(frusta_create_world_hand(world, &r.def, &hand), FRUSTA_OK) << frusta_last_error();
  for (const frusta_hand_fit& fit : r.fits) {
    ASSERT_EQ(frusta_world_set_haptic(world, hand, &fit.palm, fit.angles, FRUSTA_HAND_JOINT_COUNT),
              FRUSTA_OK)
        << frusta_last_error();
    for (int i = 0; i < steps; ++i) ASSERT_EQ(frusta_world_step(world), FRUSTA_OK);
    frusta_world_state state;
    state.struct_size = sizeof state;
    ASSERT_EQ(frusta_world_read(world, &state), FRUSTA_OK);
    EXPECT_EQ(state.rejected_inputs, 0);
    frusta_world_hand out;
    out.struct_size = sizeof out;
    ASSERT_EQ(frusta_world_get_hand(world, hand, &out), FRUSTA_OK);
    EXPECT_EQ(out.solved, 1);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(std::isfinite(out.graphic_palm.position[k]));
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) {
      EXPECT_TRUE(std::isfinite(out.graphic_angles[j]));
      EXPECT_NEAR(out.haptic_angles[j], fit.angles[j], 1e-12);  // the input the step used
    }
  }
  EXPECT_EQ(frusta_destroy_world(world), FRUSTA_OK);
}

// Prints the residuals; returns how many fingers a limit clamped.
int report(const char* what, const Replay& r) {
  std::vector<double> palm, fingers;
  int held = 0, clamped = 0;
  for (const frusta_hand_fit& fit : r.fits) {
    palm.push_back(fit.palm_residual);
    EXPECT_EQ(fit.palm_flags & FRUSTA_FIT_HELD, 0);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      fingers.push_back(fit.finger_residual[f]);
      held += (fit.finger_flags[f] & FRUSTA_FIT_HELD) != 0;
      clamped += (fit.finger_flags[f] & FRUSTA_FIT_CLAMPED) != 0;
      EXPECT_TRUE(std::isfinite(fit.finger_residual[f]));
    }
  }
  std::printf("%s: calibrated %.1f x %.1f mm; %zu samples: palm residual p50 %.1f mm max %.1f mm, "
              "finger residual p50 %.1f mm p99 %.1f mm max %.1f mm; %d fingers held, %d clamped\n",
              what, 1e3 * r.def.hand_length, 1e3 * r.def.hand_breadth, r.fits.size(),
              1e3 * percentile(palm, 0.5), 1e3 * percentile(palm, 1.0), 1e3 * percentile(fingers, 0.5),
              1e3 * percentile(fingers, 0.99), 1e3 * percentile(fingers, 1.0), held, clamped);
  return clamped;
}

TEST_F(capiTrackedRecordings, AQuest3sRightHandDrivesAWorldHand) {
  const std::vector<Sample> samples = quest_samples();
  ASSERT_EQ(samples.size(), 93u);
  const Replay right = fit_all(samples, FRUSTA_JOINT_LAYOUT_XR, FRUSTA_HAND_RIGHT);
  const Replay left = fit_all(samples, FRUSTA_JOINT_LAYOUT_XR, FRUSTA_HAND_LEFT);
  const int clamped = report("Quest 3 right hand as a right hand", right);
  report("Quest 3 right hand as a left hand", left);
  // the palm's joints placed where the runtime puts them: with the metacarpals' bases
  // at the anthropometry's 0.16 of the way to the MCPs, 264 of the 465 fingers clamped
  EXPECT_LT(clamped, 465 / 10);
  // OpenXR's axes and side agree with Frusta's: the right hand fits a right hand
  EXPECT_LT(right.mean_residual, 0.5 * left.mean_residual);
  EXPECT_GT(right.def.hand_length, 0.14);
  EXPECT_LT(right.def.hand_length, 0.23);
  drive_world(right, 11);  // 90 Hz tracking into a 1 kHz world
}

TEST_F(capiTrackedRecordings, MediaPipesKeypointsOfSixPhotographsDriveAWorldHand) {
  const std::vector<Sample> samples = mediapipe_samples();
  ASSERT_EQ(samples.size(), 6u);
  const Replay right = fit_all(samples, FRUSTA_JOINT_LAYOUT_KEYPOINTS, FRUSTA_HAND_RIGHT);
  const Replay left = fit_all(samples, FRUSTA_JOINT_LAYOUT_KEYPOINTS, FRUSTA_HAND_LEFT);
  report("MediaPipe keypoints as a right hand", right);
  report("MediaPipe keypoints as a left hand", left);
  const Replay& better = right.mean_residual < left.mean_residual ? right : left;
  std::printf("MediaPipe's hand fits a %s hand better\n", &better == &right ? "right" : "left");
  drive_world(better, 100);
}

}  // namespace
}  // namespace frusta
