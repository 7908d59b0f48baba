// SPDX-License-Identifier: MIT
// The deep grasp's steps counted in instructions, under callgrind (tools/bench
// instructions): each step's work alone, one dump per step, which tools/bench turns into
// per-step percentiles and a profile by stage of the costliest steps. A shared or
// virtual machine's clock moved the same build's p99 by half between runs; the count of
// instructions does not move, so two builds compare in it to the instruction.
//
// frusta_bench_instructions [--leaves=N] [--whole]: the grasp of a 4 cm ball of N leaves
// (10^4), scripted then held as tools/bench solver runs it; --whole: every step's work
// in the one dump callgrind writes at exit instead. Run outside valgrind it only steps.
#include <valgrind/callgrind.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "scenes/hand_scenarios.h"
#include "solver/hand_solver.h"

int main(int argc, char** argv) {
  using namespace frusta;
  int32_t leaves = 10000;
  bool whole = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--leaves=", 0) == 0) leaves = std::atoi(arg.c_str() + 9);
    if (arg == "--whole") whole = true;
  }
  if (leaves < 1) {
    std::fprintf(stderr, "frusta_bench_instructions: --leaves must be at least 1\n");
    return 2;
  }
  const scenes::HandScenario s = scenes::ball_grasp(scenes::ball_shell(leaves, 0.04));
  const HandModel model = make_hand_model(default_hand_def());
  HandSolver solver(model, SolverParams{});
  constexpr int32_t kHeld = 200;  // as the solver suite's grasp rows
  double penetration = 0.0;
  int32_t failed = 0;
  for (int32_t t = 0; t < s.steps + kHeld; ++t) {
    const HandState haptic = t < s.steps ? s.haptic(t) : s.held;
    StepStats stats;
    if (!whole) CALLGRIND_ZERO_STATS;
    CALLGRIND_TOGGLE_COLLECT;
    const frusta_result r =
        solver.step(haptic, s.objects.data(), static_cast<int32_t>(s.objects.size()), &stats,
                    std::chrono::steady_clock::time_point::max(), nullptr, t > 0);
    CALLGRIND_TOGGLE_COLLECT;
    if (!whole) CALLGRIND_DUMP_STATS;
    failed += r != FRUSTA_OK;
    penetration =
        std::max(penetration, scenes::deepest_penetration(model, solver.graphic_pose(), s.objects));
  }
  std::printf(
      "{\"leaves\": %d, \"steps\": %d, \"failed_steps\": %d, \"max_penetration_mm\": %.6f, "
      "\"under_callgrind\": %s}\n",
      leaves, s.steps + kHeld, failed, penetration * 1e3, RUNNING_ON_VALGRIND ? "true" : "false");
  return failed == 0 ? 0 : 1;
}
