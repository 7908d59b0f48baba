// SPDX-License-Identifier: MIT
// One hand of a world, each step: take its driver's inputs from the port and play them
// a fixed delay behind the step's time (input_playback.h), solve the graphic hand,
// compute the contact forces and device outputs, add the hand's reactions to the
// objects, fill the hand's snapshot and publish its device feed. Everything it needs,
// its snapshots included, is allocated when it is built (on the host's thread, when the
// hand is added).
//
// Threads: the stepping thread, but the constructor (the host's); the host reads a
// snapshot once the step that filled it is published.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "forces/contact_forces.h"
#include "forces/device_outputs.h"
#include "forces/grasp.h"
#include "port/hand_port.h"
#include "runtime/input_playback.h"
#include "runtime/scene_objects.h"
#include "runtime/world_snapshot.h"
#include "solver/hand_solver.h"

namespace frusta {

// What every hand of a world shares for a step.
struct HandStepContext {
  double dt = 0.0;            // seconds
  bool paced = false;         // on the world's own thread
  // the time whose input the step plays, on the world's clock: input_delay behind the
  // step's time (the tick's on the steady clock when paced, else steps / rate_hz), one
  // period further each step (catching up a little faster after the world stalled)
  int64_t play_ns = 0;
  int64_t max_extrapolation_ns = 0;
  HandSolver::Clock::time_point deadline = HandSolver::Clock::time_point::max();
  DeviceLimits device_limits;
  int32_t max_contacts = 0;   // kept in the snapshot
};

class HandPipeline {
 public:
  // slot: the hand's in its world; port: that slot's, which outlives the pipeline
  HandPipeline(const HandModel& model, const SolverParams& params, int32_t max_contacts,
               int32_t max_objects, int32_t slot, HandPort& port);

  // The snapshot the step fills for buffer 0..2 of the world's triple buffer
  // (TripleBuffer::write_index): a reader holding one buffer reads this hand's part of
  // it while the step fills another's.
  HandSnapshot& snapshot(int buffer) { return snapshots_[static_cast<size_t>(buffer)]; }

  // One step against the present objects: fills snap, adds the hand's reactions to
  // objects, and returns false when the solver could not place the input (a hand that
  // starts inside objects with no free placement near).
  bool step(const HandStepContext& context, SceneObjects& objects, HandSnapshot& snap);
  // Publish the step's feed for the hand's device (step: the step being taken).
  void publish_feed(const HandSnapshot& snap, uint64_t step, int64_t host_read_ns);
  // When the newest glove sample a step solved was set (steady clock, ns; 0: none yet):
  // the world's ticks align to a glove's samples.
  int64_t live_sample_ns() const { return live_sample_ns_; }
  // An object removed from the world is nobody's to ignore any more.
  void forget(int32_t slot);

 private:
  // which placed objects this hand now sinks into, which ignored ones it has left (each
  // change told to the objects), and the hand's object list without the ignored ones.
  // Returns whether what this hand ignores changed.
  bool update_ignored(SceneObjects& objects);
  // this step's pushes on each dynamic object, per body: the squeeze offered to the scene
  // (forces/grasp.h)
  void offer_grasps(SceneObjects& scene, const int32_t* object_slot,
                    const ForceMaterial* materials);

  HandSolver solver_;
  int32_t slot_;
  HandPort& port_;
  std::array<HandSnapshot, 3> snapshots_;
  InputPlayback playback_;        // the inputs taken, played by their times
  HandState accepted_;            // the last haptic input the solver took
  int64_t live_sample_ns_ = 0;    // live_sample_ns
  ContactForces forces_;
  std::vector<ObjectWrench> reactions_;  // this hand's, per object of its list
  std::vector<int32_t> grasp_entry_;     // per object of its list: its entry below, or -1
  std::vector<int32_t> grasp_object_;    // the dynamic objects pushed this step
  std::vector<BodyPushes> grasp_pushes_;  // and their pushes
  // objects that appeared inside this hand (added or put there by the host) are
  // ignored by it until they no longer overlap, so the hand is not trapped in them;
  // while any is, the hand sees its own object list (all sized up front)
  std::vector<uint8_t> ignored_;  // per slot
  int32_t ignored_count_ = 0;
  std::vector<SolverObject> objects_;
  std::vector<int32_t> object_slot_;
  std::vector<ForceMaterial> materials_;
};

}  // namespace frusta
