// SPDX-License-Identifier: MIT
// A world: hands, objects and the step that turns haptic hands into graphic hands,
// contact forces, what each device receives and what each object receives.
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

#include "forces/contact_forces.h"
#include "forces/device_outputs.h"
#include "forces/force_params.h"
#include "core/base.h"
#include "core/id_pool.h"
#include "core/spsc_queue.h"
#include "port/hand_port.h"
#include "runtime/step_histogram.h"
#include "core/triple_buffer.h"
#include "solver/hand_solver.h"
#include "spheretree/tree_file.h"

namespace frusta {

struct WorldDef {
  SolverParams solver;
  DeviceLimits device_limits;  // every hand's outputs are clamped to these
  // on dynamic objects, m/s^2; off by default: a host whose own engine moves the
  // objects (Unity's Rigidbody) owns gravity, and the world's objects stay kinematic
  vec3 gravity{0.0};
  double rate_hz = 1000.0;  // the own thread's rate, and so dynamic objects' time step
  double spin_us = 200.0;   // the own thread spins this long before each tick
  int32_t max_objects = 64;
  int32_t max_contacts_per_hand = 256;  // reported per snapshot; more are counted, not kept
  int32_t command_capacity = 256;
};

// An object as the host adds it. Kinematic objects go where the host puts them;
// dynamic ones the world moves at its rate under the hands' reactions and gravity,
// which is what lets a hand grasp, lift, carry and drop them at 1 kHz.
struct ObjectDef {
  RigidPose pose;  // of the object frame: its origin is the centre of mass
  ForceMaterial material;
  bool dynamic = false;
  double mass = 0.1;          // kilograms, > 0
  vec3 inertia{4e-5};         // principal moments in the object frame, kg m^2, > 0
  vec3 linear_velocity{0.0};  // m/s, world frame
  vec3 angular_velocity{0.0}; // rad/s, world frame
  double linear_damping = 0.0;   // 1/s: the velocity lost per second, as a fraction
  double angular_damping = 0.0;  // 1/s
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
  // forces[i] belongs to contacts[i] (object: a slot), for the kept contacts
  std::vector<ContactForce> forces;
  ContactForceStats force_stats;
  DeviceOutputs device;  // clamped to WorldDef::device_limits
  StepStats stats;
  bool solved = false;    // false until the hand's first valid haptic input
};

// One object slot as the step left it.
struct ObjectSnapshot {
  bool present = false;
  bool dynamic = false;
  uint32_t generation = 0;  // with the slot, the handle of the object in it
  RigidPose pose;
  vec3 linear_velocity{0.0};
  vec3 angular_velocity{0.0};
  ObjectWrench reaction;  // from every hand this step: what a host's engine applies
};

struct WorldSnapshot {
  uint64_t step = 0;
  double time = 0.0;  // seconds: steps times the time step
  std::vector<HandSnapshot> hands;
  std::vector<ObjectSnapshot> objects;  // one per slot, max_objects
  double step_us = 0.0;  // this step's
  double step_us_p50 = 0.0, step_us_p99 = 0.0, step_us_max = 0.0;
  // on the world's own thread only: how late each tick woke, and overruns: ticks that
  // ran more than a period late (caught up back to back) or were dropped (a stall of
  // over 10 periods)
  double wake_late_us_p50 = 0.0, wake_late_us_p99 = 0.0, wake_late_us_max = 0.0;
  int64_t overruns = 0;
  double achieved_rate_hz = 0.0;  // own thread: steps over the time since start()
  int64_t rejected_inputs = 0;  // inputs the solver could not place (inside objects)
};

// Every field finite, the rotation orthonormal, the position within kMaxCoordinate;
// the thread's error names `name` and the field.
frusta_result check_rigid_pose(const RigidPose& pose, const char* name);
// A hand-held object's mass, kg (a grain of sand to a car) and principal moments,
// kg m^2 (a 1 mg bead of 1 mm to a car): beyond them the dynamics at 1 kHz are
// meaningless, and a mass of 1e-300 once flung a cube through a palm.
constexpr double kMinMass = 1e-6, kMaxMass = 1e4;
constexpr double kMinInertia = 1e-13, kMaxInertia = 1e4;

frusta_result check_object_def(const ObjectDef& def);
frusta_result check_world_def(const WorldDef& def);

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
  frusta_result add_object(std::shared_ptr<const TreeFile> tree, const ObjectDef& def,
                           ObjectHandle* out);
  frusta_result add_object(std::shared_ptr<const TreeFile> tree, const RigidPose& pose,
                           ObjectHandle* out);
  frusta_result remove_object(ObjectHandle object);
  // Puts the object there at rest (a dynamic object's velocities are zeroed).
  frusta_result set_object_pose(ObjectHandle object, const RigidPose& pose);
  // Hand the object to the world's dynamics, or take it back (at rest) for the host.
  frusta_result set_object_dynamic(ObjectHandle object, bool dynamic);

  // Any one thread per hand: the host's haptic input, through the hand's port (see
  // HandPort::set_input: the one rule for a hand's inputs, refused while a glove
  // drives the hand). The newest wins. On the world's own thread a step plays the
  // inputs one period late, interpolated between the two it has by the times they were
  // set: a glove whose inputs arrive unevenly against the steps (two in one step,
  // none in the next) moves the hand smoothly instead of in jerks that shake a held
  // object loose. step() from the host takes the newest input as it is (the host
  // paces both).
  frusta_result set_haptic(int32_t hand, const HandState& haptic);

