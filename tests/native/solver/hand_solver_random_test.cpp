// SPDX-License-Identifier: MIT
// Random scenes beside the scripted ones: hands of random sizes and sides among one to
// three random objects (clouds, thin shells, duplicated leaves, leaves of no radius, a
// lone leaf; scaled, turned any way, placed where the hand reaches, the whole scene up to
// a kilometre from the origin), driven along random paths: drifts, sweeps of centimetres
// a step, jumps deep into the objects, joints aimed past their limits, and resets. After
// every step the graphic hand is finite, the pose of its state, sinks into no leaf deeper
// than the tolerance (the exact reference), and reports only pairs within the contact
// distance; a step fails only while no free placement near a hand that starts inside
// has been found. Some scenes solve on a level of detail, with the squared constraint
// form or with a smaller Delta_r. FRUSTA_PROPERTY_CASES=N runs N / 1000 scenes (at least
// the default's).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "scenes/hand_scenarios.h"
#include "scenes/random_cases.h"
#include "scenes/random_hands.h"
#include "scenes/random_trees.h"
#include "solver/hand_solver.h"
#include "spheretree/tree_builder.h"

namespace frusta {
namespace {

constexpr int kScenes = 24;
constexpr int kSteps = 80;

glm::dquat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  glm::dquat q(g(rng), g(rng), g(rng), g(rng));
  return glm::normalize(q);
}

struct RandomScene {
  std::vector<std::unique_ptr<SphereTree>> trees;
  std::vector<SolverObject> objects;
  std::vector<vec3> centres;  // where each object's leaves are, world
};

// 1-3 objects around `origin`, within a hand's reach of it.
RandomScene random_scene(std::mt19937_64& rng, const vec3& origin) {
  std::uniform_int_distribution<int> objects(1, 3), kind(0, 4), branching(2, 8);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), scale(0.2, 1.5);
  std::uniform_int_distribution<int> count(1, 1500);
  RandomScene scene;
  const int n = objects(rng);
  for (int o = 0; o < n; ++o) {
    const int k = kind(rng);
    std::vector<Sphere> leaves =
        k == 4 ? std::vector<Sphere>{{vec3(0.0), 0.01}}  // a lone leaf
               : testing::random_leaves(rng, count(rng), k);
    const double s = scale(rng);
    for (Sphere& leaf : leaves) {
      leaf.center *= s;
      leaf.radius *= s;
    }
    auto tree = std::make_unique<SphereTree>();
    EXPECT_EQ(build_sphere_tree(leaves, {branching(rng)}, tree.get()), FRUSTA_OK);
    const vec3 at = origin + 0.12 * vec3(unit(rng), unit(rng), unit(rng));
    scene.objects.push_back({tree.get(), {at, glm::mat3_cast(random_rotation(rng))}});
    scene.centres.push_back(at);
    scene.trees.push_back(std::move(tree));
  }
  return scene;
}

// The next haptic hand: a drift, a sweep, a jump into an object, or a hand anywhere near,
// its angles at times aimed past the joints' limits (the solver clamps them).
HandState next_haptic(std::mt19937_64& rng, const HandModel& model, const RandomScene& scene,
                      const vec3& origin, const HandState& now) {
  std::uniform_real_distribution<double> u(0.0, 1.0), unit(-1.0, 1.0);
  std::normal_distribution<double> g;
  HandState next = now;
  const double kind = u(rng);
  if (kind < 0.55) {  // a drift
    next.palm_position += 0.003 * vec3(g(rng), g(rng), g(rng));
    for (double& a : next.angles) a += 0.05 * g(rng);
    next.palm_rotation = glm::normalize(next.palm_rotation * glm::dquat(1.0, 0.02 * g(rng), 0.02 * g(rng), 0.02 * g(rng)));
  } else if (kind < 0.8) {  // a sweep of 1-6 cm
    next.palm_position += (0.01 + 0.05 * u(rng)) * glm::normalize(vec3(g(rng), g(rng), g(rng)));
    for (double& a : next.angles) a += 0.3 * g(rng);
  } else if (kind < 0.92) {  // a jump with the palm into an object's leaves
    std::uniform_int_distribution<size_t> which(0, scene.centres.size() - 1);
    next.palm_position = scene.centres[which(rng)] + 0.02 * vec3(unit(rng), unit(rng), unit(rng));
    next.palm_rotation = random_rotation(rng);
  } else {  // anywhere near, any pose
    next = scenes::random_hand_state(model, rng);
    next.palm_position = origin + 0.15 * vec3(unit(rng), unit(rng), unit(rng));
  }
  if (u(rng) < 0.1)  // aimed past the limits
    for (double& a : next.angles) a += 2.0 * unit(rng);
  return next;
}

