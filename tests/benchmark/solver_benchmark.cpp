// SPDX-License-Identifier: MIT
// tools/bench solver: the graphic-hand step, its time next to its error, in one run.
//  - every scenario of the acceptance list: p50 / p99 / max step time, contacts, QP
//    iterations, sub-steps, and the deepest penetration against the exact leaf set; the
//    objects stay put and the solver is told so, as a world tells it: a hand held still
//    rests (not solved), so each row also gives the steps at rest and the p50 / p99 of
//    the steps solved;
//  - both constraint forms on every scenario (robustness: penetration, failures);
//  - this machine's own noise first: a fixed piece of arithmetic timed 2,000 times;
//  - the deep grasp against balls of 10^2..10^6 leaves, with MuJoCo beside each row and,
//    up to 10^5, each step's least time over 5 runs (one run's p99 moves with the
//    machine's slow phases);
//    the level of detail's time against its error budget at 10^5 and 10^6 leaves; the
//    time-against-error knobs (Delta_r, iteration cap, tree level, budget) at 10^4;
//  - the thread question: a finger's solve against a thread hand-off, measured;
//  - a fingertip slid over sharp edges (scenes/edge_slides.h), per shape and speed over
//    every path and depth: the force's change per step (max, p99) against the contact
//    stiffness x the haptic move, its turn, the graphic fingertip's move per step against
//    twice the haptic one, the step time and the penetration;
//  - the step budget: every scenario and the 10^4-leaf grasp under the deadline the world
//    gives a hand, then tighter ones: time, steps over it, and the forces' continuity;
//  - detection alone (the tree walks) on the poses of the grasp and the over-budget
//    scenarios, fingers and palm apart;
//  - with FRUSTA_WITH_MUJOCO, the same grasp in MuJoCo, side by side (in the grasp rows).
// Prints one JSON document. Step times exclude the penetration checks. Arguments name
// the sections to run (scenarios free edges budget detection forms leaves lod knobs threads;
// default all); flags such as tools/bench's --benchmark_format are ignored, but for
// --leaves=N and --scene=NAME, which keep one row of the leaves, lod and budget sections (to
// profile it).
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "geometry/contact_test.h"
#include "geometry/exact_distance.h"
#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "runtime/world_def.h"
#include "bench_sections.h"
#include "percentile.h"
#include "forces/contact_forces.h"
#include "forces/force_params.h"
#include "scenes/baked_objects.h"
#include "scenes/edge_slides.h"
#include "scenes/hand_scenarios.h"
#include "solver/hand_solver.h"
#ifdef FRUSTA_WITH_MUJOCO
#include "mujoco_peer.h"
#endif

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;

double micros(Clock::duration d) { return std::chrono::duration<double, std::micro>(d).count(); }

using bench::percentile;

// This thread's CPU time, microseconds: what a step costs, without the time the OS gave
// other work meanwhile (a shared machine preempts a bench for milliseconds).
double thread_cpu_us() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return 1e6 * static_cast<double>(now.tv_sec) + 1e-3 * static_cast<double>(now.tv_nsec);
}

struct Measured {
  int32_t steps = 0, failed_steps = 0;
  std::vector<double> step_us, cpu_us;  // wall and this thread's CPU time of each step
  std::vector<double> solved_us;        // wall time of the steps that were not at rest
  int32_t resting = 0;                  // steps at rest (StepStats::resting): not solved
  int32_t max_contacts = 0, max_candidates = 0, max_substeps = 0;
  double qp_iterations = 0, iterations = 0, finger_solves = 0;
  double max_penetration = 0.0;  // metres
  double max_standoff = 0.0;     // metres a touching body stopped short of the leaves
  bool lagged = false, infeasible = false;
};

// How far short of the leaves the touching bodies stopped (the error of standing in
// for leaves by larger nodes): per body in contact, its exact gap to the nearest leaf.
double max_standoff(const HandModel& model, const HandSolver& solver, const std::vector<SolverObject>& objects) {
  double worst = 0.0;
  bool seen[kBodyCount] = {};
  for (const SolverContact& c : solver.contacts()) {
    if (seen[c.body] || c.body == kPalmBody) continue;
    seen[c.body] = true;
    const SegmentFrame frame = make_segment_frame(
        finger_segment(model, solver.graphic_pose(), c.body / FRUSTA_SEGMENTS_PER_FINGER, c.body % FRUSTA_SEGMENTS_PER_FINGER));
    double nearest = INFINITY;
    for (const SolverObject& o : objects)
      for (const Sphere& leaf : o.tree->leaves)
        if (may_touch(frame, {o.pose.rotation * leaf.center + o.pose.position, leaf.radius}, nearest))
          nearest = std::min(nearest, exact_distance(frame, {o.pose.rotation * leaf.center + o.pose.position, leaf.radius}));
    worst = std::max(worst, nearest);
  }
  return worst;
}

