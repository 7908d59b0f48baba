// SPDX-License-Identifier: MIT
// tools/bench runtime: what the 1 kHz thread's plumbing costs, in one run.
//  - wake-up lateness of the periodic clock at 1 kHz for several spin windows (0 =
//    sleep only), with the CPU time each costs, so jitter and burnt CPU sit side by side;
//  - the cost of reading the output snapshot (a triple buffer) in nanoseconds, with the
//    writer idle and with it publishing flat out.
//  - the world's step time with 1 and 2 hands (each grasping its own ball) among 1, 5
//    and 20 objects, on the host's loop, and one hand's grasp held exactly still (at
//    rest: not solved). Every other held grasp here trembles (held_grasp), as a hand
//    does, so its steps are solved;
//  - a room: one hand in the deep grasp of one ball among 1,000 props (4000-leaf balls
//    spread over 10 x 10 x 3 m), beside the same grasp with that ball alone (in a world
//    of the default 64 object slots and in one of the room's 1,000), stepped in turn,
//    each step's least time over 3 runs, and the room's ratio to the one-object scene
//    (issue 21: within 10 %);
//  - what hand slots cost: the step time with one hand present in worlds of 1, 8 and 64
//    hand slots (a free hand, where the step's own plumbing shows, and a grasping one),
//    and the bytes an empty slot holds;
//  - what a hand that comes and goes costs the host: add_hand (its whole pipeline is
//    allocated here), remove_hand, and the read that frees it;
//  - what timed input costs a step: the same free and grasping hand fed one stamped
//    sample a step (set_haptic_at) against one untimed (set_haptic), and with a
//    host that stalls 5-50 ms and catches up in bursts;
//  - objects on a table (runtime/object_contact.h): the step time of a marble, a 1 kg
//    box and a box on a box dropped on the samples' table, while they fall and settle
//    and once at rest, beside how far from the nominal height each rests; and one
//    resting pair's contact walked (both trees) against answered from the contact cache.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <thread>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "hand/anthropometry.h"
#include "hand/hand_model.h"
#include "core/periodic_clock.h"
#include "runtime/contact_cache.h"
#include "runtime/world.h"
#include "scenes/baked_objects.h"
#include "scenes/hand_scenarios.h"
#include "scenes/jittery_host.h"
#include "core/step_histogram.h"
#include "core/triple_buffer.h"
#include "percentile.h"

