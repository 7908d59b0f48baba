// SPDX-License-Identifier: MIT
// A fingertip sliding over sharp convex edges (issue 20's acceptance): the 120-degree
// edges of a hexagonal prism, the 90-degree edge of a box and the 30-degree edge of a
// wedge (the test prisms of scenes/baked_objects.h), each lying ridge up under the
// index tip. The haptic hand is rigid (the index bent, the other fingers open) and
// carries the index tip's centre along a path at a constant speed in 1 ms steps,
// `depth` into the object:
//  - across: down one face, round the edge at the same depth, down the other face;
//  - over: a straight line over the ridge, `depth` into it at the top: the contact is
//    made and broken while sliding;
//  - along: on the ridge, along the edge.
// Each path goes and comes back, and starts and ends 2 mm clear of the object.
// Shared by the test of the solver's continuity and the solver benchmark.
#pragma once

#include <string>
#include <vector>

#include "solver/solver_params.h"
#include "scenes/hand_scenarios.h"

namespace frusta::scenes {

enum class EdgePath { kAcross, kOver, kAlong };
constexpr EdgePath kEdgePaths[] = {EdgePath::kAcross, EdgePath::kOver, EdgePath::kAlong};
const char* edge_path_name(EdgePath path);

// The test prisms the slides are on: hex_prism, edge_box, wedge.
std::vector<std::string> edge_shape_names();

constexpr int kEdgeSlideFinger = FRUSTA_FINGER_INDEX;
constexpr double kEdgeSlideStep = 1e-3;  // seconds a haptic sample stands for

// The slide over the edge of test prism `shape` at `speed` (m/s), `depth` (m).
HandScenario edge_slide(const std::string& shape, EdgePath path, double speed, double depth);

// What one step did to the sliding fingertip (the tip centre of kEdgeSlideFinger) and to
// the hand's normal force (seed eq. 12, summed over its contacts).
struct EdgeSlideStep {
  double haptic_move = 0.0;          // metres the haptic fingertip moved since the last step
  double graphic_move = 0.0;         // ... and the graphic fingertip
  double force = 0.0;                // newtons, |F|
  double force_change = 0.0;         // newtons, how much |F| changed since the last step
  double force_turn = 0.0;           // newtons, |F - F_last|: the change with its turning
  double friction_change = 0.0;      // newtons, |f - f_last| of the summed friction
  double penetration = 0.0;          // metres, into the exact leaf set (when checked)
  double step_us = 0.0;              // solver step plus forces (when timed)
  bool lagging = false;              // the sub-step cap stopped the hand short
};

// Steps a HandSolver (`params`) and ContactForces (the default material) through the
// slide. The first step starts the graphic hand, so it moves nothing. A failed solver
// step ends the run early (fewer steps than s.steps).
std::vector<EdgeSlideStep> run_edge_slide(const HandScenario& s, const SolverParams& params,
                                          bool check_penetration, bool timed);

}  // namespace frusta::scenes