// The scripted part, then `hold` held steps; penetration checked every `check_every`.
Measured measure(const scenes::HandScenario& s, const SolverParams& params, int32_t hold, int32_t check_every) {
  const HandModel model = make_hand_model(default_hand_def());
  HandSolver solver(model, params);
  Measured m;
  const int32_t total = s.steps + hold;
  m.step_us.reserve(static_cast<size_t>(total));
  for (int32_t t = 0; t < total; ++t) {
    const HandState haptic = t < s.steps ? s.haptic(t) : s.held;
    StepStats stats;
    const double cpu_start = thread_cpu_us();
    const Clock::time_point start = Clock::now();
    // the objects stay put, as a world tells the solver of a still scene
    const frusta_result r = solver.step(haptic, s.objects.data(), static_cast<int32_t>(s.objects.size()), &stats,
                                        Clock::time_point::max(), nullptr, t > 0);
    m.step_us.push_back(micros(Clock::now() - start));
    m.cpu_us.push_back(thread_cpu_us() - cpu_start);
    if (stats.resting) ++m.resting; else m.solved_us.push_back(m.step_us.back());
    ++m.steps;
    if (r != FRUSTA_OK) {
      ++m.failed_steps;
      continue;
    }
    m.max_contacts = std::max(m.max_contacts, static_cast<int32_t>(solver.contacts().size()));
    m.max_candidates = std::max(m.max_candidates, stats.candidates);
    m.max_substeps = std::max(m.max_substeps, stats.substeps);
    m.qp_iterations += stats.qp_iterations;
    m.iterations += stats.iterations;
    m.finger_solves += stats.finger_solves;
    m.lagged |= stats.lagging;
    m.infeasible |= stats.infeasible;
    if (t == s.steps - 1) m.max_standoff = max_standoff(model, solver, s.objects);
    if (t % check_every == 0 || t == total - 1)
      m.max_penetration = std::max(m.max_penetration,
                                   scenes::deepest_penetration(model, solver.graphic_pose(), s.objects));
  }
  return m;
}

// Each step's least wall time over `runs` runs of the scenario, `first` among them: what
// the step costs here without this machine's slow phases (machine_noise_fixed_work), which
// move one run's p99 by a fifth. Each run checks the penetration as the first did (the
// checks read every leaf between steps, which leaves the next step's caches as cold).
std::vector<double> least_step_us(const scenes::HandScenario& s, const SolverParams& params, int32_t hold,
                                  int32_t check_every, const Measured& first, int32_t runs) {
  std::vector<double> least = first.step_us;
  for (int32_t r = 1; r < runs; ++r) {
    const Measured again = measure(s, params, hold, check_every);
    for (size_t t = 0; t < least.size() && t < again.step_us.size(); ++t)
      least[t] = std::min(least[t], again.step_us[t]);
  }
  return least;
}

// The same arithmetic (a dependent chain of multiply-adds, no memory) timed again and
// again: its spread is the machine's, not the solver's. On the 2-core VM these benches
// run on, a fifth of the samples took 1.25-1.3 times the least, in phases of 2-8 ms.
void print_machine_noise() {
  constexpr int kSamples = 2000;
  std::vector<double> us(kSamples);
  volatile double seed = 1.0;
  for (int i = 0; i < kSamples; ++i) {
    const Clock::time_point start = Clock::now();
    double x = seed;
    for (int k = 0; k < 20000; ++k) x = x * 1.0000001 + 1e-9;
    seed = x;
    us[static_cast<size_t>(i)] = micros(Clock::now() - start);
  }
  const double least = percentile(us, 0.0);
  int32_t slow = 0;
  for (double u : us) slow += u > 1.1 * least ? 1 : 0;
  std::printf("\"machine_noise_fixed_work\": {\"samples\": %d, \"least_us\": %.2f, \"p50_over_least\": %.3f, "
              "\"p99_over_least\": %.3f, \"share_over_1_1_least\": %.3f},\n",
              kSamples, least, percentile(us, 0.5) / least, percentile(us, 0.99) / least,
              static_cast<double>(slow) / kSamples);
}

