// SPDX-License-Identifier: MIT
#include "tracking/hand_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <vector>

#include "scenes/random_cases.h"
#include "core/error.h"
#include "scenes/random_hands.h"

namespace frusta {
namespace {

constexpr int32_t kXr = FRUSTA_JOINT_LAYOUT_XR;
constexpr int32_t kKeypoints = FRUSTA_JOINT_LAYOUT_KEYPOINTS;
constexpr std::uint64_t kSeed = 0x7a3c'6f17ULL;

HandFitOptions options_for(int32_t layout) {
  HandFitOptions o;
  o.layout = layout;
  return o;
}

const char* layout_name(int32_t layout) { return layout == kXr ? "xr" : "keypoints"; }

HandFit fit_once(HandFitter& fitter, const std::array<TrackedJoint, kMaxTrackedJoints>& joints) {
  HandFit fit;
  fitter.fit(joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  return fit;
}

struct Errors {
  double position = 0.0;  // metres
  double rotation = 0.0;  // radians
  double angle = 0.0;     // radians, the largest over the 20
};

Errors errors(const HandFit& fit, const HandState& truth) {
  Errors e;
  e.position = glm::length(fit.palm_position - truth.palm_position);
  e.rotation = scenes::rotation_angle(fit.palm_rotation, truth.palm_rotation);
  for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
    e.angle = std::max(e.angle, std::fabs(fit.angles[j] - truth.angles[j]));
  return e;
}

// Acceptance: random poses within the limits, both hands, hand sizes from a child's to a
// large adult's: forward kinematics -> joints -> a new fitter -> the same palm and angles.
TEST(HandFitProperty, RoundTripOfForwardKinematicsIsExactInBothLayouts) {
  const std::uint64_t cases = std::max<std::uint64_t>(scenes::property_case_count() / 100, 1);
  std::mt19937_64 rng(kSeed);
  for (int32_t layout : {kXr, kKeypoints}) {
    Errors worst;
    std::uint64_t worst_case = 0, failures = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
      const HandModel model =
          make_hand_model(scenes::random_hand_def(i % 2 ? FRUSTA_HAND_LEFT : FRUSTA_HAND_RIGHT, rng));
      const HandState truth = scenes::random_hand_state(model, rng);
      HandFitter fitter(model, options_for(layout));
      const HandFit fit = fit_once(fitter, scenes::tracked_joints(model, truth, layout));
      const Errors e = errors(fit, truth);
      const bool bad = !(e.position <= 1e-6 && e.rotation <= 1e-6 && e.angle <= 1e-6) ||
                       fit.palm_flags != 0 ||
                       std::any_of(fit.finger_flags.begin(), fit.finger_flags.end(),
                                   [](int32_t f) { return f != 0; });
      if (bad) ++failures;
      if (std::max({e.position, e.rotation, e.angle}) > std::max({worst.position, worst.rotation, worst.angle})) {
        worst = e;
        worst_case = i;
      }
    }
    std::printf("%s: %llu cases, worst palm %.3g m %.3g rad, worst angle %.3g rad (case %llu)\n",
                layout_name(layout), static_cast<unsigned long long>(cases), worst.position,
                worst.rotation, worst.angle, static_cast<unsigned long long>(worst_case));
    EXPECT_EQ(failures, 0u) << layout_name(layout) << ": worst case " << worst_case;
  }
}

TEST(HandFit, ResidualsOfExactJointsAreRounding) {
  std::mt19937_64 rng(kSeed + 1);
  const HandModel model = make_hand_model(scenes::random_hand_def(FRUSTA_HAND_LEFT, rng));
  const HandState truth = scenes::random_hand_state(model, rng);
  for (int32_t layout : {kXr, kKeypoints}) {
    HandFitter fitter(model, options_for(layout));
    const HandFit fit = fit_once(fitter, scenes::tracked_joints(model, truth, layout));
    EXPECT_LT(fit.palm_residual, 1e-9);
    for (double r : fit.finger_residual) EXPECT_LT(r, 1e-9);
  }
}

TEST(HandFit, PalmIsComposedWithTheJointsFrame) {
  std::mt19937_64 rng(kSeed + 2);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  HandFitter fitter(model, options_for(kXr));
  const vec3 frame_position(0.3, -1.0, 2.0);
  const glm::dquat frame_rotation = glm::angleAxis(0.7, glm::normalize(vec3(1.0, 2.0, -0.5)));
  HandFit fit;
  fitter.fit(scenes::tracked_joints(model, truth, kXr).data(), frame_position, frame_rotation, &fit);
  EXPECT_LT(glm::length(fit.palm_position - (frame_position + frame_rotation * truth.palm_position)),
            1e-9);
  EXPECT_LT(scenes::rotation_angle(fit.palm_rotation, frame_rotation * truth.palm_rotation), 1e-9);
}

// ---------------------------------------------------------------- missing joints

void set_missing(std::array<TrackedJoint, kMaxTrackedJoints>& joints, int index) {
  joints[static_cast<size_t>(index)].flags = 0;
  // what an invalid joint holds is not read
  joints[static_cast<size_t>(index)].position = vec3(std::nan(""));
}

class HandFitMissing : public ::testing::TestWithParam<int32_t> {
 protected:
  HandFitMissing()
      : model_(make_hand_model(scenes::sized_hand_def(FRUSTA_HAND_RIGHT, 0.18, 0.08))) {}
  int32_t layout() const { return GetParam(); }
  // Two poses a tracker sees one after the other: the second a few degrees from the
  // first, every flexion at least 0.15 rad (a joint bent by less has a twin bent the
  // other way that puts the joints beyond it in nearly the same place: a missing joint
  // there is told from its twin by the last fit, up to twice its bend)
  std::pair<HandState, HandState> poses(std::uint64_t seed) const {
    std::mt19937_64 rng(seed);
    HandState first = scenes::random_hand_state(model_, rng);
    HandState second = first;
    std::uniform_real_distribution<double> unit(0.0, 1.0), nudge(-0.05, 0.05);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int j = 1; j < 4; ++j) {
        const double lo = 0.15, hi = model_.fingers[f].joint_max[j];
        first.angles[f * 4 + j] = lo + unit(rng) * (hi - lo);
        second.angles[f * 4 + j] = std::clamp(first.angles[f * 4 + j] + nudge(rng), lo, hi);
      }
    second.palm_position += vec3(0.01, -0.02, 0.005);
    return {first, second};
  }
  HandModel model_;
};

// A joint that drops out while tracking: what the rest determines is fit exactly; what
// only it determined (a tip: the last flexion) keeps the last good value.
TEST_P(HandFitMissing, EachSingleJointMissingKeepsTheFitExactOrHeldAndSaysSo) {
  const auto [first, second] = poses(11);
  const int count = joint_count(layout());
  for (int missing = 0; missing < count; ++missing) {
    HandFitter fitter(model_, options_for(layout()));
    fit_once(fitter, scenes::tracked_joints(model_, first, layout()));
    auto joints = scenes::tracked_joints(model_, second, layout());
    set_missing(joints, missing);
    const HandFit fit = fit_once(fitter, joints);
    SCOPED_TRACE(::testing::Message() << layout_name(layout()) << " joint " << missing);
    EXPECT_EQ(fit.palm_flags, 0);
    EXPECT_LT(glm::length(fit.palm_position - second.palm_position), 1e-9);
    EXPECT_LT(scenes::rotation_angle(fit.palm_rotation, second.palm_rotation), 1e-9);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      const bool is_tip = chain_joint(layout(), f, 3) == missing;
      EXPECT_EQ(fit.finger_flags[f], is_tip ? FRUSTA_FIT_PARTIAL : 0) << "finger " << f;
      for (int j = 0; j < 4; ++j) {
        // a missing tip leaves the last flexion as the first pose had it
        const double want = is_tip && j == 3 ? first.angles[f * 4 + j] : second.angles[f * 4 + j];
        EXPECT_NEAR(fit.angles[f * 4 + j], want, 1e-6) << "finger " << f << " angle " << j;
      }
    }
  }
}

