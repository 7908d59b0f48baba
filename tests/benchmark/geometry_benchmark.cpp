// SPDX-License-Identifier: MIT
// Pair-test and constraint costs (nanoseconds per call) next to their errors against
// the exact reference, measured on the same pre-generated cases, plus a whole-hand
// forward kinematics with every segment end's Jacobian.
//
// Every benchmark runs over a batch of cases from tests/scenes/random_cases.h (fixed
// seed): "mix" is the tests' family mix, "hand" hand-like segments with spheres near
// them, "boundary" spheres within 1e-9..1e-3 m of touching. Counters:
//   ns_per_call          CPU nanoseconds per pair (per hand for kinematics)
//   false_positive_rate  reported contacts among true non-contacts (exact gap > margin)
//   false_negative_rate  missed contacts among true contacts (exact gap <= margin)
// tools/bench runs this binary with --benchmark_format=json.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "frusta/frusta.h"
#include "geometry/constraint.h"
#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "geometry/patent_test.h"
#include "geometry/segment_frame.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "scenes/random_cases.h"

namespace frusta {
namespace {

using scenes::Family;

// 4096 pairs: ~1 MB of frames and spheres, warm in L2 after the first pass
constexpr std::size_t kBatch = 4096;

enum class Scene { kMix, kHand, kBoundary };

struct Batch {
  std::vector<Segment> segments;
  std::vector<SegmentFrame> frames;
  std::vector<Sphere> spheres;
  std::vector<double> gaps;  // exact_distance, the reference
};

Batch make_batch(Scene scene) {
  scenes::CaseGenerator gen(scenes::kBenchmarkSeed + static_cast<std::uint64_t>(scene));
  Batch b;
  for (std::size_t i = 0; i < kBatch; ++i) {
    const scenes::Case c = scene == Scene::kMix    ? gen.next()
                           : scene == Scene::kHand ? gen.make(Family::kHand)
                                                   : gen.make(Family::kBoundary);
    b.segments.push_back(c.segment);
    b.frames.push_back(make_segment_frame(c.segment));
    b.spheres.push_back(c.sphere);
    b.gaps.push_back(exact_distance(b.frames.back(), c.sphere));
  }
  return b;
}

const Batch& batch(Scene scene) {
  static const std::array<Batch, 3> batches = {make_batch(Scene::kMix), make_batch(Scene::kHand),
                                               make_batch(Scene::kBoundary)};
  return batches[static_cast<std::size_t>(scene)];
}

// ns per call: a rate counter inverted (CPU seconds per item), scaled to nanoseconds
void report_per_call(benchmark::State& state, std::size_t calls_per_iteration) {
  const auto items = static_cast<std::int64_t>(calls_per_iteration) * state.iterations();
  state.SetItemsProcessed(items);
  state.counters["ns_per_call"] = benchmark::Counter(
      static_cast<double>(calls_per_iteration) * 1e-9,
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// error rates of a yes/no test against exact_distance <= margin on the batch
template <class Test>
void report_errors(benchmark::State& state, const Batch& b, double margin, Test&& test) {
  std::size_t contacts = 0, fp = 0, fn = 0;
  for (std::size_t i = 0; i < b.frames.size(); ++i) {
    const bool truth = b.gaps[i] <= margin;
    const bool said = test(b.frames[i], b.spheres[i]);
    contacts += truth;
    fp += said && !truth;
    fn += !said && truth;
  }
  const std::size_t non_contacts = b.frames.size() - contacts;
  state.counters["false_positive_rate"] =
      non_contacts ? static_cast<double>(fp) / static_cast<double>(non_contacts) : 0.0;
  state.counters["false_negative_rate"] =
      contacts ? static_cast<double>(fn) / static_cast<double>(contacts) : 0.0;
  state.counters["contact_fraction"] =
      static_cast<double>(contacts) / static_cast<double>(b.frames.size());
}

void BM_PatentTest(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  for (auto _ : state) {
    std::size_t hits = 0;
    for (std::size_t i = 0; i < kBatch; ++i) hits += patent_contact(b.frames[i], b.spheres[i]);
    benchmark::DoNotOptimize(hits);
  }
  report_per_call(state, kBatch);
  report_errors(state, b, 0.0, [](const SegmentFrame& f, const Sphere& s) {
    return patent_contact(f, s);
  });
}

// range(0): prediction margin in micrometres (0 or the 2 mm of method.md section 7)
void BM_MayTouch(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  const double margin = static_cast<double>(state.range(0)) * 1e-6;
  for (auto _ : state) {
    std::size_t hits = 0;
    for (std::size_t i = 0; i < kBatch; ++i) hits += may_touch(b.frames[i], b.spheres[i], margin);
    benchmark::DoNotOptimize(hits);
  }
  report_per_call(state, kBatch);
  report_errors(state, b, margin, [margin](const SegmentFrame& f, const Sphere& s) {
    return may_touch(f, s, margin);
  });
}

void BM_ExactDistance(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBatch; ++i) sum += exact_distance(b.frames[i], b.spheres[i]);
    benchmark::DoNotOptimize(sum);
  }
  report_per_call(state, kBatch);
}

void BM_ExactProximity(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  for (auto _ : state) {
    vec3 sum(0.0);
    for (std::size_t i = 0; i < kBatch; ++i) {
      const Proximity p = exact_proximity(b.frames[i], b.spheres[i]);
      sum += p.hand_point + p.normal;
    }
    benchmark::DoNotOptimize(sum);
  }
  report_per_call(state, kBatch);
}

// range(0): ConstraintForm (0 squared, 1 distance); value and all three gradients
void BM_ContactConstraint(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  const auto form = static_cast<ConstraintForm>(state.range(0));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBatch; ++i) {
      const Constraint g = contact_constraint(b.frames[i], b.spheres[i], form);
      sum += g.value + g.grad_proximal.x + g.grad_distal.y + g.grad_center.z;
    }
    benchmark::DoNotOptimize(sum);
  }
  report_per_call(state, kBatch);
}