namespace frusta {
namespace {

using Clock = std::chrono::steady_clock;

// The deep grasp's haptic hand at step t, held after its script as a steady hand holds a
// ball: with a tremor (0.1 mm at 8 Hz), so that every step is solved. A hand held
// exactly still in a still scene rests (HandSolver::step) and costs a step ~2 us: the
// world-steps row "held": "still".
HandState held_grasp(const scenes::HandScenario& grasp, int64_t t, bool tremor = true) {
  HandState state = grasp.haptic(static_cast<int32_t>(std::min<int64_t>(t, grasp.steps - 1)));
  if (tremor && t >= grasp.steps)
    state.palm_position.z += 1e-4 * std::sin(2.0 * glm::pi<double>() * 8.0 * 1e-3 * static_cast<double>(t));
  return state;
}

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void wake_up(int spin_us, bool last) {
  PeriodicClock clock(std::chrono::milliseconds(1), std::chrono::microseconds(spin_us));
  StepHistogram lateness;
  constexpr int kTicks = 2000;
  const double cpu0 = thread_cpu_seconds();
  clock.start();
  for (int i = 0; i < kTicks; ++i)
    lateness.record(std::chrono::duration<double, std::micro>(clock.wait()).count());
  const double cpu = thread_cpu_seconds() - cpu0;
  std::printf("  {\"spin_us\": %d, \"ticks\": %d, \"late_p50_us\": %.2f, \"late_p99_us\": %.2f, "
              "\"late_max_us\": %.2f, \"missed\": %lld, \"cpu_share\": %.3f}%s\n",
              spin_us, kTicks, lateness.percentile(0.5), lateness.percentile(0.99), lateness.max(),
              static_cast<long long>(clock.missed()), cpu / (kTicks * 1e-3), last ? "" : ",");
}

// a snapshot the size the world will publish: two hands, contacts, forces (~8 KB)
struct Snapshot {
  uint64_t step;
  double payload[1024];
};

double read_ns(bool writer_busy) {
  static TripleBuffer<Snapshot> buffer;
  std::atomic<bool> done{false};
  std::thread writer;
  if (writer_busy)
    writer = std::thread([&] {
      for (uint64_t s = 0; !done.load(std::memory_order_relaxed); ++s) {
        buffer.write_slot().step = s;
        buffer.publish();
      }
    });
  constexpr int kReads = 2000000;
  uint64_t sum = 0;
  const Clock::time_point start = Clock::now();
  for (int i = 0; i < kReads; ++i) sum += buffer.read().step;
  const double ns = std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kReads;
  done = true;
  if (writer.joinable()) writer.join();
  if (sum == 1) std::printf(" ");  // keeps the reads from being optimised away
  return ns;
}

void world_steps(int hands, int objects, bool tremor, bool last) {
  World world(WorldDef{});
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(2000, 0.04);
  HandDef left_def = default_hand_def();
  left_def.side = FRUSTA_HAND_LEFT;
  // the left hand grasps its own ball half a metre away (its palm there too)
  const vec3 offsets[2] = {vec3(0.0), vec3(0.0, 0.5, 0.0)};
  HandHandle handles[2];
  for (int h = 0; h < hands; ++h) {
    world.add_hand(make_hand_model(h == 0 ? default_hand_def() : left_def), &handles[h]);
    ObjectHandle handle;
    world.add_object(ball, RigidPose{offsets[h] + vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)}, &handle);
  }
  for (int k = hands; k < objects; ++k) {
    ObjectHandle handle;
    world.add_object(ball, RigidPose{vec3(0.8 * std::cos(0.3 * k), 0.8 * std::sin(0.3 * k), 0.3), glm::dmat3(1.0)}, &handle);
  }
  const scenes::HandScenario grasp = scenes::ball_grasp(ball);
  StepHistogram steps;
  constexpr int kWarm = 300, kMeasured = 2000;
  for (int t = 0; t < kWarm + kMeasured; ++t) {
    for (int h = 0; h < hands; ++h) {
      HandState haptic = held_grasp(grasp, t, tremor);
      haptic.palm_position += offsets[h];
      world.set_haptic(handles[h], haptic);
    }
    const Clock::time_point start = Clock::now();
    world.step();
    if (t >= kWarm) steps.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  const WorldSnapshot& s = world.read();
  std::printf("  {\"hands\": %d, \"objects\": %d, \"held\": \"%s\", \"leaves_per_ball\": 2000, \"steps\": %d, "
              "\"p50_us\": %.2f, \"p99_us\": %.2f, \"max_us\": %.2f, \"contacts_hand0\": %d}%s\n",
              hands, objects, tremor ? "tremor" : "still", kMeasured, steps.percentile(0.5), steps.percentile(0.99), steps.max(),
              s.hand(handles[0])->contact_count, last ? "" : ",");
}

// One hand in ball_grasp's deep grasp of its ball, among `objects` - 1 props (a shared
// 4000-leaf ball of 10 cm radius) on a 10 x 10 x 10 grid over a 10 x 10 x 3 m room, in
// a world of `slots` object slots. Props are kinematic, as a room's furniture is.
class RoomScene {
 public:
  RoomScene(int objects, int slots) : world_(room_def(objects, slots)) {
    static const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(2000, 0.04);
    static const std::shared_ptr<const TreeFile> prop = scenes::ball_shell(4000, 0.10);
    world_.add_hand(make_hand_model(default_hand_def()), &hand_);
    ObjectHandle handle;
    world_.add_object(ball, RigidPose{vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)}, &handle);
    // grid points 1 x 1 x 0.3 m apart, none nearer the hand than 0.7 m
    for (int k = 1; k < objects; ++k) {
      const vec3 at(-4.5 + k % 10, -4.5 + (k / 10) % 10, -1.35 + 0.3 * (k / 100));
      world_.add_object(prop, RigidPose{at, glm::dmat3(1.0)}, &handle);
    }
    grasp_ = scenes::ball_grasp(ball);
  }
  // step t's time, microseconds
  double step(int64_t t) {
    world_.set_haptic(hand_, held_grasp(grasp_, t));
    const Clock::time_point start = Clock::now();
    world_.step();
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
  }
  int32_t contacts() { return world_.read().hand(hand_)->contact_count; }