TEST_P(HandFitMissing, AWholeFingerMissingHoldsItsLastGoodAngles) {
  const auto [first, second] = poses(21);
  for (int finger = 0; finger < FRUSTA_FINGER_COUNT; ++finger) {
    HandFitter fitter(model_, options_for(layout()));
    fit_once(fitter, scenes::tracked_joints(model_, first, layout()));
    auto joints = scenes::tracked_joints(model_, second, layout());
    // its moving joints (the first is the palm's)
    for (int k = 1; k < kChainPoints; ++k) set_missing(joints, chain_joint(layout(), finger, k));
    const HandFit fit = fit_once(fitter, joints);
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
      EXPECT_EQ(fit.finger_flags[f], f == finger ? FRUSTA_FIT_HELD : 0);
      const HandState& want = f == finger ? first : second;
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(fit.angles[f * 4 + j], want.angles[f * 4 + j], 1e-6);
    }
    EXPECT_EQ(fit.finger_residual[finger], 0.0);  // no joint to measure it by
  }
}

TEST_P(HandFitMissing, OneMovingJointIsTooFewAndTwoAreEnough) {
  const auto [first, second] = poses(31);
  const int finger = FRUSTA_FINGER_RING;
  for (int kept = 1; kept < kChainPoints; ++kept) {
    HandFitter fitter(model_, options_for(layout()));
    fit_once(fitter, scenes::tracked_joints(model_, first, layout()));
    auto one = scenes::tracked_joints(model_, second, layout());
    for (int k = 1; k < kChainPoints; ++k)
      if (k != kept) set_missing(one, chain_joint(layout(), finger, k));
    EXPECT_EQ(fit_once(fitter, one).finger_flags[finger], FRUSTA_FIT_HELD) << "kept " << kept;
  }
}