// the per-segment precomputation every pair test reuses
void BM_MakeSegmentFrame(benchmark::State& state, Scene scene) {
  const Batch& b = batch(scene);
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < kBatch; ++i) sum += make_segment_frame(b.segments[i]).cos_alpha;
    benchmark::DoNotOptimize(sum);
  }
  report_per_call(state, kBatch);
}

// Whole hand: forward kinematics, then the point Jacobian of D and E of all 15
// segments (30 Jacobians), per hand state; states random within the joint limits.
void BM_HandKinematicsWithJacobians(benchmark::State& state) {
  const HandModel model = make_hand_model(default_hand_def());
  std::mt19937_64 rng(scenes::kBenchmarkSeed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), coord(-0.5, 0.5);
  std::normal_distribution<double> gauss;
  constexpr std::size_t kStates = 256;
  std::vector<HandState> states(kStates);
  for (HandState& s : states) {
    for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
      for (int j = 0; j < FRUSTA_JOINTS_PER_FINGER; ++j) {
        const FingerModel& m = model.fingers[static_cast<std::size_t>(f)];
        const auto jj = static_cast<std::size_t>(j);
        s.angles[static_cast<std::size_t>(f * FRUSTA_JOINTS_PER_FINGER + j)] =
            m.joint_min[jj] + unit(rng) * (m.joint_max[jj] - m.joint_min[jj]);
      }
    s.palm_position = vec3(coord(rng), coord(rng), coord(rng));
    s.palm_rotation = glm::normalize(glm::dquat(gauss(rng), gauss(rng), gauss(rng), gauss(rng)));
  }
  HandPose pose;
  double jacobian[3 * kJacobianColumns];
  for (auto _ : state) {
    double sum = 0.0;
    for (const HandState& s : states) {
      forward_kinematics(model, s, pose);
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        for (int seg = 0; seg < FRUSTA_SEGMENTS_PER_FINGER; ++seg) {
          const Segment segment = finger_segment(model, pose, f, seg);
          point_jacobian(pose, f, seg, segment.proximal, jacobian);
          sum += jacobian[0];
          point_jacobian(pose, f, seg, segment.distal, jacobian);
          sum += jacobian[3 * kJacobianColumns - 1];
        }
    }
    benchmark::DoNotOptimize(sum);
  }
  report_per_call(state, kStates);
  state.counters["jacobians_per_call"] = 2.0 * FRUSTA_FINGER_COUNT * FRUSTA_SEGMENTS_PER_FINGER;
}

BENCHMARK_CAPTURE(BM_PatentTest, mix, Scene::kMix);
BENCHMARK_CAPTURE(BM_PatentTest, hand, Scene::kHand);
BENCHMARK_CAPTURE(BM_PatentTest, boundary, Scene::kBoundary);
BENCHMARK_CAPTURE(BM_MayTouch, mix, Scene::kMix)->ArgName("margin_um")->Arg(0)->Arg(2000);
BENCHMARK_CAPTURE(BM_MayTouch, hand, Scene::kHand)->ArgName("margin_um")->Arg(0)->Arg(2000);
BENCHMARK_CAPTURE(BM_MayTouch, boundary, Scene::kBoundary)->ArgName("margin_um")->Arg(0);
BENCHMARK_CAPTURE(BM_ExactDistance, mix, Scene::kMix);
BENCHMARK_CAPTURE(BM_ExactDistance, hand, Scene::kHand);
BENCHMARK_CAPTURE(BM_ExactProximity, mix, Scene::kMix);
BENCHMARK_CAPTURE(BM_ExactProximity, hand, Scene::kHand);
BENCHMARK_CAPTURE(BM_ContactConstraint, mix, Scene::kMix)->ArgName("distance_form")->Arg(0)->Arg(1);
BENCHMARK_CAPTURE(BM_ContactConstraint, hand, Scene::kHand)->ArgName("distance_form")->Arg(0)->Arg(1);
BENCHMARK_CAPTURE(BM_MakeSegmentFrame, mix, Scene::kMix);
BENCHMARK(BM_HandKinematicsWithJacobians);

}  // namespace
}  // namespace frusta
