// SPDX-License-Identifier: MIT
// What a step publishes for the host: every hand (graphic and haptic, contacts,
// forces, device outputs, solver figures), every object slot, and the step's timing.
// Sized once when the world is built (and when a hand is added), so that filling it
// allocates nothing.
#pragma once

#include <cstdint>
#include <vector>

#include "forces/contact_forces.h"
#include "forces/device_outputs.h"
#include "hand/kinematics.h"
#include "solver/hand_solver.h"

namespace frusta {

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

}  // namespace frusta