void print_measured(const Measured& m) {
  const double n = std::max(1, m.steps);
  std::printf("\"steps\": %d, \"failed_steps\": %d, \"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f, "
              "\"max_contacts\": %d, \"max_candidates\": %d, \"max_substeps\": %d, "
              "\"qp_iterations_per_step\": %.2f, \"linearisations_per_step\": %.2f, "
              "\"finger_solves_per_step\": %.2f, \"lagged\": %s, \"infeasible_qp\": %s, "
              "\"max_penetration_mm\": %.6f, \"max_standoff_mm\": %.4f, \"cpu_p50_us\": %.2f, "
              "\"cpu_p99_us\": %.2f, \"cpu_max_us\": %.2f, \"resting_steps\": %d, \"solved_p50_us\": %.2f, "
              "\"solved_p99_us\": %.2f",
              m.steps, m.failed_steps, percentile(m.step_us, 0.5), percentile(m.step_us, 0.99),
              percentile(m.step_us, 1.0), m.max_contacts, m.max_candidates, m.max_substeps,
              m.qp_iterations / n, m.iterations / n, m.finger_solves / n, m.lagged ? "true" : "false",
              m.infeasible ? "true" : "false", m.max_penetration * 1e3, m.max_standoff * 1e3,
              percentile(m.cpu_us, 0.5), percentile(m.cpu_us, 0.99), percentile(m.cpu_us, 1.0), m.resting,
              percentile(m.solved_us, 0.5), percentile(m.solved_us, 0.99));
}

// runs of the grasp rows up to 10^5 leaves whose steps' least times give their second p99
constexpr int32_t kLeastOfRuns = 5;

// One finger's solve is microseconds: a hand-off to another thread and back is the
// least a parallel solve pays per step. Spinning (a core burnt per worker) and
// sleeping (a condition variable, what a shared machine allows) are both measured.
double spin_round_trip_us() {
  std::atomic<int> turn{0};
  constexpr int kRounds = 20000;
  std::thread other([&] {
    for (int i = 0; i < kRounds; ++i) {
      while (turn.load(std::memory_order_acquire) != 1) {
      }
      turn.store(0, std::memory_order_release);
    }
  });
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < kRounds; ++i) {
    turn.store(1, std::memory_order_release);
    while (turn.load(std::memory_order_acquire) != 0) {
    }
  }
  const double us = micros(Clock::now() - start) / kRounds;
  other.join();
  return us;
}

double sleep_round_trip_us() {
  std::mutex mutex;
  std::condition_variable changed;
  int turn = 0;
  constexpr int kRounds = 5000;
  std::thread other([&] {
    for (int i = 0; i < kRounds; ++i) {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [&] { return turn == 1; });
      turn = 0;
      changed.notify_one();
    }
  });
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < kRounds; ++i) {
    std::unique_lock<std::mutex> lock(mutex);
    turn = 1;
    changed.notify_one();
    changed.wait(lock, [&] { return turn == 0; });
  }
  const double us = micros(Clock::now() - start) / kRounds;
  other.join();
  return us;
}

// A scenario stepped as the world's own thread steps one hand: each step has the step
// budget's deadline (kStepBudgetShare of a `period_us` period, or `budget_us` where
// given), and the forces follow the solver's lag. Time against error: the step time
// (solver and forces) and the steps over the budget, beside how often the budget bound,
// how far the lag limit held a push back, how far a body's push changed beyond the
// continuity bound where it bound, and the penetration.
struct Budgeted {
  std::vector<double> step_us, cpu_us;  // wall and CPU time of each step
  int32_t over = 0, lagged = 0;
  double held_back_max_n = 0.0, continuity_excess_max_n = -INFINITY, penetration = 0.0;
};