TEST_P(HandFitMissing, NoPalmJointHoldsThePalmAndEveryFinger) {
  const auto [first, second] = poses(41);
  HandFitter fitter(model_, options_for(layout()));
  fit_once(fitter, scenes::tracked_joints(model_, first, layout()));
  auto joints = scenes::tracked_joints(model_, second, layout());
  const PalmJoints palm = palm_joints(model_, layout());
  for (int i = 0; i < palm.count; ++i) set_missing(joints, palm.joints[static_cast<size_t>(i)].index);
  const HandFit fit = fit_once(fitter, joints);
  EXPECT_EQ(fit.palm_flags, FRUSTA_FIT_HELD);
  EXPECT_LT(glm::length(fit.palm_position - first.palm_position), 1e-9);
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    EXPECT_EQ(fit.finger_flags[f], FRUSTA_FIT_HELD);
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(fit.angles[f * 4 + j], first.angles[f * 4 + j], 1e-6);
  }
}

TEST_P(HandFitMissing, NothingEverTrackedIsTheRestPoseWithNoHistory) {
  HandFitter fitter(model_, options_for(layout()));
  std::array<TrackedJoint, kMaxTrackedJoints> joints{};  // all invalid
  const HandFit fit = fit_once(fitter, joints);
  EXPECT_EQ(fit.palm_flags, FRUSTA_FIT_HELD | FRUSTA_FIT_NO_HISTORY);
  EXPECT_EQ(fit.palm_position, vec3(0.0));
  for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f) {
    EXPECT_EQ(fit.finger_flags[f], FRUSTA_FIT_HELD | FRUSTA_FIT_NO_HISTORY);
    for (int j = 0; j < 4; ++j)
      EXPECT_EQ(fit.angles[f * 4 + j], std::clamp(0.0, model_.fingers[f].joint_min[j],
                                                  model_.fingers[f].joint_max[j]));
  }
}

