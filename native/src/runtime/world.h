// SPDX-License-Identifier: MIT
// A world: hands, objects and the step that turns haptic hands into graphic hands,
// contact forces, what each device receives and what each object receives. World
// puts its parts together:
//  - host_objects.h: the host's side of the objects (ids, trees, queued commands),
//    which take effect at the next step boundary through a lock-free queue;
//  - scene_objects.h: the stepping side (slots, the present list, reactions) and
//    object_dynamics.h, how dynamic objects move;
//  - hand_pipeline.h: per hand, input -> solver -> forces -> device outputs, with its
//    port (port/hand_port.h) for what drives it;
//  - world_snapshot.h: what a step publishes, through a triple buffer the host reads
//    without locks and without ever seeing a torn state;
//  - step_thread.h: the world's own thread.
// The host and the stepping thread never wait for each other. A step allocates
// nothing once the world is built.
//
// Threads: the host thread calls add_object / remove_object / set_object_pose / read;
// one stepping thread (the host's own loop, or the world's 1 kHz thread) calls step();
// any one thread per hand calls set_haptic.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/base.h"
#include "core/triple_buffer.h"
#include "port/hand_port.h"
#include "runtime/hand_pipeline.h"
#include "runtime/host_objects.h"
#include "runtime/scene_objects.h"
#include "runtime/step_histogram.h"
#include "runtime/step_thread.h"
#include "runtime/world_def.h"
#include "runtime/world_snapshot.h"
#include "spheretree/tree_file.h"

namespace frusta {

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
  bool running() const { return thread_.running(); }
  ~World();

  // The host thread: the newest snapshot, unchanged until the next read().
  const WorldSnapshot& read();

  int32_t hand_count() const { return static_cast<int32_t>(hands_.size()); }
  double rate_hz() const { return def_.rate_hz; }

  // The port of `hand` (< hand_count()), for what drives it: the host or a glove.
  HandPort& port(int32_t hand) { return hands_[static_cast<size_t>(hand)]->port(); }

 private:
  // on the own thread `paced`: inputs are played one period before the tick (steady
  // clock, ns), interpolated by the times they were set, so a device's jitter does not
  // jerk the hand
  void step_once(double dt, bool paced, int64_t tick_ns);
  void apply_commands();

  WorldDef def_;
  std::vector<std::unique_ptr<HandPipeline>> hands_;
  HostObjects host_objects_;    // the host's side
  SceneObjects scene_objects_;  // the stepping thread's
  StepHistogram histogram_;
  uint64_t step_ = 0;
  double time_ = 0.0;
  int64_t rejected_ = 0;
  TripleBuffer<WorldSnapshot> output_;
  std::atomic<int64_t> host_read_ns_{0};
  StepThread thread_;  // last: stopped (joined) before the parts it steps are freed
};

}  // namespace frusta
