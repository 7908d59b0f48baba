// SPDX-License-Identifier: MIT
#include "scenario.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/geometric.hpp>

#include "geometry/exact_distance.h"
#include "solver/detection.h"

namespace frusta::testing {

std::shared_ptr<const TreeFile> sample_tree(const std::string& name) {
  static std::map<std::string, std::shared_ptr<const TreeFile>> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  auto file = std::make_shared<TreeFile>();
  const std::string path = std::string(FRUSTA_SAMPLE_OBJECTS_DIR) + "/" + name + ".frtree";
  EXPECT_EQ(load_tree_file(path, file.get()), FRUSTA_OK) << path << " (built by frusta_sample_objects)";
  cache[name] = file;
  return file;
}

glm::dquat about(const vec3& axis, double angle) { return glm::angleAxis(angle, glm::normalize(axis)); }

double deepest_penetration(const HandModel& model, const HandPose& pose,
                           const std::vector<SolverObject>& objects) {
  const HandReach reach = hand_reach(model);
  double deepest = 0.0;
  for (const SolverObject& object : objects) {
    for (const Sphere& local : object.tree->leaves) {
      const Sphere leaf{object.pose.rotation * local.center + object.pose.position, local.radius};
      // a leaf beyond the hand's bound cannot touch it: an exact test, not a cull heuristic
      if (glm::length(leaf.center - pose.palm_position) > reach.hand + leaf.radius) continue;
      for (int f = 0; f < FRUSTA_FINGER_COUNT; ++f)
        for (int s = 0; s < FRUSTA_SEGMENTS_PER_FINGER; ++s)
          deepest = std::max(deepest, -exact_distance(make_segment_frame(finger_segment(model, pose, f, s)), leaf));
      for (int k = 0; k < static_cast<int>(model.palm_spheres.size()); ++k) {
        const Sphere palm = palm_sphere(model, pose, k);
        deepest = std::max(deepest, palm.radius + leaf.radius - glm::length(palm.center - leaf.center));
      }
    }
  }
  return deepest;
}

void Scene::add(const std::string& name, const RigidPose& pose) {
  trees.push_back(sample_tree(name));
  objects.push_back({&trees.back()->tree, pose});
}

RunLog run(HandSolver& solver, const Scene& scene, int32_t steps,
           const std::function<HandState(int32_t)>& haptic) {
  RunLog log;
  for (int32_t t = 0; t < steps; ++t) {
    StepStats stats;
    const frusta_result r = solver.step(haptic(t), scene.objects.data(),
                                        static_cast<int32_t>(scene.objects.size()), &stats);
    EXPECT_EQ(r, FRUSTA_OK) << "step " << t;
    if (r != FRUSTA_OK) break;
    ++log.steps;
    log.max_penetration = std::max(
        log.max_penetration, deepest_penetration(solver.model(), solver.graphic_pose(), scene.objects));
    log.max_substeps = std::max(log.max_substeps, stats.substeps);
    log.max_contacts = std::max(log.max_contacts, static_cast<int32_t>(solver.contacts().size()));
    log.qp_iterations += stats.qp_iterations;
    log.lagged |= stats.lagging;
  }
  return log;
}

double state_change(const HandState& a, const HandState& b) {
  double change = glm::length(a.palm_position - b.palm_position);
  change = std::max(change, glm::length(glm::dvec4(a.palm_rotation.x - b.palm_rotation.x,
                                                   a.palm_rotation.y - b.palm_rotation.y,
                                                   a.palm_rotation.z - b.palm_rotation.z,
                                                   a.palm_rotation.w - b.palm_rotation.w)));
  for (size_t j = 0; j < a.angles.size(); ++j)
    change = std::max(change, std::fabs(a.angles[j] - b.angles[j]));
  return change;
}

double hold_drift(HandSolver& solver, const Scene& scene, const HandState& haptic, int32_t steps,
                  RunLog& log) {
  StepStats stats;
  EXPECT_EQ(solver.step(haptic, scene.objects.data(), static_cast<int32_t>(scene.objects.size()), &stats),
            FRUSTA_OK);
  const HandState first = solver.graphic();
  double drift = 0.0;
  for (int32_t t = 0; t < steps; ++t) {  // every step, so an oscillation shows too
    const RunLog held = run(solver, scene, 1, [&](int32_t) { return haptic; });
    log.max_penetration = std::max(log.max_penetration, held.max_penetration);
    drift = std::max(drift, state_change(first, solver.graphic()));
  }
  return drift;
}

}  // namespace frusta::testing