 private:
  static WorldDef room_def(int objects, int slots) {
    WorldDef def;
    def.max_objects = slots;
    def.command_capacity = std::max(def.command_capacity, objects + 16);
    return def;
  }
  World world_;
  HandHandle hand_;
  scenes::HandScenario grasp_;
};

void room() {
  struct Scene {
    int objects, slots;
    std::vector<double> least;  // each measured step's least time over the runs
    int32_t contacts = 0;
  } rows[] = {{1, WorldDef{}.max_objects, {}}, {1, 1000, {}}, {1000, 1000, {}}};
  // The scenes step in turn, one step each, and each step keeps its least time over 3
  // runs: the machine's slow phases (a few milliseconds, up to 1.6 times as slow) fall on
  // every scene alike, where 2,000 steps of one scene and then of the next had moved the
  // ratio's p99 between 1.00 and 1.22 from run to run.
  constexpr int kRuns = 3, kWarm = 300, kMeasured = 2000;
  for (Scene& s : rows) s.least.assign(kMeasured, INFINITY);
  for (int run = 0; run < kRuns; ++run) {
    std::vector<std::unique_ptr<RoomScene>> scenes;
    for (const Scene& s : rows) scenes.push_back(std::make_unique<RoomScene>(s.objects, s.slots));
    for (int t = 0; t < kWarm + kMeasured; ++t)
      for (size_t k = 0; k < scenes.size(); ++k) {
        const double us = scenes[k]->step(t);
        if (t >= kWarm) rows[k].least[t - kWarm] = std::min(rows[k].least[t - kWarm], us);
      }
    for (size_t k = 0; k < scenes.size(); ++k) rows[k].contacts = scenes[k]->contacts();
  }
  std::printf("\"room\": {\"scenes\": [\n");
  for (const Scene& s : rows)
    std::printf("  {\"objects\": %d, \"max_objects\": %d, \"steps\": %d, \"runs\": %d, \"p50_us\": %.2f, "
                "\"p99_us\": %.2f, \"max_us\": %.2f, \"contacts\": %d}%s\n",
                s.objects, s.slots, kMeasured, kRuns, bench::percentile(s.least, 0.5),
                bench::percentile(s.least, 0.99), bench::percentile(s.least, 1.0), s.contacts,
                &s == &rows[2] ? "" : ",");
  const std::vector<double>& one = rows[0].least;
  const std::vector<double>& many = rows[2].least;
  double one_sum = 0.0, many_sum = 0.0;
  for (int t = 0; t < kMeasured; ++t) {
    one_sum += one[t];
    many_sum += many[t];
  }
  std::printf("], \"ratio_to_one_object\": {\"p50\": %.3f, \"p99\": %.3f, \"max\": %.3f, \"all_steps\": %.3f}},\n",
              bench::percentile(many, 0.5) / bench::percentile(one, 0.5),
              bench::percentile(many, 0.99) / bench::percentile(one, 0.99),
              bench::percentile(many, 1.0) / bench::percentile(one, 1.0), many_sum / one_sum);
}

// One hand present, free or grasping a ball, in a world of `slots` hand slots.
void hand_slots(int slots, bool grasping, bool last) {
  WorldDef def;
  def.max_hands = slots;
  World world(def);
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(2000, 0.04);
  HandHandle hand;
  world.add_hand(make_hand_model(default_hand_def()), &hand);
  ObjectHandle handle;
  world.add_object(ball, RigidPose{vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)}, &handle);
  const scenes::HandScenario grasp = scenes::ball_grasp(ball);
  const HandState free_hand = scenes::open_hand(vec3(0.0, 0.5, 0.0));
  StepHistogram steps;
  constexpr int kWarm = 300, kMeasured = 5000;
  for (int t = 0; t < kWarm + kMeasured; ++t) {
    world.set_haptic(hand, grasping ? held_grasp(grasp, t) : free_hand);
    const Clock::time_point start = Clock::now();
    world.step();
    if (t >= kWarm) steps.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  std::printf("  {\"max_hands\": %d, \"present\": 1, \"hand\": \"%s\", \"steps\": %d, \"p50_us\": %.3f, "
              "\"p99_us\": %.3f, \"contacts\": %d}%s\n",
              slots, grasping ? "grasping" : "free", kMeasured, steps.percentile(0.5),
              steps.percentile(0.99), world.read().hand(hand)->contact_count, last ? "" : ",");
}

// One hand, free or grasping a ball, fed untimed inputs, stamped ones, or stamped ones
// from a host that stalls (5, 10, 20, 50 ms every 150 ms) and catches up in a burst.
void timed_input(const char* feed, bool grasping, bool last) {
  World world(WorldDef{});
  const std::shared_ptr<const TreeFile> ball = scenes::ball_shell(2000, 0.04);
  HandHandle hand;
  world.add_hand(make_hand_model(default_hand_def()), &hand);
  ObjectHandle handle;
  world.add_object(ball, RigidPose{vec3(0.10, 0.0, -0.058), glm::dmat3(1.0)}, &handle);
  const scenes::HandScenario grasp = scenes::ball_grasp(ball);
  auto input = [&](int64_t t) {
    return grasping ? held_grasp(grasp, t)
                    : scenes::open_hand(vec3(0.0, 0.5 + 1e-5 * static_cast<double>(t), 0.0));
  };
  const bool timed = feed[0] != 'u', stalls = feed[0] == 's';
  const scenes::JitteryHost host(stalls ? scenes::JitteryHost::stall_cycle(100, 100000, 150)
                                        : std::vector<scenes::HostStall>{},
                                 stalls ? 0.0003 : 0.0, 1);
  std::vector<int64_t> samples;
  samples.reserve(64);
  StepHistogram steps;
  constexpr int kWarm = 300, kMeasured = 5000;
  for (int64_t n = 1; n <= kWarm + kMeasured; ++n) {
    if (timed) {
      host.delivered_before(n, &samples);
      for (int64_t j : samples)
        world.set_haptic_at(hand, input(j), static_cast<int64_t>(std::llround(host.stamp(j) * 1e9)));
    } else {
      world.set_haptic(hand, input(n));
    }
    const Clock::time_point start = Clock::now();
    world.step();
    if (n > kWarm) steps.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  std::printf("  {\"feed\": \"%s\", \"hand\": \"%s\", \"steps\": %d, \"p50_us\": %.3f, \"p99_us\": %.3f, "
              "\"max_us\": %.3f}%s\n",
              feed, grasping ? "grasping" : "free", kMeasured, steps.percentile(0.5),
              steps.percentile(0.99), steps.max(), last ? "" : ",");
}

// The host's time to add a hand (allocating its pipeline), to remove it, and for the read
// that frees it once a step applied the removal; one other hand steps throughout.
void hand_add_remove() {
  World world(WorldDef{});
  const HandModel model = make_hand_model(default_hand_def());
  HandHandle resident;
  world.add_hand(model, &resident);
  StepHistogram add_us, remove_us, read_us;
  constexpr int kCycles = 500;
  for (int i = 0; i < kCycles; ++i) {
    HandHandle hand;
    Clock::time_point start = Clock::now();
    world.add_hand(model, &hand);
    add_us.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    world.set_haptic(hand, scenes::open_hand());
    world.step();
    start = Clock::now();
    world.remove_hand(hand);
    remove_us.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    world.step();
    start = Clock::now();
    world.read();  // frees the hand
    read_us.record(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  std::printf("\"hand_add_remove\": {\"cycles\": %d, \"add_p50_us\": %.2f, \"add_p99_us\": %.2f, "
              "\"remove_p50_us\": %.2f, \"remove_p99_us\": %.2f, \"freeing_read_p50_us\": %.2f, "
              "\"freeing_read_p99_us\": %.2f},\n",
              kCycles, add_us.percentile(0.5), add_us.percentile(0.99), remove_us.percentile(0.5),
              remove_us.percentile(0.99), read_us.percentile(0.5), read_us.percentile(0.99));
}

ObjectHandle drop(World& world, const char* tree, const vec3& at, double mass, bool dynamic) {
  ObjectHandle handle;
  world.add_object(scenes::sample_tree(tree), scenes::object_at(at, mass, dynamic), &handle);
  return handle;
}

void objects_on_table() {
  constexpr double kTop = 0.015;  // the table's top: 3 cm thick, centred at 0
  struct Case {
    const char* name;
    const char* tree;
    double mass, half_height;  // of the object on top
    bool on_box;               // standing on a 1 kg box
  } cases[] = {{"marble", "marble", 0.05, 0.0087, false},
               {"box", "box", 1.0, 0.02, false},
               {"box_on_box", "box", 0.2, 0.02, true}};
  std::printf("\"objects_on_table\": {\"scenes\": [\n");
  for (const Case& c : cases) {
    WorldDef def;
    def.gravity = vec3(0.0, 0.0, -9.81);
    World world(def);
    drop(world, "table", vec3(0.0), 1.0, false);
    const double base = c.on_box ? kTop + 0.04 : kTop;
    if (c.on_box) drop(world, "box", vec3(0.0, 0.0, kTop + 0.021), 1.0, true);
    const ObjectHandle top = drop(world, c.tree, vec3(0.005, 0.0, base + c.half_height + 0.02), c.mass, true);
    StepHistogram settling, resting;
    for (int t = 0; t < 3000; ++t) {
      const Clock::time_point start = Clock::now();
      world.step();
      const double us = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
      if (t < 1000) settling.record(us);
      if (t >= 2000) resting.record(us);
    }
    const ObjectSnapshot& o = world.read().objects[static_cast<size_t>(top.slot)];
    std::printf("  {\"scene\": \"%s\", \"settling_p50_us\": %.2f, \"settling_p99_us\": %.2f, "
                "\"settling_max_us\": %.2f, \"resting_p50_us\": %.2f, \"resting_max_us\": %.2f, "
                "\"rests_off_nominal_mm\": %.3f, \"speed_mm_s\": %.4f}%s\n",
                c.name, settling.percentile(0.5), settling.percentile(0.99), settling.max(),
                resting.percentile(0.5), resting.max(), 1e3 * (o.pose.position.z - base - c.half_height),
                1e3 * glm::length(o.linear_velocity), &c == &cases[2] ? "" : ",");
  }
  // one pair at rest, the 1 kg box on the table: a walk of both trees against the cache
  const std::shared_ptr<const TreeFile> table = scenes::sample_tree("table"), box = scenes::sample_tree("box");
  ObjectDef on, under;
  on.pose.position = vec3(0.0, 0.0, kTop + 0.02 - 0.0003);
  on.mass = 1.0;
  const ContactSide a{&box->tree, &on, 1.0}, b{&table->tree, &under, 0.0};
  constexpr int kCalls = 2000;
  ContactCache cache;
  ObjectWrench wa, wb;
  double t0 = thread_cpu_seconds();
  PatchStick stick;
  for (int i = 0; i < kCalls; ++i) add_object_contact(a, b, 1e-3, &stick, &wa, &wb);
  const double walked = (thread_cpu_seconds() - t0) / kCalls;
  t0 = thread_cpu_seconds();
  for (int i = 0; i < kCalls; ++i) {
    cache.touch(0, 1, a, 1, 1, b, 1e-3, &wa, &wb);
    cache.end_step();
  }
  const double cached = (thread_cpu_seconds() - t0) / kCalls;
  std::printf("], \"box_on_table_pair_us\": {\"walked\": %.2f, \"cached\": %.2f, \"walks\": %lld}},\n",
              1e6 * walked, 1e6 * cached, static_cast<long long>(cache.walks()));
}

}  // namespace
}  // namespace frusta

int main() {
  using namespace frusta;
  std::printf("{\n\"suite\": \"runtime\",\n\"hardware_threads\": %u,\n\"wake_up_1khz\": [\n",
              std::thread::hardware_concurrency());
  const int spins[] = {0, 50, 200, 1000};
  for (size_t i = 0; i < std::size(spins); ++i) wake_up(spins[i], i + 1 == std::size(spins));
  std::printf("],\n\"snapshot_read_ns\": {\"writer_idle\": %.2f, \"writer_publishing\": %.2f, \"snapshot_bytes\": %zu},\n",
              read_ns(false), read_ns(true), sizeof(Snapshot));
  // an empty hand slot: its port, and a slot header in each of the three snapshots
  // an empty hand slot: its port (with its input queue), and a slot header in each of
  // the three snapshots
  std::printf("\"empty_hand_slot_bytes\": %zu,\n",
              sizeof(HandPort) + HandPort::kInputQueueCapacity * sizeof(TimedInput) + 3 * sizeof(HandSlot));
  std::printf("\"hand_playback_bytes\": %zu,\n", InputPlayback::kCapacity * sizeof(TimedInput));
  hand_add_remove();
  objects_on_table();
  room();
  std::printf("\"hand_slots\": [\n");
  for (bool grasping : {false, true})
    for (int slots : {1, 8, 64}) hand_slots(slots, grasping, grasping && slots == 64);
  std::printf("],\n");
  std::printf("\"timed_input\": [\n");
  for (bool grasping : {false, true})
    for (const char* feed : {"untimed", "timed", "timed, stalls"})
      timed_input(feed, grasping, grasping && feed[0] == 't' && feed[5] == ',');
  std::printf("],\n");
  std::printf("\"world_step\": [\n");
  for (int hands : {1, 2})
    for (int objects : {hands, 5, 20}) world_steps(hands, objects, true, false);  // each hand holds one
  world_steps(1, 1, false, true);
  std::printf("]\n}\n");
  return 0;
}
