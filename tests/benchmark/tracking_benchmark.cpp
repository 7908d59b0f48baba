// SPDX-License-Identifier: MIT
// Tracked joints to a hand (native/src/tracking): the time of one fit, in both layouts,
// next to its error against the exact palm and angles that made the joints, under
// Gaussian noise of sigma 0, 1, 2 and 5 mm on every joint coordinate (and with a tenth
// of the joints missing); calibration's time next to its hand length and breadth error.
// Hands are random: both sides, lengths 0.14..0.23 m, poses uniform within the joint
// limits (tests/scenes/random_hands.h, fixed seed). BM_FitTimed: a timed fit with the
// One Euro filter off and on (the default def's), to show what the filter costs. Counters:
//   us_per_fit                 CPU microseconds per fit of one hand
//   angle_error_p50, _p99      radians, over all 20 angles of every case
//   flexion_p99, abduction_p99 radians, the flexions and the abductions alone
//   palm_position_p50 (m), palm_rotation_p50 (rad), finger_residual_p50 (m)
//   us_per_calibration, length_error_max, breadth_error_max (fractions)
// tools/bench runs this binary with --benchmark_format=json.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "scenes/random_cases.h"
#include "scenes/random_hands.h"
#include "tracking/hand_calibration.h"
#include "tracking/hand_fit.h"

