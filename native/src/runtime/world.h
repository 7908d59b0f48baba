// SPDX-License-Identifier: MIT
// A world: hands, objects and the step that turns haptic hands into graphic hands.
// The host and the stepping thread never wait for each other:
//  - object commands (add, remove, move) go through a lock-free queue and take effect
//    at the next step boundary;
//  - each hand's haptic input is a triple buffer any one thread may write;
//  - every step publishes a snapshot (graphic hands, contacts, timing) through a triple
//    buffer the host reads without locks and without ever seeing a torn state.
// A step allocates nothing once the world is built: slots, queues, snapshots and the
// solvers' buffers are sized up front or reach their high-water mark and stay.
//
// Threads: the host thread calls add_object / remove_object / set_object_pose / read;
// one stepping thread (the host's own loop, or the world's 1 kHz thread) calls step();
// any one thread per hand calls set_haptic.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include "frusta/frusta.h"
#include "runtime/spsc_queue.h"
#include "runtime/step_histogram.h"
#include "runtime/triple_buffer.h"
#include "solver/hand_solver.h"
#include "spheretree/tree_file.h"

namespace frusta {

struct WorldDef {
  SolverParams solver;
  int32_t max_objects = 64;
  int32_t max_contacts_per_hand = 256;  // reported per snapshot; more are counted, not kept
  int32_t command_capacity = 256;
};

// Names an object slot; a removed object's handle turns stale through the generation.
struct ObjectHandle {
  int32_t slot = -1;
  uint32_t generation = 0;
};

struct HandSnapshot {
  HandState graphic;
  HandState haptic;       // the input this step used
  int32_t contact_count = 0;  // all of them, even beyond the kept ones
  std::vector<SolverContact> contacts;  // sized once, at max_contacts_per_hand
  StepStats stats;
  bool solved = false;    // false until the hand's first valid haptic input
};

struct WorldSnapshot {
  uint64_t step = 0;
  std::vector<HandSnapshot> hands;
  double step_us_p50 = 0.0, step_us_p99 = 0.0, step_us_max = 0.0;
  // on the world's own thread only: how late each tick woke, and ticks lost to overruns
  double wake_late_us_p50 = 0.0, wake_late_us_p99 = 0.0, wake_late_us_max = 0.0;
  int64_t overruns = 0;
  int64_t rejected_inputs = 0;  // haptic inputs the solver refused (NaN, absurd)
};

class World {
 public:
  explicit World(const WorldDef& def);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Before the first step only (the stepping thread does not expect new hands). The
  // world's solver settings are checked against the hand here.
  frusta_result add_hand(const HandModel& model, int32_t* out_hand);

  // Host thread. Queued; applied at the next step boundary. The tree stays alive as
  // long as the world holds it (and is released on the host thread, never in a step).
  frusta_result add_object(std::shared_ptr<const TreeFile> tree, const RigidPose& pose,
                           ObjectHandle* out);
  frusta_result remove_object(ObjectHandle object);
  frusta_result set_object_pose(ObjectHandle object, const RigidPose& pose);

  // Any one thread per hand: the newest haptic hand wins. Bad values are the solver's
  // to refuse (counted in the snapshot); a hand index the world lacks is refused here.
  frusta_result set_haptic(int32_t hand, const HandState& haptic);

  // The stepping thread: apply queued commands, solve every hand, publish a snapshot.
  // From the host's loop only while the world's own thread is not running.
  frusta_result step();

  // Host thread: run step() on the world's own thread at `rate_hz` on absolute
  // deadlines (sleep, then spin the last `spin_us`), until stop(). No thread exists
  // until start() is called.
  frusta_result start(double rate_hz, double spin_us);
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }
  ~World();

  // The host thread: the newest snapshot, unchanged until the next read().
  const WorldSnapshot& read();

  int32_t hand_count() const { return static_cast<int32_t>(hands_.size()); }

 private:
  enum class CommandKind : int32_t { kAdd, kRemove, kPose };
  struct Command {
    CommandKind kind = CommandKind::kAdd;
    int32_t slot = -1;
    RigidPose pose;
    const TreeFile* tree = nullptr;  // kAdd: the host keeps it alive in host_trees_
  };
  struct ObjectSlot {  // the stepping thread's view
    const TreeFile* tree = nullptr;
    RigidPose pose;
  };
  struct HandSlot {
    explicit HandSlot(const HandModel& model, const SolverParams& params, const HandState& rest)
        : solver(model, params), input(rest) {}
    HandSolver solver;
    TripleBuffer<HandState> input;
    bool has_input = false;
  };

  void run(double rate_hz, double spin_us);
  void step_once();
  void apply_commands();
  frusta_result check_handle(ObjectHandle object) const;
  frusta_result queue(const Command& command);
  void release_retired();  // host: drop trees whose removal a step has applied

  WorldDef def_;
  std::vector<std::unique_ptr<HandSlot>> hands_;
  // host side: which slots are taken, their generations, and the trees they hold
  std::vector<uint32_t> host_generation_;
  std::vector<std::shared_ptr<const TreeFile>> host_trees_;
  std::vector<int32_t> host_free_;
  uint64_t pushed_ = 0;  // commands queued so far
  std::vector<std::pair<uint64_t, std::shared_ptr<const TreeFile>>> retired_;
  // stepping side
  SpscQueue<Command> commands_;
  std::atomic<uint64_t> applied_{0};  // commands the stepping thread has applied
  std::vector<ObjectSlot> slots_;
  std::vector<SolverObject> active_;  // rebuilt when commands change the slots
  std::vector<int32_t> active_slot_;  // the slot behind each active object
  StepHistogram histogram_;
  uint64_t step_ = 0;
  int64_t rejected_ = 0;
  TripleBuffer<WorldSnapshot> output_;
  StepHistogram lateness_;
  int64_t overruns_ = 0;
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace frusta
