// SPDX-License-Identifier: MIT
#include "core/error.h"
#include "scenario_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace frusta::testing {

namespace {

// one step, checked: false when the solver refused it
bool checked_step(HandSolver& solver, const scenes::HandScenario& s, const HandState& haptic, RunLog& log) {
  StepStats stats;
  const frusta_result r =
      solver.step(haptic, s.objects.data(), static_cast<int32_t>(s.objects.size()), &stats);
  EXPECT_EQ(r, FRUSTA_OK) << s.name << " step " << log.steps << ": " << frusta::last_error_message();
  if (r != FRUSTA_OK) return false;
  ++log.steps;
  log.max_penetration = std::max(
      log.max_penetration, scenes::deepest_penetration(solver.model(), solver.graphic_pose(), s.objects));
  log.max_substeps = std::max(log.max_substeps, stats.substeps);
  log.lagged |= stats.lagging;
  return true;
}

}  // namespace

RunLog run(HandSolver& solver, const scenes::HandScenario& scenario) {
  RunLog log;
  for (int32_t t = 0; t < scenario.steps; ++t)
    if (!checked_step(solver, scenario, scenario.haptic(t), log)) break;
  return log;
}

double state_change(const HandState& a, const HandState& b) {
  double change = glm::length(a.palm_position - b.palm_position);
  const glm::dquat dq = a.palm_rotation - b.palm_rotation;
  change = std::max(change, std::sqrt(dq.w * dq.w + dq.x * dq.x + dq.y * dq.y + dq.z * dq.z));
  for (size_t j = 0; j < a.angles.size(); ++j) change = std::max(change, std::fabs(a.angles[j] - b.angles[j]));
  return change;
}

double hold_drift(HandSolver& solver, const scenes::HandScenario& scenario, int32_t steps, RunLog& log) {
  if (!checked_step(solver, scenario, scenario.held, log)) return INFINITY;
  const HandState first = solver.graphic();
  double drift = 0.0;
  for (int32_t t = 0; t < steps; ++t) {
    if (!checked_step(solver, scenario, scenario.held, log)) return INFINITY;
    drift = std::max(drift, state_change(first, solver.graphic()));
  }
  return drift;
}

}  // namespace frusta::testing
