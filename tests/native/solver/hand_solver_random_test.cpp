// SPDX-License-Identifier: MIT
// Random scenes beside the scripted ones: hands of random sizes and sides among one to
// three random objects near and up to three further off (clouds, thin shells, duplicated
// leaves, leaves of no radius, a lone leaf; scaled, turned any way, the whole scene up
// to a kilometre from the origin), driven along random paths: drifts, sweeps of
// centimetres a step, jumps deep into the objects, joints aimed past their limits, and
// resets. After every step the graphic hand is valid (as an input would have to be), the
// pose of its state, sinks into no leaf deeper than the tolerance (the exact reference),
// and reports only pairs within the contact distance; a step fails only while no free
// placement near a hand that starts inside has been found. Some scenes solve on a level
// of detail, with the squared constraint form or with a smaller Delta_r; in some the
// host moves objects (after which a hand may be caught inside, and depth is not
// checked). A twin solver looking only at what a broad phase over the objects finds near
// (the runtime's way) makes the same hands and contacts to the bit.
// FRUSTA_PROPERTY_CASES=N runs 24 N / 10^6 scenes (at least 4).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtc/quaternion.hpp>
#include <memory>
#include <random>
#include <vector>

#include "core/error.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"
#include "scenes/hand_scenarios.h"
#include "scenes/random_cases.h"
#include "scenes/random_hands.h"
#include "scenes/random_scenes.h"
#include "solver/hand_solver.h"
#include "scene_finder.h"

