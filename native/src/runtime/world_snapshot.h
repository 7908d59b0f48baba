// SPDX-License-Identifier: MIT
// What a step publishes for the host: every hand slot (graphic and haptic hands,
// contacts, forces, device outputs, solver figures), every object slot, and the step's
// timing. The world's part is sized once when the world is built; each hand's part is
// its own, made when the hand is added (one per buffer of the triple buffer), so that
// filling either allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/contact_forces.h"
#include "forces/device_outputs.h"
#include "hand/kinematics.h"
#include "runtime/world_def.h"
#include "solver/hand_solver.h"

namespace frusta {

struct HandSnapshot {
  const HandModel* model = nullptr;  // the hand's, for its geometry (kinematics.h)
  HandState graphic;
  HandState haptic;       // the input this step used
  int32_t contact_count = 0;  // all of them, even beyond the kept ones
  std::vector<SolverContact> contacts;  // sized once, at max_contacts_per_hand
  // forces[i] belongs to contacts[i] (object: a slot), for the kept contacts
  std::vector<ContactForce> forces;
  ContactForceStats force_stats;
  DeviceOutputs device;  // clamped to WorldDef::device_limits
  StepStats stats;
  int32_t ignored_objects = 0;  // objects put inside the hand, which it passes through
  bool solved = false;    // false until the hand's first valid haptic input
  // the step played a time past the hand's newest sample (its driver is late or has
  // stopped): the input was extrapolated, at most max_extrapolation, or held
  bool input_late = false;
};

// One hand slot as the step left it. A hand's snapshot is the hand's own: it stays
// alive as long as a snapshot the host has read shows the hand.
struct HandSlot {
  bool present = false;
  uint32_t generation = 0;  // with the slot, the handle of the hand in it
  const HandSnapshot* hand = nullptr;  // present only
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
  // bit h: the hand in slot h ignores the object, which was put inside it, until they
  // part (hand_pipeline.h)
  uint64_t ignored_by = 0;
  // the hand slot holding it in a grasp (scene_objects.h), or -1: while held, reaction is
  // what carrying it takes, not the hand's pushes
  int32_t held_by = -1;
};

struct WorldSnapshot {
  uint64_t step = 0;
  double time = 0.0;  // seconds: steps times the time step
  std::vector<HandSlot> hands;          // one per slot, max_hands
  std::vector<ObjectSnapshot> objects;  // one per slot, max_objects
  uint64_t commands_applied = 0;  // host commands applied so far (host_commands.h)
  double step_us = 0.0;  // this step's
  double step_us_p50 = 0.0, step_us_p99 = 0.0, step_us_max = 0.0;
  // on the world's own thread only: how late each tick woke, and overruns: ticks that
  // ran more than a period late (caught up back to back) or were dropped (a stall of
  // over 10 periods)
  double wake_late_us_p50 = 0.0, wake_late_us_p99 = 0.0, wake_late_us_max = 0.0;
  int64_t overruns = 0;
  double achieved_rate_hz = 0.0;  // own thread: steps over the time since start()
  bool realtime = false;          // own thread: it runs at real-time priority
  int64_t rejected_inputs = 0;  // inputs the solver could not place (inside objects)

  // The hand `hand` names in this step, or null: a slot out of range, empty, or another
  // hand's (added after this step, or removed before it).
  const HandSnapshot* hand(HandHandle hand) const {
    if (hand.slot < 0 || hand.slot >= static_cast<int32_t>(hands.size())) return nullptr;
    const HandSlot& h = hands[static_cast<size_t>(hand.slot)];
    return h.present && h.generation == hand.generation ? h.hand : nullptr;
  }
  // The same for an object.
  const ObjectSnapshot* object(ObjectHandle object) const {
    if (object.slot < 0 || object.slot >= static_cast<int32_t>(objects.size())) return nullptr;
    const ObjectSnapshot& o = objects[static_cast<size_t>(object.slot)];
    return o.present && o.generation == object.generation ? &o : nullptr;
  }
};

}  // namespace frusta