std::string layout_param_name(const ::testing::TestParamInfo<int32_t>& layout) {
  return layout_name(layout.param);
}
INSTANTIATE_TEST_SUITE_P(Layouts, HandFitMissing, ::testing::Values(kXr, kKeypoints),
                         layout_param_name);

TEST(HandFit, TooFewPalmPointsFallBackOnTheWristsOrientation) {
  std::mt19937_64 rng(kSeed + 3);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  HandFitter fitter(model, options_for(kXr));
  auto joints = scenes::tracked_joints(model, truth, kXr);
  // the wrist alone of the palm-rigid joints
  const PalmJoints palm = palm_joints(model, kXr);
  for (int i = 0; i < palm.count; ++i)
    if (palm.joints[static_cast<size_t>(i)].index != 1) set_missing(joints, palm.joints[static_cast<size_t>(i)].index);
  const HandFit fit = fit_once(fitter, joints);
  EXPECT_EQ(fit.palm_flags, FRUSTA_FIT_ORIENTATION);
  EXPECT_LT(glm::length(fit.palm_position - truth.palm_position), 1e-9);
  EXPECT_LT(scenes::rotation_angle(fit.palm_rotation, truth.palm_rotation), 1e-9);
  // and without it the palm holds
  joints[1].flags = FRUSTA_JOINT_POSITION_VALID;
  EXPECT_EQ(fit_once(fitter, joints).palm_flags, FRUSTA_FIT_HELD);
}

// Orientations weighed in, from a weight too small to square (the hostile test's 1e-300
// once tripped a debug assertion) to a metre: the exact pose still.
TEST(HandFit, AnyOrientationWeightFitsExactJointsExactly) {
  std::mt19937_64 rng(kSeed + 6);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  for (double weight : {1e-300, 1e-160, 0.05, 1.0}) {
    HandFitOptions options = options_for(kXr);
    options.orientation_weight = weight;
    HandFitter fitter(model, options);
    const HandFit fit = fit_once(fitter, scenes::tracked_joints(model, truth, kXr));
    EXPECT_LT(glm::length(fit.palm_position - truth.palm_position), 1e-9) << weight;
    EXPECT_LT(scenes::rotation_angle(fit.palm_rotation, truth.palm_rotation), 1e-9) << weight;
  }
}

TEST(HandFit, RequireTrackedTreatsInferredJointsAsMissing) {
  std::mt19937_64 rng(kSeed + 4);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  auto joints = scenes::tracked_joints(model, truth, kXr);
  // the index finger's moving joints inferred, not tracked
  for (int k = 1; k < kChainPoints; ++k)
    joints[static_cast<size_t>(chain_joint(kXr, FRUSTA_FINGER_INDEX, k))].flags &=
        ~(FRUSTA_JOINT_POSITION_TRACKED | FRUSTA_JOINT_ORIENTATION_TRACKED);
  HandFitOptions options = options_for(kXr);
  HandFitter loose(make_hand_model(default_hand_def()), options);
  EXPECT_EQ(fit_once(loose, joints).finger_flags[FRUSTA_FINGER_INDEX], 0);
  options.require_tracked = true;
  HandFitter strict(model, options);
  EXPECT_EQ(fit_once(strict, joints).finger_flags[FRUSTA_FINGER_INDEX],
            FRUSTA_FIT_HELD | FRUSTA_FIT_NO_HISTORY);
}

// ---------------------------------------------------------------- limits and noise

