// SPDX-License-Identifier: MIT
// One half of tools/bench paired: a deep grasp (or a named hand scenario) stepped by one
// build of the solver. Compiled once per build against that build's own headers, the
// second time with -Dfrusta=frustb and linked to that build's libraries with their
// symbols renamed the same way, so two builds share one process (paired_main.cpp).
#include <chrono>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/hand_scenarios.h"
#include "solver/hand_solver.h"

#define FRUSTA_PAIRED_CAT2(a, b) a##b
#define FRUSTA_PAIRED_CAT(a, b) FRUSTA_PAIRED_CAT2(a, b)
#define FRUSTA_PAIRED(name) FRUSTA_PAIRED_CAT(name, FRUSTA_PAIRED_HALF)

namespace {

struct Half {
  frusta::scenes::HandScenario scenario;
  frusta::HandModel model;
  std::unique_ptr<frusta::HandSolver> solver;
  uint64_t hash = 0;
};

// FNV-1a over the bytes of what a step leaves: two builds that make the same hands and
// contacts to the bit hash alike
void mix(uint64_t& hash, const void* data, size_t size) {
  const unsigned char* bytes = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 1099511628211ull;
}

}  // namespace

// scene: a hand scenario's name, or empty for the deep grasp of a ball of `leaves` leaves
extern "C" void* FRUSTA_PAIRED(paired_make)(int32_t leaves, const char* scene) {
  using namespace frusta;
  auto* half = new Half{scene[0] != '\0' ? scenes::make_hand_scenario(scene)
                                         : scenes::ball_grasp(scenes::ball_shell(leaves, 0.04)),
                        make_hand_model(default_hand_def()), nullptr, 0};
  return half;
}

// the scripted steps and 200 held
extern "C" int32_t FRUSTA_PAIRED(paired_steps)(void* half) {
  return static_cast<Half*>(half)->scenario.steps + 200;
}

extern "C" void FRUSTA_PAIRED(paired_restart)(void* half) {
  Half& h = *static_cast<Half*>(half);
  h.solver = std::make_unique<frusta::HandSolver>(h.model, frusta::SolverParams{});
  h.hash = 1469598103934665603ull;
}

// step t of the scenario (the objects vouched for as unchanged after the first), in
// wall-clock microseconds
extern "C" double FRUSTA_PAIRED(paired_step)(void* half, int32_t t) {
  Half& h = *static_cast<Half*>(half);
  const frusta::scenes::HandScenario& s = h.scenario;
  const frusta::HandState haptic = t < s.steps ? s.haptic(t) : s.held;
  const auto start = std::chrono::steady_clock::now();
  h.solver->step(haptic, s.objects.data(), static_cast<int32_t>(s.objects.size()), nullptr,
                 std::chrono::steady_clock::time_point::max(), nullptr, t > 0);
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  const frusta::HandState& g = h.solver->graphic();
  mix(h.hash, &g.palm_position, sizeof g.palm_position);
  mix(h.hash, &g.palm_rotation, sizeof g.palm_rotation);
  mix(h.hash, g.angles.data(), sizeof(double) * g.angles.size());
  for (const frusta::SolverContact& c : h.solver->contacts()) {
    mix(h.hash, &c.object, sizeof c.object);
    mix(h.hash, &c.leaf, sizeof c.leaf);
    mix(h.hash, &c.body, sizeof c.body);
    mix(h.hash, &c.distance, sizeof c.distance);
  }
  return us;
}

extern "C" uint64_t FRUSTA_PAIRED(paired_hash)(void* half) { return static_cast<Half*>(half)->hash; }
