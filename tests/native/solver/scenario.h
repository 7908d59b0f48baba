// SPDX-License-Identifier: MIT
// Scripted haptic trajectories against the baked sample objects, with the exact
// reference for what matters: how deep the graphic hand ever sinks into the leaves.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solver/hand_solver.h"
#include "spheretree/tree_file.h"

namespace frusta::testing {

// The sample objects baked at build time (samples/objects), by name: ball, box, plate,
// bowl, mug, octahedron.
std::shared_ptr<const TreeFile> sample_tree(const std::string& name);

// A rotation quaternion about an axis.
glm::dquat about(const vec3& axis, double angle);

// Deepest penetration (metres, > 0 when sinking) of the hand at `pose` into any leaf of
// any object: every leaf against every segment solid and palm sphere, by the exact
// distance, with only an exact bound test in front.
double deepest_penetration(const HandModel& model, const HandPose& pose,
                           const std::vector<SolverObject>& objects);

struct Scene {
  std::vector<std::shared_ptr<const TreeFile>> trees;
  std::vector<SolverObject> objects;
  void add(const std::string& name, const RigidPose& pose);
};

// What a run saw, step by step.
struct RunLog {
  double max_penetration = 0.0;  // metres
  int32_t steps = 0;
  int32_t max_substeps = 0;
  int32_t max_contacts = 0;
  int32_t qp_iterations = 0;
  bool lagged = false;
};

// Steps `solver` through haptic(t) for t = 0..steps-1, checking penetration each step.
RunLog run(HandSolver& solver, const Scene& scene, int32_t steps,
           const std::function<HandState(int32_t)>& haptic);

// Largest change of any joint angle (rad) or palm coordinate (m) between two states.
double state_change(const HandState& a, const HandState& b);

// Holds the haptic hand still for `steps` and returns the largest state change from
// the first held step's result.
double hold_drift(HandSolver& solver, const Scene& scene, const HandState& haptic, int32_t steps,
                  RunLog& log);

}  // namespace frusta::testing