  // The stepping thread: apply queued commands, solve every hand, publish a snapshot.
  // From the host's loop only while the world's own thread is not running.
  frusta_result step();

  // Host thread: run step() on the world's own thread at `rate_hz` on absolute
  // deadlines (sleep, then spin the last `spin_us`), until stop(). No thread exists
  // until start() is called. The first form uses the def's rate and spin.
  frusta_result start();
  frusta_result start(double rate_hz, double spin_us);
  void stop();
  bool running() const { return running_.load(std::memory_order_acquire); }
  ~World();

  // The host thread: the newest snapshot, unchanged until the next read().
  const WorldSnapshot& read();

  int32_t hand_count() const { return static_cast<int32_t>(hands_.size()); }
  double rate_hz() const { return def_.rate_hz; }

  // The port of `hand` (< hand_count()), for what drives it: the host or a glove.
  HandPort& port(int32_t hand) { return hands_[static_cast<size_t>(hand)]->port; }

 private:
  enum class CommandKind : int32_t { kAdd, kRemove, kPose, kDynamic };
  struct Command {
    CommandKind kind = CommandKind::kAdd;
    int32_t slot = -1;
    uint32_t generation = 0;
    ObjectDef def;  // kAdd: all of it; kPose: the pose; kDynamic: the flag
    const TreeFile* tree = nullptr;  // kAdd: the host keeps it alive in host_trees_
  };
  struct ObjectSlot {  // the stepping thread's view
    const TreeFile* tree = nullptr;
    uint32_t generation = 0;
    ObjectDef def;  // pose and velocities as the world moves it
    ObjectWrench reaction;  // this step's, from every hand
  };
  struct HandSlot {
    HandSlot(const HandModel& model, const SolverParams& params, int32_t max_contacts,
             int32_t index, double rate_hz)
        : solver(model, params), port(index, rate_hz), forces(max_contacts) {}
    HandSolver solver;
    HandPort port;
    bool has_input = false;
    TimedInput previous, newest;  // the two last inputs read
    HandState accepted;  // the last haptic input the solver took
    ContactForces forces;
    // objects that appeared inside this hand (added or put there by the host) are
    // ignored by it until they no longer overlap, so the hand is not trapped in them;
    // while any is, the hand sees its own object list (all sized up front)
    std::vector<uint8_t> ignored;  // per slot
    int32_t ignored_count = 0;
    std::vector<SolverObject> objects;
    std::vector<int32_t> object_slot;
    std::vector<ForceMaterial> materials;
  };

  void run(double rate_hz, double spin_us);
  // on the own thread `paced`: inputs are played one period before the tick (steady
  // clock, ns), interpolated by the times they were set, so a device's jitter does not
  // jerk the hand
  void step_once(double dt, bool paced, int64_t tick_ns);
  void step_hand(HandSlot& hand, HandSnapshot& snap, double dt, bool paced, int64_t tick_ns,
                 HandSolver::Clock::time_point deadline);
  void move_dynamic_objects(double dt);
  void publish_device_feed(HandSlot& hand, const HandSnapshot& snap);
  // which placed objects this hand now sinks into, which ignored ones it has left, and
  // the hand's object list without the ignored ones
  void update_ignored(HandSlot& hand);
  void apply_commands();
  void rebuild_active();
  frusta_result check_handle(ObjectHandle object) const;
  frusta_result queue(const Command& command);
  void release_retired();  // host: drop trees whose removal a step has applied

  WorldDef def_;
  std::vector<std::unique_ptr<HandSlot>> hands_;
  // host side: which slots are taken, their generations, and the trees they hold
  IdPool object_ids_;
  std::vector<std::shared_ptr<const TreeFile>> host_trees_;
  uint64_t pushed_ = 0;  // commands queued so far
  std::vector<std::pair<uint64_t, std::shared_ptr<const TreeFile>>> retired_;
  // stepping side
  SpscQueue<Command> commands_;
  std::atomic<uint64_t> applied_{0};  // commands the stepping thread has applied
  std::vector<ObjectSlot> slots_;
  std::vector<SolverObject> active_;  // rebuilt when commands change the slots
  std::vector<int32_t> active_slot_;  // the slot behind each active object
  std::vector<ForceMaterial> active_material_;
  std::vector<uint8_t> placed_;  // per slot: added or moved by the host this step
  bool objects_moved_ = false;   // active_ was rebuilt this step (poses, or which)
  std::vector<ObjectWrench> hand_reactions_;  // one hand's, per active object
  StepHistogram histogram_;
  uint64_t step_ = 0;
  double time_ = 0.0;
  int64_t rejected_ = 0;
  TripleBuffer<WorldSnapshot> output_;
  StepHistogram lateness_;
  int64_t overruns_ = 0;
  double achieved_rate_hz_ = 0.0;
  std::atomic<int64_t> host_read_ns_{0};
  std::atomic<bool> running_{false};
  std::thread thread_;
};

}  // namespace frusta