namespace frusta {
namespace {

constexpr int kScenes = 24;
constexpr int kSteps = 80;

struct RandomScene {
  std::vector<std::shared_ptr<const TreeFile>> trees;
  std::vector<SolverObject> objects;
  std::vector<vec3> centres;  // where each object is, world
};

// 1-3 objects around `origin`, within a hand's reach of it, and 0-3 further off (what a
// broad phase leaves out until the hand goes there).
RandomScene random_scene(std::mt19937_64& rng, const vec3& origin) {
  std::uniform_int_distribution<int> objects(1, 3), far_objects(0, 3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), far(0.25, 0.6);
  RandomScene scene;
  const int near = objects(rng), n = near + far_objects(rng);
  for (int o = 0; o < n; ++o) {
    std::shared_ptr<const TreeFile> tree = scenes::random_object_tree(rng);
    const vec3 at =
        origin + (o < near ? 0.12 * vec3(unit(rng), unit(rng), unit(rng))
                           : far(rng) * glm::normalize(vec3(unit(rng), unit(rng), unit(rng))));
    scene.objects.push_back({&tree->tree, {at, glm::mat3_cast(scenes::random_rotation(rng))}});
    scene.centres.push_back(at);
    scene.trees.push_back(std::move(tree));
  }
  return scene;
}

// The graphic hands and their contacts equal to the bit.
bool same_hand(const HandSolver& a, const HandSolver& b) {
  static_assert(sizeof(SolverContact) == 4 * sizeof(int32_t) + 10 * sizeof(double),
                "no padding: compared byte for byte");
  // (memcmp's pointers may not be null, even for no bytes: an empty list's data() may be)
  return scenes::same_bits(a.graphic(), b.graphic()) &&
         a.contacts().size() == b.contacts().size() &&
         (a.contacts().empty() || std::memcmp(a.contacts().data(), b.contacts().data(),
                                              a.contacts().size() * sizeof(SolverContact)) == 0);
}

TEST(HandSolverRandom, RandomHandsOnRandomPathsAmongRandomObjectsNeverSink) {
  // as many as the property tests' cases allow: 24 at their million, fewer in the
  // sanitizer and cross-built runs, more by hand
  const int scenes_count = scenes::scaled_case_count(kScenes, 4);
  std::mt19937_64 rng(scenes::kPropertySeed + 211);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), u(0.0, 1.0);
  const std::array<double, 4> kOffsets = {0.0, 1.0, 30.0, 1000.0};
  int64_t steps = 0, placed = 0, contacts = 0, deep_targets = 0;
  for (int scene_index = 0; scene_index < scenes_count; ++scene_index) {
    const HandModel model = make_hand_model(scenes::random_hand_def(scene_index % 2, rng));
    const vec3 origin = kOffsets[static_cast<size_t>(scene_index) % kOffsets.size()] *
                        glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
    RandomScene scene = random_scene(rng, origin);
    // in some scenes the host moves objects: a little, or a jump of centimetres (into the
    // hand too, which then may be caught inside; the checks of depth stop there)
    const bool moving = u(rng) < 0.3;
    bool moved_once = false;
    // the knobs too: a level of detail (its nodes bound their leaves, so a hand clear of
    // them is clear of the leaves), the squared constraint form, a smaller Delta_r
    SolverParams params;
    const double knobs = u(rng);
    if (knobs < 0.15)
      params.lod_error = 0.001 + 0.002 * u(rng);
    else if (knobs < 0.25)
      params.tree_level = 2 + static_cast<int32_t>(3.0 * u(rng));
    if (u(rng) < 0.2) params.form = ConstraintForm::kSquared;
    if (u(rng) < 0.2) params.prediction_margin = 0.0005 + 0.001 * u(rng);
    ASSERT_EQ(HandSolver::check_params(params, model), FRUSTA_OK) << last_error_message();
    HandSolver solver(model, params);
    // its twin, looking only at the objects a broad phase finds near (the runtime's
    // way): the same hands and contacts to the bit
    HandSolver twin(model, params);
    testing::SceneFinder finder(scene.objects);
    HandState haptic = scenes::random_hand_state(model, rng);
    haptic.palm_position = origin + 0.1 * vec3(unit(rng), unit(rng), unit(rng));
    for (int t = 0; t < kSteps; ++t) {
      haptic = scenes::next_random_haptic(rng, model, scene.centres, origin, haptic);
      ASSERT_EQ(check_hand_state(haptic, "haptic"), FRUSTA_OK);  // as the solver's callers check
      if (u(rng) < 0.02) {
        solver.reset();
        twin.reset();
      }
      bool moved_now = false;
      if (moving && u(rng) < 0.3) {
        std::uniform_int_distribution<size_t> which(0, scene.objects.size() - 1);
        const size_t o = which(rng);
        RigidPose& pose = scene.objects[o].pose;
        const double reach = u(rng) < 0.1 ? 0.05 : 0.003;
        pose.position += reach * vec3(unit(rng), unit(rng), unit(rng));
        pose.rotation =
            pose.rotation * glm::mat3_cast(glm::normalize(glm::dquat(
                                1.0, 0.03 * unit(rng), 0.03 * unit(rng), 0.03 * unit(rng))));
        scene.centres[o] = pose.position;
        finder.moved(scene.objects, o);
        moved_now = moved_once = true;
      }
      const bool as_before = t > 0 && solver.started() && !moved_now;
      const bool was_started = solver.started();
      StepStats stats;
      const int32_t count = static_cast<int32_t>(scene.objects.size());
      const frusta_result r = solver.step(haptic, scene.objects.data(), count, &stats,
                                          HandSolver::Clock::time_point::max(), nullptr, as_before);
      const frusta_result twin_r =
          twin.step(haptic, scene.objects.data(), count, nullptr,
                    HandSolver::Clock::time_point::max(), &finder, as_before);
      ++steps;
      SCOPED_TRACE(::testing::Message() << "scene " << scene_index << " step " << t);
      ASSERT_EQ(twin_r, r);
      ASSERT_EQ(twin.started(), solver.started());
      ASSERT_TRUE(same_hand(twin, solver)) << "with a broad phase, another hand or contacts";
      if (!solver.started()) {
        // only a hand starting inside, with no free placement near, stays unplaced
        ASSERT_EQ(r, FRUSTA_ERROR_OUT_OF_RANGE);
        continue;
      }
      ASSERT_EQ(r, FRUSTA_OK) << last_error_message();
      placed += !was_started;
      ASSERT_EQ(check_hand_state(solver.graphic(), "graphic"), FRUSTA_OK) << last_error_message();
      HandPose fresh;
      forward_kinematics(model, solver.graphic(), fresh);
      ASSERT_EQ(bodies_unmoved(fresh, solver.graphic_pose()), (1u << kBodyCount) - 1u);
      for (const SolverContact& c : solver.contacts()) {
        ASSERT_LE(c.distance, params.contact_distance);
        ++contacts;
      }
      if (moved_once) continue;
      const double depth = scenes::deepest_penetration(model, solver.graphic_pose(), scene.objects);
      // the tolerance, and the rounding of coordinates a kilometre from the origin
      ASSERT_LE(depth, params.penetration_tolerance + 1e-12 * (1.0 + glm::length(origin)));
      deep_targets +=
          scenes::deepest_penetration(model, solver.target_pose(), scene.objects) > 0.005;
      for (const SolverContact& c : solver.contacts())
        ASSERT_GE(c.distance, -params.penetration_tolerance - 1e-12 * (1.0 + glm::length(origin)));
    }
  }
  std::printf(
      "[ random scenes ] %d scenes, %lld steps, %lld placements, %lld contacts, %lld "
      "steps aimed 5 mm or more inside\n",
      scenes_count, static_cast<long long>(steps), static_cast<long long>(placed),
      static_cast<long long>(contacts), static_cast<long long>(deep_targets));
  // the paths reach the objects: contacts made, targets deep inside
  EXPECT_GT(contacts, steps / 2);
  EXPECT_GT(deep_targets, steps / 10);
}

}  // namespace
}  // namespace frusta