Budgeted measure_budgeted(const scenes::HandScenario& s, double budget_us, int32_t hold, int32_t check_every) {
  const HandModel model = make_hand_model(default_hand_def());
  HandSolver solver(model, SolverParams{});
  ContactForces forces;
  Budgeted b;
  const int32_t count = static_cast<int32_t>(s.objects.size());
  std::array<vec3, kBodyCount> before{};
  HandPose haptic_before;
  const auto budget = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double, std::micro>(budget_us));
  for (int32_t t = 0; t < s.steps + hold; ++t) {
    StepStats stats;
    ContactForceStats force_stats;
    const double cpu_start = thread_cpu_us();
    const Clock::time_point start = Clock::now();
    if (solver.step(t < s.steps ? s.haptic(t) : s.held, s.objects.data(), count, &stats, start + budget,
                    nullptr, t > 0) != FRUSTA_OK)
      continue;
    if (!solver.started()) {  // being placed over several steps: no hand to touch with yet
      const double cpu = thread_cpu_us() - cpu_start;
      b.cpu_us.push_back(cpu);
      b.step_us.push_back(micros(Clock::now() - start));
      b.over += cpu > budget_us ? 1 : 0;
      b.lagged += 1;
      continue;
    }
    forces.update(solver.graphic_pose(), solver.target_pose(), solver.contacts().data(),
                  static_cast<int32_t>(solver.contacts().size()), s.objects.data(), count, nullptr, &force_stats,
                  stats.lagging);
    const double us = micros(Clock::now() - start), cpu = thread_cpu_us() - cpu_start;
    b.step_us.push_back(us);
    b.cpu_us.push_back(cpu);
    b.over += cpu > budget_us ? 1 : 0;
    b.lagged += stats.lagging ? 1 : 0;
    b.held_back_max_n = std::max(b.held_back_max_n, force_stats.held_back_by);
    std::array<vec3, kBodyCount> push{};
    for (const ContactForce& f : forces.forces()) push[static_cast<size_t>(f.body)] += f.normal_force;
    if (t > 0 && (stats.lagging || force_stats.held_back > 0))
      for (int body = 0; body < kBodyCount; ++body)
        b.continuity_excess_max_n = std::max(
            b.continuity_excess_max_n,
            std::fabs(glm::length(push[static_cast<size_t>(body)]) - glm::length(before[static_cast<size_t>(body)])) -
                kDefaultContactStiffness * scenes::body_move(model, haptic_before, solver.target_pose(), body));
    before = push;
    haptic_before = solver.target_pose();
    if (t % check_every == 0)
      b.penetration = std::max(b.penetration, scenes::deepest_penetration(model, solver.graphic_pose(), s.objects));
  }
  return b;
}

void print_budgeted(const Budgeted& b, double budget_us) {
  std::printf("\"budget_us\": %.0f, \"steps\": %zu, \"cpu_p50_us\": %.2f, \"cpu_p99_us\": %.2f, "
              "\"cpu_max_us\": %.2f, \"wall_max_us\": %.2f, \"steps_over_budget_cpu\": %d, "
              "\"steps_budget_bound\": %d, \"push_held_back_max_n\": %.4f, "
              "\"push_change_over_stiffness_x_move_max_n\": %s, \"max_penetration_mm\": %.6f",
              budget_us, b.cpu_us.size(), percentile(b.cpu_us, 0.5), percentile(b.cpu_us, 0.99),
              percentile(b.cpu_us, 1.0), percentile(b.step_us, 1.0), b.over, b.lagged, b.held_back_max_n,
              std::isfinite(b.continuity_excess_max_n) ? std::to_string(b.continuity_excess_max_n).c_str() : "null",
              b.penetration * 1e3);
}

}  // namespace
}  // namespace frusta