namespace frusta {
namespace {

constexpr std::size_t kCases = 512;

struct Batch {
  std::vector<std::unique_ptr<HandFitter>> fitters;
  std::vector<HandState> truths;
  std::vector<std::array<TrackedJoint, kMaxTrackedJoints>> joints;
};

// kCases hands, each with a fitter and one noisy sample; `missing` of every 100 joints
// dropped at random
Batch make_batch(int32_t layout, double sigma, int missing) {
  std::mt19937_64 rng(scenes::kBenchmarkSeed + static_cast<std::uint64_t>(layout));
  std::uniform_int_distribution<int> percent(0, 99);
  HandFitOptions options;
  options.layout = layout;
  Batch b;
  for (std::size_t i = 0; i < kCases; ++i) {
    const HandModel model = make_hand_model(scenes::random_hand_def(static_cast<int>(i % 2), rng));
    b.truths.push_back(scenes::random_hand_state(model, rng));
    b.joints.push_back(scenes::tracked_joints(model, b.truths.back(), layout));
    scenes::add_noise(b.joints.back().data(), joint_count(layout), sigma, rng);
    for (int j = 0; j < joint_count(layout); ++j)
      if (percent(rng) < missing) b.joints.back()[static_cast<std::size_t>(j)].flags = 0;
    b.fitters.push_back(std::make_unique<HandFitter>(model, options));
  }
  return b;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// range(0): sigma in micrometres; range(1): percent of joints missing
void BM_Fit(benchmark::State& state, int32_t layout) {
  const double sigma = static_cast<double>(state.range(0)) * 1e-6;
  Batch b = make_batch(layout, sigma, static_cast<int>(state.range(1)));
  HandFit fit;
  const vec3 origin(0.0);
  const glm::dquat identity(1.0, 0.0, 0.0, 0.0);
  for (auto _ : state) {
    for (std::size_t i = 0; i < kCases; ++i) {
      b.fitters[i]->fit(b.joints[i].data(), origin, identity, &fit);
      benchmark::DoNotOptimize(fit.angles[0]);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(kCases) * state.iterations());
  state.counters["us_per_fit"] = benchmark::Counter(
      static_cast<double>(kCases) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);

  // the errors, each sample fit by a fitter that saw it first (a held value would be
  // the rest pose's: the missing-joint rows measure that too)
  b = make_batch(layout, sigma, static_cast<int>(state.range(1)));
  std::vector<double> angles, flexions, abductions, positions, rotations, residuals;
  for (std::size_t i = 0; i < kCases; ++i) {
    b.fitters[i]->fit(b.joints[i].data(), origin, identity, &fit);
    const HandState& truth = b.truths[i];
    for (int j = 0; j < FRUSTA_HAND_JOINT_COUNT; ++j) {
      const double e = std::fabs(fit.angles[static_cast<std::size_t>(j)] - truth.angles[static_cast<std::size_t>(j)]);
      angles.push_back(e);
      (j % FRUSTA_JOINTS_PER_FINGER == 0 ? abductions : flexions).push_back(e);
    }
    positions.push_back(glm::length(fit.palm_position - truth.palm_position));
    rotations.push_back(scenes::rotation_angle(fit.palm_rotation, truth.palm_rotation));
    for (double r : fit.finger_residual) residuals.push_back(r);
  }
  state.counters["angle_error_p50"] = percentile(angles, 0.5);
  state.counters["angle_error_p99"] = percentile(angles, 0.99);
  state.counters["flexion_p99"] = percentile(flexions, 0.99);
  state.counters["abduction_p99"] = percentile(abductions, 0.99);
  state.counters["palm_position_p50"] = percentile(positions, 0.5);
  state.counters["palm_rotation_p50"] = percentile(rotations, 0.5);
  state.counters["finger_residual_p50"] = percentile(residuals, 0.5);
}

// 2 s at 90 Hz of a hand moving through random poses, 2 mm noise: sizes across the
// adult range and a child's, both sides
void BM_Calibrate(benchmark::State& state, int32_t layout) {
  constexpr int kFrames = 180;
  constexpr double kSizes[][2] = {{0.15, 0.068}, {0.19, 0.085}, {0.23, 0.105}};
  struct Recording {
    HandDef truth;
    std::vector<TrackedJoint> frames;
  };
  std::vector<Recording> recordings;
  std::mt19937_64 rng(scenes::kBenchmarkSeed + 7);
  const int count = joint_count(layout);
  for (int side : {FRUSTA_HAND_RIGHT, FRUSTA_HAND_LEFT})
    for (const auto& size : kSizes) {
      Recording r;
      r.truth = scenes::sized_hand_def(side, size[0], size[1]);
      const HandModel model = make_hand_model(r.truth);
      for (int f = 0; f < kFrames; ++f) {
        auto joints = scenes::tracked_joints(model, scenes::random_hand_state(model, rng), layout);
        scenes::add_noise(joints.data(), count, 0.002, rng);
        r.frames.insert(r.frames.end(), joints.begin(), joints.begin() + count);
      }
      recordings.push_back(std::move(r));
    }
  double length_error = 0.0, breadth_error = 0.0;
  for (auto _ : state) {
    for (const Recording& r : recordings) {
      HandCalibration calibration(layout, kFrames);
      for (int f = 0; f < kFrames; ++f) calibration.add_frame(r.frames.data() + f * count);
      HandDef def = default_hand_def();
      def.side = r.truth.side;
      if (calibration.size(&def) != FRUSTA_OK) state.SkipWithError("calibration refused");
      length_error = std::max(length_error, std::fabs(def.hand_length / r.truth.hand_length - 1.0));
      breadth_error = std::max(breadth_error, std::fabs(def.hand_breadth / r.truth.hand_breadth - 1.0));
    }
  }
  state.counters["us_per_calibration"] = benchmark::Counter(
      static_cast<double>(recordings.size()) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["length_error_max"] = length_error;
  state.counters["breadth_error_max"] = breadth_error;
}

// A timed fit (HandFitter::fit_at, 90 Hz samples), 2 mm noise: range(0) 0 the filter
// off, 1 the default One Euro filter; its cost is the difference of the two rows
void BM_FitTimed(benchmark::State& state, int32_t layout) {
  Batch b = make_batch(layout, 0.002, 0);
  HandFitOptions options;
  options.layout = layout;
  if (state.range(0) == 0) options.filter_min_cutoff = 0.0;
  for (std::size_t i = 0; i < kCases; ++i)
    b.fitters[i] = std::make_unique<HandFitter>(make_hand_model(default_hand_def()), options);
  HandFit fit;
  const vec3 origin(0.0);
  const glm::dquat identity(1.0, 0.0, 0.0, 0.0);
  double time = 0.0;
  for (auto _ : state) {
    time += 1.0 / 90.0;
    for (std::size_t i = 0; i < kCases; ++i) {
      b.fitters[i]->fit_at(time, b.joints[i].data(), origin, identity, &fit);
      benchmark::DoNotOptimize(fit.angles[0]);
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(kCases) * state.iterations());
  state.counters["us_per_fit"] = benchmark::Counter(
      static_cast<double>(kCases) * 1e-6,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// sigma 0, 1, 2, 5 mm; then 2 mm with a tenth of the joints missing
void fit_arguments(benchmark::internal::Benchmark* b) {
  for (int sigma_um : {0, 1000, 2000, 5000}) b->Args({sigma_um, 0});
  b->Args({2000, 10});
}

BENCHMARK_CAPTURE(BM_Fit, xr, FRUSTA_JOINT_LAYOUT_XR)->Apply(fit_arguments);
BENCHMARK_CAPTURE(BM_Fit, keypoints, FRUSTA_JOINT_LAYOUT_KEYPOINTS)->Apply(fit_arguments);
BENCHMARK_CAPTURE(BM_FitTimed, xr, FRUSTA_JOINT_LAYOUT_XR)->ArgName("filter")->Arg(0)->Arg(1);
BENCHMARK_CAPTURE(BM_Calibrate, xr, FRUSTA_JOINT_LAYOUT_XR)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Calibrate, keypoints, FRUSTA_JOINT_LAYOUT_KEYPOINTS)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace frusta
