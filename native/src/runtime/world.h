// SPDX-License-Identifier: MIT
// A world: hands, objects and the step that turns haptic hands into graphic hands,
// contact forces, what each device receives and what each object receives. World
// puts its parts together:
//  - host_commands.h: the one lock-free queue of the host's commands, which take
//    effect at the next step boundary;
//  - host_objects.h and host_hands.h: the host's side of the objects (ids, trees) and
//    of the hands (ids, their pipelines, and a port per hand slot);
//  - scene_objects.h: the stepping side (slots, the present list, reactions) and
//    object_dynamics.h, how dynamic objects move;
//  - hand_pipeline.h: per hand, input -> solver -> forces -> device outputs, with its
//    port (port/hand_port.h) for what drives it; hands come and go while the world
//    steps, each built and freed on the host's thread;
//  - world_snapshot.h: what a step publishes, through a triple buffer the host reads
//    without locks and without ever seeing a torn state;
//  - step_thread.h: the world's own thread.
// The host and the stepping thread never wait for each other. A step allocates
// nothing once the world is built.
//
// Threads: the host thread calls add_hand / remove_hand / add_object / remove_object /
// set_object_pose / read; one stepping thread (the host's own loop, or the world's
// 1 kHz thread) calls step(); any one thread per hand calls set_haptic.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/base.h"
#include "core/triple_buffer.h"
#include "port/hand_port.h"
#include "runtime/hand_pipeline.h"
#include "runtime/host_commands.h"
#include "runtime/host_hands.h"
#include "runtime/host_objects.h"
#include "runtime/scene_objects.h"
#include "core/step_histogram.h"
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

  // Host thread, at any time. Queued like an object: the hand is solved from the next
  // step on, and its port takes inputs at once. Everything it needs is allocated here.
  // The world's solver settings are checked against the hand here.
  // FRUSTA_ERROR_CAPACITY when max_hands hands are present or still being let go of, or
  // the queue is full.
  frusta_result add_hand(const HandModel& model, HandHandle* out);
  // Host thread. Queued: the handle is refused at once by the calls that change the
  // world (set_haptic included); read() shows the hand until a step has applied the
  // removal. FRUSTA_ERROR_WRONG_STATE while a device drives the hand. The hand's memory
  // is freed on the host's thread once read() has returned a step without it.
  frusta_result remove_hand(HandHandle hand);
  // Whether a handle names a hand (any thread) or an object (host thread) added and not
  // removed.
  bool hand_is_live(HandHandle hand) const { return host_hands_.is_live(hand); }
  bool object_is_live(ObjectHandle object) const { return host_objects_.is_live(object); }

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
  // drives the hand). Each step plays the hand's samples input_delay behind the step's
  // time, interpolated between the two around that time, extrapolated at most
  // max_extrapolation past the newest, then held (input_playback.h): a driver whose
  // samples arrive unevenly (two in one step, none in the next, a burst after a stall)
  // moves the hand as its samples say instead of in jerks that shake a held object
  // loose. set_haptic stamps the sample with when it is set (steady clock); step() from
  // the host takes the newest untimed input as it is (the host paces both).
  // FRUSTA_ERROR_STALE_ID for a hand removed (even while a removal is under way).
  frusta_result set_haptic(HandHandle hand, const HandState& haptic);
  // The same, stamped by the driver with the sample's time on the world's clock (ns):
  // the steady clock (steady_ns()) for a world on its own thread; for a world the host
  // steps, the world's time after a step, steps / rate_hz (the host's own clock, in
  // effect). A hand's samples must come in time order.
  frusta_result set_haptic_at(HandHandle hand, const HandState& haptic, int64_t time_ns);

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

  // The host thread: the newest snapshot, unchanged until the next read(), which may
  // free what the previous one showed.
  const WorldSnapshot& read();

  int32_t max_hands() const { return def_.max_hands; }
  double rate_hz() const { return def_.rate_hz; }

  // The port of a hand slot (0..max_hands-1), for what drives its hand: the host or a
  // glove. It lives as long as the world.
  HandPort& port(int32_t slot) { return host_hands_.port(slot); }

 private:
  // on the own thread `paced`, at the tick tick_ns (steady clock); inputs are played
  // input_delay behind the step's time
  // Returns when the coming ticks should fall (StepThread::Step), 0 for none.
  int64_t step_once(double dt, bool paced, int64_t tick_ns);
  void apply_commands();

  WorldDef def_;
  HostCommands commands_;       // the host's side
  HostObjects host_objects_;
  Wakeup sample_arrived_;  // a glove's sample set: before the ports, which signal it
  HostHands host_hands_;
  SceneObjects scene_objects_;  // the stepping thread's
  std::vector<HandPipeline*> hands_;          // by slot: the hand's pipeline, or null
  std::vector<uint32_t> hand_generation_;     // by slot
  std::vector<int32_t> present_hands_;        // the slots of hands_ that are not null
  uint64_t applied_ = 0;                      // commands applied
  StepHistogram histogram_;
  uint64_t step_ = 0;
  double time_ = 0.0;
  int64_t rejected_ = 0;
  int64_t play_ns_ = 0;  // the time whose inputs the last step played (world clock)
  bool playing_ = false;
  TripleBuffer<WorldSnapshot> output_;
  std::atomic<int64_t> host_read_ns_{0};
  StepThread thread_;  // last: stopped (joined) before the parts it steps are freed
};

}  // namespace frusta