TEST(HandFit, JointsBeyondTheLimitsAreClampedAndSaySo) {
  const HandModel model = make_hand_model(default_hand_def());
  HandDef loose_def = default_hand_def();
  // the same hand with room to bend the index finger backwards 60 degrees
  loose_def.joint_min[FRUSTA_FINGER_INDEX][1] = -1.2;
  const HandModel loose = make_hand_model(loose_def);
  HandState state;
  state.angles[FRUSTA_FINGER_INDEX * 4 + 1] = -1.0;
  HandFitter fitter(model, options_for(kXr));
  const HandFit fit = fit_once(fitter, scenes::tracked_joints(loose, state, kXr));
  EXPECT_EQ(fit.finger_flags[FRUSTA_FINGER_INDEX], FRUSTA_FIT_CLAMPED);
  EXPECT_EQ(fit.angles[FRUSTA_FINGER_INDEX * 4 + 1], model.fingers[FRUSTA_FINGER_INDEX].joint_min[1]);
  EXPECT_GT(fit.finger_residual[FRUSTA_FINGER_INDEX], 0.005);
  for (int f : {0, 2, 3, 4}) EXPECT_EQ(fit.finger_flags[f], 0);
}

TEST(HandFit, NoisyJointsGiveAnglesNearTheTruth) {
  std::mt19937_64 rng(kSeed + 5);
  for (int32_t layout : {kXr, kKeypoints}) {
    std::vector<double> errors;
    for (int i = 0; i < 200; ++i) {
      const HandModel model = make_hand_model(scenes::random_hand_def(i % 2, rng));
      const HandState truth = scenes::random_hand_state(model, rng);
      auto joints = scenes::tracked_joints(model, truth, layout);
      scenes::add_noise(joints.data(), joint_count(layout), 0.002, rng);
      HandFitter fitter(model, options_for(layout));
      const HandFit fit = fit_once(fitter, joints);
      for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) {
        ASSERT_TRUE(std::isfinite(fit.angles[j]));
        errors.push_back(std::fabs(fit.angles[j] - truth.angles[j]));
      }
      for (double r : fit.finger_residual) EXPECT_LT(r, 0.01);
    }
    std::sort(errors.begin(), errors.end());
    const double p50 = errors[errors.size() / 2];
    std::printf("%s, 2 mm noise: angle error p50 %.3f rad, p99 %.3f rad\n", layout_name(layout),
                p50, errors[errors.size() * 99 / 100]);
    EXPECT_LT(p50, 0.1);
  }
}


// ---------------------------------------------------------------- the One Euro filter

HandFitOptions filtered(double min_cutoff) {
  HandFitOptions o = options_for(kXr);
  o.filter_min_cutoff = min_cutoff;
  return o;
}

// A tracked hand's samples at 90 Hz: the palm drifting, fingers bending, with noise.
std::vector<std::array<TrackedJoint, kMaxTrackedJoints>> noisy_samples(const HandModel& model,
                                                                      int count) {
  std::mt19937_64 rng(kSeed + 20);
  HandState state = scenes::random_hand_state(model, rng);
  std::vector<std::array<TrackedJoint, kMaxTrackedJoints>> samples;
  for (int i = 0; i < count; ++i) {
    state.palm_position += vec3(0.002, -0.001, 0.0005);
    auto joints = scenes::tracked_joints(model, state, kXr);
    scenes::add_noise(joints.data(), joint_count(kXr), 0.002, rng);
    samples.push_back(joints);
  }
  return samples;
}

TEST(HandFitFilter, OffIsBitIdenticalToTheUntimedFit) {
  const HandModel model = make_hand_model(default_hand_def());
  HandFitter timed(model, filtered(0.0)), untimed(model, filtered(0.0));
  const vec3 frame_position(0.3, -1.0, 2.0);
  const glm::dquat frame_rotation = glm::angleAxis(0.7, glm::normalize(vec3(1.0, 2.0, -0.5)));
  const auto samples = noisy_samples(model, 50);
  for (size_t i = 0; i < samples.size(); ++i) {
    HandFit a, b;
    timed.fit_at(static_cast<double>(i) / 90.0, samples[i].data(), frame_position, frame_rotation, &a);
    untimed.fit(samples[i].data(), frame_position, frame_rotation, &b);
    ASSERT_EQ(std::memcmp(&a.palm_position, &b.palm_position, sizeof a.palm_position), 0) << i;
    ASSERT_EQ(std::memcmp(&a.palm_rotation, &b.palm_rotation, sizeof a.palm_rotation), 0) << i;
    ASSERT_EQ(std::memcmp(a.angles.data(), b.angles.data(), sizeof a.angles), 0) << i;
    ASSERT_EQ(a.palm_residual, b.palm_residual);
    ASSERT_EQ(a.finger_residual, b.finger_residual);
    ASSERT_EQ(a.palm_flags, b.palm_flags);
    ASSERT_EQ(a.finger_flags, b.finger_flags);
  }
}

