// SPDX-License-Identifier: MIT
// Running a scripted scenario under GoogleTest: every step checked against the exact
// leaf-sphere reference, and the hold that must not drift.
#pragma once

#include <cstdint>

#include "scenes/hand_scenarios.h"
#include "solver/hand_solver.h"

namespace frusta::testing {

struct RunLog {
  double max_penetration = 0.0;  // metres
  int32_t steps = 0;
  int32_t max_substeps = 0;
  bool lagged = false;
};

// Steps the solver through the scenario's scripted trajectory.
RunLog run(HandSolver& solver, const scenes::HandScenario& scenario);

// Largest change of any joint angle (rad), palm coordinate (m) or rotation quaternion
// component between two states.
double state_change(const HandState& a, const HandState& b);

// Holds the haptic hand at scenario.held for `steps` and returns the largest change
// from the first held step's graphic hand, over every step (an oscillation shows too).
double hold_drift(HandSolver& solver, const scenes::HandScenario& scenario, int32_t steps, RunLog& log);

}  // namespace frusta::testing