bool finite(const HandState& s) {
  bool ok = std::isfinite(s.palm_position.x) && std::isfinite(s.palm_position.y) &&
            std::isfinite(s.palm_position.z) && std::isfinite(s.palm_rotation.w) &&
            std::isfinite(s.palm_rotation.x) && std::isfinite(s.palm_rotation.y) &&
            std::isfinite(s.palm_rotation.z);
  for (double a : s.angles) ok = ok && std::isfinite(a);
  return ok;
}

TEST(HandSolverRandom, RandomHandsOnRandomPathsAmongRandomObjectsNeverSink) {
  const int scenes_count =
      std::max<int>(kScenes, static_cast<int>(scenes::property_case_count(0) / 1000));
  std::mt19937_64 rng(scenes::kPropertySeed + 211);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), u(0.0, 1.0);
  const std::array<double, 4> kOffsets = {0.0, 1.0, 30.0, 1000.0};
  int64_t steps = 0, placed = 0, contacts = 0, deep_targets = 0;
  for (int scene_index = 0; scene_index < scenes_count; ++scene_index) {
    const HandModel model = make_hand_model(scenes::random_hand_def(scene_index % 2, rng));
    const vec3 origin = kOffsets[static_cast<size_t>(scene_index) % kOffsets.size()] *
                        glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
    const RandomScene scene = random_scene(rng, origin);
    // the knobs too: a level of detail (its nodes bound their leaves, so a hand clear of
    // them is clear of the leaves), the squared constraint form, a smaller Delta_r
    SolverParams params;
    const double knobs = u(rng);
    if (knobs < 0.15) params.lod_error = 0.001 + 0.002 * u(rng);
    else if (knobs < 0.25) params.tree_level = 2 + static_cast<int32_t>(3.0 * u(rng));
    if (u(rng) < 0.2) params.form = ConstraintForm::kSquared;
    if (u(rng) < 0.2) params.prediction_margin = 0.0005 + 0.001 * u(rng);
    ASSERT_EQ(HandSolver::check_params(params, model), FRUSTA_OK) << last_error_message();
    HandSolver solver(model, params);
    HandState haptic = scenes::random_hand_state(model, rng);
    haptic.palm_position = origin + 0.1 * vec3(unit(rng), unit(rng), unit(rng));
    for (int t = 0; t < kSteps; ++t) {
      haptic = next_haptic(rng, model, scene, origin, haptic);
      if (u(rng) < 0.02) solver.reset();
      const bool was_started = solver.started();
      StepStats stats;
      const frusta_result r =
          solver.step(haptic, scene.objects.data(), static_cast<int32_t>(scene.objects.size()),
                      &stats, HandSolver::Clock::time_point::max(), nullptr, t > 0 && was_started);
      ++steps;
      SCOPED_TRACE(::testing::Message() << "scene " << scene_index << " step " << t);
      if (!solver.started()) {
        // only a hand starting inside, with no free placement near, stays unplaced
        ASSERT_EQ(r, FRUSTA_ERROR_OUT_OF_RANGE);
        continue;
      }
      ASSERT_EQ(r, FRUSTA_OK) << last_error_message();
      placed += !was_started;
      ASSERT_TRUE(finite(solver.graphic()));
      HandPose fresh;
      forward_kinematics(model, solver.graphic(), fresh);
      ASSERT_EQ(bodies_unmoved(fresh, solver.graphic_pose()), (1u << kBodyCount) - 1u);
      const double depth = scenes::deepest_penetration(model, solver.graphic_pose(), scene.objects);
      // the tolerance, and the rounding of coordinates a kilometre from the origin
      ASSERT_LE(depth, params.penetration_tolerance + 1e-12 * (1.0 + glm::length(origin)));
      deep_targets += scenes::deepest_penetration(model, solver.target_pose(), scene.objects) > 0.005;
      for (const SolverContact& c : solver.contacts()) {
        ASSERT_GE(c.distance, -params.penetration_tolerance - 1e-12 * (1.0 + glm::length(origin)));
        ASSERT_LE(c.distance, params.contact_distance);
        ++contacts;
      }
    }
  }
  std::printf("[ random scenes ] %d scenes, %lld steps, %lld placements, %lld contacts, %lld "
              "steps aimed 5 mm or more inside\n",
              scenes_count, static_cast<long long>(steps), static_cast<long long>(placed),
              static_cast<long long>(contacts), static_cast<long long>(deep_targets));
  // the paths reach the objects: contacts made, targets deep inside
  EXPECT_GT(contacts, steps);
  EXPECT_GT(deep_targets, steps / 10);
}

}  // namespace
}  // namespace frusta