int main(int argc, char** argv) {
  using namespace frusta;
  const bench::Sections sections(argc, argv);
  // to profile one row: --leaves=N keeps the leaves section's N-leaf grasp alone (no
  // node-radius row), --scene=NAME the budget section's scenario at the world's budget
  int32_t only_leaves = 0;
  std::string only_scene;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--leaves=", 0) == 0) only_leaves = std::atoi(arg.c_str() + 9);
    if (arg.rfind("--scene=", 0) == 0) only_scene = arg.substr(8);
  }
  auto wanted = [&](const char* section) { return sections.wanted(section); };
  const SolverParams defaults;
  const std::vector<std::string> names = scenes::hand_scenario_names();
  std::printf("{\n\"suite\": \"solver\",\n\"hardware_threads\": %u,\n", std::thread::hardware_concurrency());
  std::printf("\"defaults\": {\"prediction_margin_mm\": %.3f, \"form\": \"distance\", \"max_iterations\": %d, "
              "\"penetration_tolerance_mm\": %.4f},\n",
              defaults.prediction_margin * 1e3, defaults.max_iterations, defaults.penetration_tolerance * 1e3);
  print_machine_noise();

  // the acceptance scenarios, each scripted then held 1,000 steps
  double finger_solve_us = 0.0;
  if (wanted("scenarios")) {
  std::printf("\"scenarios\": [\n");
  for (size_t i = 0; i < names.size(); ++i) {
    const scenes::HandScenario s = scenes::make_hand_scenario(names[i]);
    const Measured m = measure(s, defaults, 1000, 1);
    if (names[i] == "ball_grasp") finger_solve_us = percentile(m.step_us, 0.5) / std::max(1.0, m.finger_solves / m.steps);
    std::printf("  {\"name\": \"%s\", ", names[i].c_str());
    print_measured(m);
    std::printf("}%s\n", i + 1 < names.size() ? "," : "");
  }
  std::printf("],\n");
  }

  // nothing near: a hand waving among 20 objects half a metre away (the cost of a scene
  // the hand is not touching: bounds only, no detection, no solve)
  if (wanted("free")) {
    scenes::HandScenario s;
    for (int k = 0; k < 20; ++k)
      s.add(scenes::sample_tree(k % 2 ? "mug" : "ball"),
            {vec3(0.5 * std::cos(0.314 * k), 0.5 * std::sin(0.314 * k), 0.1 * (k % 3)), glm::dmat3(1.0)});
    HandState open = scenes::open_hand(), closed = open;
    for (int f = 0; f < 5; ++f) scenes::set_flexion(closed, f, 1.2, 1.2, 1.0);
    s.steps = 1000;
    s.haptic = [open, closed](int32_t t) {
      HandState h = scenes::mix(open, closed, 0.5 + 0.5 * std::sin(0.02 * t));
      h.palm_position = vec3(0.05 * std::sin(0.01 * t), 0.05 * std::cos(0.013 * t), 0.0);
      return h;
    };
    s.held = closed;
    const Measured m = measure(s, defaults, 0, 50);
    std::printf("\"free_space_20_objects\": {");
    print_measured(m);
    std::printf("},\n");
  }

  // a fingertip slid over sharp edges: continuity and its cost, per shape and speed
  if (wanted("edges")) {
    std::printf("\"edges\": [\n");
    const std::vector<std::string> shapes = scenes::edge_shape_names();
    const double speeds[] = {0.1, 0.5, 1.0};
    for (size_t i = 0; i < shapes.size(); ++i)
      for (size_t v = 0; v < std::size(speeds); ++v) {
        std::vector<double> jumps, turns, step_us;
        double move = 0.0, move_excess = -INFINITY, force_excess = -INFINITY, deepest = 0.0, most = 0.0;
        int32_t failed = 0;
        for (const scenes::EdgePath path : scenes::kEdgePaths)
          for (int mm = 1; mm <= 5; ++mm) {
            const scenes::HandScenario s = scenes::edge_slide(shapes[i], path, speeds[v], mm * 1e-3);
            const std::vector<scenes::EdgeSlideStep> log = scenes::run_edge_slide(s, defaults, true, true);
            failed += s.steps - static_cast<int32_t>(log.size());
            for (const scenes::EdgeSlideStep& k : log) {
              jumps.push_back(k.force_change);
              turns.push_back(k.force_turn);
              step_us.push_back(k.step_us);
              move = std::max(move, k.graphic_move);
              move_excess = std::max(move_excess, k.graphic_move - 2.0 * k.haptic_move);
              force_excess = std::max(force_excess, k.force_change - kDefaultContactStiffness * k.haptic_move);
              deepest = std::max(deepest, k.penetration);
              most = std::max(most, k.force);
            }
          }
        std::printf("  {\"shape\": \"%s\", \"speed_m_s\": %.1f, \"steps\": %zu, \"failed_steps\": %d, "
                    "\"force_jump_max_n\": %.4f, \"force_jump_p99_n\": %.4f, "
                    "\"force_jump_over_stiffness_x_move_max_n\": %.4f, \"force_turn_max_n\": %.4f, "
                    "\"force_turn_p99_n\": %.4f, \"graphic_move_max_mm\": %.4f, "
                    "\"graphic_move_over_twice_haptic_max_mm\": %.4f, \"max_force_n\": %.3f, "
                    "\"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f, \"max_penetration_mm\": %.6f}%s\n",
                    shapes[i].c_str(), speeds[v], jumps.size(), failed, percentile(jumps, 1.0),
                    percentile(jumps, 0.99), force_excess, percentile(turns, 1.0), percentile(turns, 0.99),
                    move * 1e3, move_excess * 1e3, most, percentile(step_us, 0.5), percentile(step_us, 0.99),
                    percentile(step_us, 1.0), deepest * 1e3,
                    i + 1 == shapes.size() && v + 1 == std::size(speeds) ? "" : ",");
      }
    std::printf("],\n");
  }

  // the step budget (issue 20, Build 3): every scenario and the 10^4-leaf deep grasp with
  // the deadline the world's own thread gives one hand at 1 kHz; then budgets that bind
  if (wanted("budget")) {
    std::printf("\"budget\": [\n");
    const double period_budget_us = 1e3 * kStepBudgetShare;
    std::vector<std::pair<std::string, scenes::HandScenario>> runs;
    for (const std::string& name : names) runs.emplace_back(name, scenes::make_hand_scenario(name));
    runs.emplace_back("ball_grasp_10k_leaves", scenes::ball_grasp(scenes::ball_shell(10000, 0.04)));
    for (const auto& [name, s] : runs) {
      if (!only_scene.empty() && name != only_scene) continue;
      std::printf("  {\"name\": \"%s\", ", name.c_str());
      print_budgeted(measure_budgeted(s, period_budget_us, 200, 5), period_budget_us);
      std::printf("},\n");
    }
    for (double tight_us : {100.0, 30.0}) {
      if (!only_scene.empty()) break;
      std::printf("  {\"name\": \"ball_grasp_10k_leaves\", ");
      print_budgeted(measure_budgeted(runs.back().second, tight_us, 200, 5), tight_us);
      std::printf("},\n");
    }
    std::printf("  {\"end\": true}\n],\n");
  }

  // detection alone (issue 21): the tree walks of every body, timed on the graphic hands
  // the grasp against 10^3..10^6 leaves and the over-budget scenarios step through, with
  // the palm's share apart (the same walks on a hand without palm spheres); CPU time
  if (wanted("detection")) {
    std::printf("\"detection\": [\n");
    std::vector<std::pair<std::string, scenes::HandScenario>> runs;
    for (int32_t leaves : {1000, 10000, 100000, 1000000})
      runs.emplace_back("ball_grasp_" + std::to_string(leaves) + "_leaves",
                        scenes::ball_grasp(scenes::ball_shell(leaves, 0.04)));
    for (const char* name : {"plate_teleport", "start_inside"})
      runs.emplace_back(name, scenes::make_hand_scenario(name));
    for (size_t r = 0; r < runs.size(); ++r) {
      const scenes::HandScenario& s = runs[r].second;
      const HandModel model = make_hand_model(default_hand_def());
      HandModel fingers_only = model;
      fingers_only.palm_spheres.clear();
      const HandReach reach = hand_reach(model);
      HandSolver solver(model, defaults);
      std::vector<HandPose> poses;
      for (int32_t t = 0; t < s.steps + 200; ++t)
        if (solver.step(t < s.steps ? s.haptic(t) : s.held, s.objects.data(),
                        static_cast<int32_t>(s.objects.size()), nullptr) == FRUSTA_OK)
          poses.push_back(solver.graphic_pose());
      CandidateSet set;
      std::vector<double> whole_us, fingers_us;
      int32_t most = 0, most_palm = 0;
      double visited = 0.0;
      for (int pass = 0; pass < 2; ++pass)  // the first warms the scratch buffers
        for (const HandPose& pose : poses)
          for (int palm = 1; palm >= 0; --palm) {
            const double start = thread_cpu_us();
            detect_candidates(palm ? model : fingers_only, reach, pose, s.objects.data(),
                              static_cast<int32_t>(s.objects.size()), defaults.prediction_margin,
                              TreeCut(defaults.tree_level, defaults.lod_error), set);
            const double us = thread_cpu_us() - start;
            if (pass == 0) continue;
            (palm ? whole_us : fingers_us).push_back(us);
            if (palm) {
              most = std::max(most, set.size());
              most_palm = std::max(most_palm, set.count(kPalmBody));
              visited += set.tree_nodes_visited;
            }
          }
      std::vector<double> palm_us(whole_us.size());
      for (size_t i = 0; i < whole_us.size(); ++i) palm_us[i] = whole_us[i] - fingers_us[i];
      std::printf("  {\"name\": \"%s\", \"poses\": %zu, \"cpu_p50_us\": %.2f, \"cpu_p99_us\": %.2f, "
                  "\"cpu_max_us\": %.2f, \"fingers_cpu_p50_us\": %.2f, \"fingers_cpu_p99_us\": %.2f, "
                  "\"palm_cpu_p50_us\": %.2f, \"palm_cpu_p99_us\": %.2f, \"max_candidates\": %d, "
                  "\"max_palm_candidates\": %d, \"nodes_visited_per_call\": %.1f}%s\n",
                  runs[r].first.c_str(), poses.size(), percentile(whole_us, 0.5), percentile(whole_us, 0.99),
                  percentile(whole_us, 1.0), percentile(fingers_us, 0.5), percentile(fingers_us, 0.99),
                  percentile(palm_us, 0.5), percentile(palm_us, 0.99), most, most_palm,
                  visited / std::max(1.0, static_cast<double>(poses.size())), r + 1 < runs.size() ? "," : "");
    }
    std::printf("],\n");
  }

  // the two constraint forms on the same scripts
  if (wanted("forms")) {
  std::printf("\"forms\": [\n");
  for (int f = 0; f < 2; ++f) {
    SolverParams p = defaults;
    p.form = f == 0 ? ConstraintForm::kSquared : ConstraintForm::kDistance;
    for (size_t i = 0; i < names.size(); ++i) {
      const Measured m = measure(scenes::make_hand_scenario(names[i]), p, 200, 1);
      std::printf("  {\"form\": \"%s\", \"name\": \"%s\", ", f == 0 ? "squared" : "distance", names[i].c_str());
      print_measured(m);
      std::printf("}%s\n", f == 1 && i + 1 == names.size() ? "" : ",");
    }
  }
  std::printf("],\n");
  }

  // the deep grasp against ever denser balls
  if (wanted("leaves")) {
  std::printf("\"grasp_by_leaves\": [\n");
  const int32_t counts[] = {100, 1000, 4000, 10000, 100000, 1000000};
  for (size_t i = 0; i < std::size(counts); ++i) {
    if (only_leaves > 0 && counts[i] != only_leaves) continue;
    const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(counts[i], 0.04);
    const scenes::HandScenario s = scenes::ball_grasp(ball);
    const int32_t check_every = counts[i] >= 100000 ? 10 : 1;
    const Measured m = measure(s, defaults, 200, check_every);
    std::printf("  {\"leaves\": %d, \"tree_depth\": %d, ", counts[i], ball->tree.depth);
    print_measured(m);
    if (counts[i] <= 100000) {
      const std::vector<double> least = least_step_us(s, defaults, 200, check_every, m, kLeastOfRuns);
      std::printf(", \"least_of_%d_runs\": {\"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f}", kLeastOfRuns,
                  percentile(least, 0.5), percentile(least, 0.99), percentile(least, 1.0));
    }
#ifdef FRUSTA_WITH_MUJOCO
    // MuJoCo's default contacts, then the stiffest stable at 1 ms (what a user tunes to);
    // above 10^4 leaves only the latter (MuJoCo tests every leaf each step), and not at
    // 10^6: MuJoCo 2.2.2 compiles a body's geoms in time quadratic in their number
    // (mj_loadXML of one body's spheres: 0.3 s for 10^4, 1.1 s for 2x10^4, 5.0 s for
    // 4x10^4), about 50 minutes for 10^6
    if (counts[i] > 100000) {
      std::printf(", \"mujoco_stiff_contacts\": {\"error\": \"not run: MuJoCo 2.2.2 loads one body of N "
                  "spheres in time quadratic in N (5.0 s at 4x10^4; about 50 min at 10^6)\"}");
    } else {
      std::vector<Sphere> world;
      for (const Sphere& leaf : ball->tree.leaves) world.push_back({leaf.center + s.objects[0].pose.position, leaf.radius});
      for (double time_constant : {0.0, 0.002}) {
        if (time_constant == 0.0 && counts[i] > 10000) continue;
        const bench::PeerResult peer = bench::run_mujoco_grasp(
            make_hand_model(default_hand_def()), world, s.steps + 200,
            [&](int32_t t) { return t < s.steps ? s.haptic(t) : s.held; }, time_constant);
        const char* key = time_constant > 0.0 ? "mujoco_stiff_contacts" : "mujoco";
        if (peer.ok)
          std::printf(", \"%s\": {\"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f, \"max_contacts\": %d, "
                      "\"max_penetration_mm\": %.6f, \"load_s\": %.2f, \"p50_ratio_mujoco_over_frusta\": %.2f, "
                      "\"p99_ratio_mujoco_over_frusta\": %.2f}",
                      key, peer.p50_us, peer.p99_us, peer.max_us, peer.max_contacts, peer.max_penetration_mm, peer.load_s,
                      peer.p50_us / std::max(1e-9, percentile(m.step_us, 0.5)),
                      peer.p99_us / std::max(1e-9, percentile(m.step_us, 0.99)));
        else
          std::printf(", \"%s\": {\"error\": \"%s\"}", key, peer.error.c_str());
      }
    }
#endif
    std::printf("},\n");
  }
  std::printf("  {\"end\": true}\n],\n");
  }

  // time against error: the same grasp with nodes that stand out of their leaves by no
  // more than the budget standing in for them (the penetration is against the leaves)
  if (wanted("lod")) {
    std::printf("\"lod_curve\": [\n");
    for (int32_t leaves : {100000, 1000000}) {
      if (only_leaves > 0 && leaves != only_leaves) continue;
      const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(leaves, 0.04);
      const scenes::HandScenario s = scenes::ball_grasp(ball);
      for (double budget : {0.0, 0.00005, 0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.003}) {
        SolverParams p = defaults;
        p.lod_error = budget;
        const Measured m = measure(s, p, 200, 10);
        std::printf("  {\"leaves\": %d, \"lod_error_mm\": %g, ", leaves, budget * 1e3);
        print_measured(m);
        std::printf("},\n");
      }
    }
    std::printf("  {\"end\": true}\n],\n");
  }

  // the knobs, one at a time, on the 10^4-leaf grasp
  if (wanted("knobs")) {
  std::printf("\"grasp_knobs_10k_leaves\": [\n");
  const scenes::HandScenario grasp = scenes::ball_grasp(scenes::ball_shell(10000, 0.04));
  struct Knob {
    const char* name;
    double value;
    SolverParams params;
  };
  std::vector<Knob> knobs;
  for (double margin : {0.001, 0.002, 0.004}) {
    SolverParams p = defaults;
    p.prediction_margin = margin;
    knobs.push_back({"prediction_margin_mm", margin * 1e3, p});
  }
  for (int cap : {1, 2, 5, 20}) {
    SolverParams p = defaults;
    p.max_iterations = cap;
    knobs.push_back({"max_iterations", static_cast<double>(cap), p});
  }
  for (int level : {2, 3, 4, -1}) {
    SolverParams p = defaults;
    p.tree_level = level;
    knobs.push_back({"tree_level", static_cast<double>(level), p});
  }
  for (double budget : {0.00025, 0.0005, 0.001}) {
    SolverParams p = defaults;
    p.lod_error = budget;
    knobs.push_back({"lod_error_mm", budget * 1e3, p});
  }
  for (size_t i = 0; i < knobs.size(); ++i) {
    const Measured m = measure(grasp, knobs[i].params, 200, 1);
    std::printf("  {\"knob\": \"%s\", \"value\": %g, ", knobs[i].name, knobs[i].value);
    print_measured(m);
    std::printf("}%s\n", i + 1 < knobs.size() ? "," : "");
  }
  std::printf("],\n");
  }

  if (wanted("threads"))
    std::printf("\"threads\": {\"finger_solve_us\": %.2f, \"spin_round_trip_us\": %.3f, "
                "\"sleep_round_trip_us\": %.3f},\n",
                finger_solve_us, spin_round_trip_us(), sleep_round_trip_us());
  std::printf("\"end\": true\n}\n");
  return 0;
}