TEST(HandFitFilter, AStillHandPassesUnchanged) {
  std::mt19937_64 rng(kSeed + 21);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  const auto joints = scenes::tracked_joints(model, truth, kXr);
  HandFitter fitter(model, HandFitOptions{});
  for (int i = 0; i < 100; ++i) {
    HandFit fit;
    fitter.fit_at(10.0 + i / 90.0, joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
    const Errors e = errors(fit, truth);
    ASSERT_LT(std::max({e.position, e.rotation, e.angle}), 1e-9) << i;
  }
}

TEST(HandFitFilter, ATimeNotAfterThePreviousIsRefusedNamingIt) {
  const HandModel model = make_hand_model(default_hand_def());
  HandFitter fitter(model, HandFitOptions{});
  const auto samples = noisy_samples(model, 2);
  HandFit fit;
  ASSERT_EQ(fitter.check_time(1.0), FRUSTA_OK);
  fitter.fit_at(1.0, samples[0].data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  for (double t : {1.0, 0.5, -1.0}) {
    EXPECT_EQ(fitter.check_time(t), FRUSTA_ERROR_OUT_OF_RANGE) << t;
    EXPECT_NE(std::strstr(last_error_message(), "time"), nullptr) << last_error_message();
  }
  EXPECT_EQ(fitter.check_time(std::nan("")), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_EQ(fitter.check_time(INFINITY), FRUSTA_ERROR_NOT_FINITE);
  EXPECT_EQ(fitter.check_time(std::nextafter(1.0, 2.0)), FRUSTA_OK);
  // an untimed fit restarts the filter: any time is next
  fitter.fit(samples[1].data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  EXPECT_EQ(fitter.check_time(-5.0), FRUSTA_OK);
}

// tracking lost, then found elsewhere: the fit is taken as it is, not dragged from the
// stale pose; without the loss the filter would drag it
TEST(HandFitFilter, AHeldFitRestartsTheFilter) {
  std::mt19937_64 rng(kSeed + 22);
  const HandModel model = make_hand_model(default_hand_def());
  HandState a = scenes::random_hand_state(model, rng), b = a;
  b.palm_position += vec3(0.2, 0.0, 0.0);
  for (int j = 1; j < FRUSTA_HAND_JOINT_COUNT; j += 4) b.angles[j] = a.angles[j] > 0.5 ? 0.1 : 0.9;
  const auto at_a = scenes::tracked_joints(model, a, kXr), at_b = scenes::tracked_joints(model, b, kXr);
  std::array<TrackedJoint, kMaxTrackedJoints> lost{};  // nothing present
  for (bool lose : {true, false}) {
    // the same samples unfiltered: what "taken as it is" means
    HandFitter fitter(model, HandFitOptions{}), plain(model, filtered(0.0));
    HandFit fit, raw;
    double t = 0.0;
    const auto both = [&](const std::array<TrackedJoint, kMaxTrackedJoints>& joints) {
      fitter.fit_at(t, joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
      plain.fit_at(t, joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &raw);
      t += 1.0 / 90.0;
    };
    for (int i = 0; i < 90; ++i) both(at_a);
    if (lose) {
      both(lost);
      EXPECT_EQ(fit.palm_flags, FRUSTA_FIT_HELD);
      EXPECT_LT(errors(fit, a).position, 1e-9);  // held: the last fit, as it was
    }
    both(at_b);
    double angle = 0.0;
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j)
      angle = std::max(angle, std::fabs(fit.angles[j] - raw.angles[j]));
    const double position = glm::length(fit.palm_position - raw.palm_position);
    if (lose) {
      EXPECT_EQ(position, 0.0);
      EXPECT_EQ(scenes::rotation_angle(fit.palm_rotation, raw.palm_rotation), 0.0);
      EXPECT_EQ(angle, 0.0);
    } else {
      EXPECT_GT(position, 0.05);  // dragged: the filter's lag
      EXPECT_GT(angle, 0.05);
    }
  }
}

// a held finger restarts its angles' filter alone
TEST(HandFitFilter, AHeldFingerRestartsItsAngles) {
  std::mt19937_64 rng(kSeed + 23);
  const HandModel model = make_hand_model(default_hand_def());
  HandState a = scenes::random_hand_state(model, rng), b = a;
  for (int j = 1; j < FRUSTA_HAND_JOINT_COUNT; j += 4) b.angles[j] = a.angles[j] > 0.5 ? 0.1 : 0.9;
  const auto at_a = scenes::tracked_joints(model, a, kXr), at_b = scenes::tracked_joints(model, b, kXr);
  auto index_lost = at_a;
  for (int k = 1; k < kChainPoints; ++k)
    set_missing(index_lost, chain_joint(kXr, FRUSTA_FINGER_INDEX, k));
  HandFitter fitter(model, HandFitOptions{});
  HandFit fit;
  double t = 0.0;
  for (int i = 0; i < 90; ++i, t += 1.0 / 90.0)
    fitter.fit_at(t, at_a.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  fitter.fit_at(t, index_lost.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  t += 1.0 / 90.0;
  EXPECT_EQ(fit.finger_flags[FRUSTA_FINGER_INDEX], FRUSTA_FIT_HELD);
  fitter.fit_at(t, at_b.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &fit);
  const int index_mcp = FRUSTA_FINGER_INDEX * 4 + 1, middle_mcp = FRUSTA_FINGER_MIDDLE * 4 + 1;
  EXPECT_NEAR(fit.angles[index_mcp], b.angles[index_mcp], 1e-6);              // taken as it is
  EXPECT_GT(std::fabs(fit.angles[middle_mcp] - b.angles[middle_mcp]), 0.05);  // filtered
}

// what the filter removes from a still hand's jitter, fit by fit
TEST(HandFitFilter, ReducesAStillHandsJitter) {
  std::mt19937_64 rng(kSeed + 24);
  const HandModel model = make_hand_model(default_hand_def());
  const HandState truth = scenes::random_hand_state(model, rng);
  for (double sigma : {0.001, 0.002, 0.005}) {
    double raw = 0.0, smooth = 0.0;
    HandFitter plain(model, filtered(0.0)), filter(model, HandFitOptions{});
    for (int i = 0; i < 900; ++i) {
      auto joints = scenes::tracked_joints(model, truth, kXr);
      scenes::add_noise(joints.data(), joint_count(kXr), sigma, rng);
      HandFit a, b;
      plain.fit_at(i / 90.0, joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &a);
      filter.fit_at(i / 90.0, joints.data(), vec3(0.0), glm::dquat(1, 0, 0, 0), &b);
      if (i < 90) continue;
      raw += std::pow(errors(a, truth).position, 2);
      smooth += std::pow(errors(b, truth).position, 2);
    }
    const double factor = std::sqrt(raw / smooth);
    std::printf("a still hand, %.0f mm noise: the palm's jitter reduced %.1f times\n", 1e3 * sigma,
                factor);
    EXPECT_GT(factor, 3.0);
  }
}

}  // namespace
}  // namespace frusta
