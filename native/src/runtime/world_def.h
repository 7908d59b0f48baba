// SPDX-License-Identifier: MIT
// What a world and its objects are made from (WorldDef, ObjectDef), the handles of an
// object and a hand, and the one check of each, used where they enter (the C ABI and World's
// entry points).
#pragma once

#include <cstdint>

#include "core/base.h"
#include "forces/device_outputs.h"
#include "forces/force_params.h"
#include "solver/hand_solver.h"

namespace frusta {

struct WorldDef {
  SolverParams solver;
  DeviceLimits device_limits;  // every hand's outputs are clamped to these
  // on dynamic objects, m/s^2; off by default: a host whose own engine moves the
  // objects (Unity's Rigidbody) owns gravity, and the world's objects stay kinematic
  vec3 gravity{0.0};
  double rate_hz = 1000.0;  // the own thread's rate, and so dynamic objects' time step
  double spin_us = 200.0;   // the own thread spins this long before each tick
  // the own thread and its gloves' threads ask for real-time priority (core/
  // thread_priority.h): a glove answered late is felt, whatever else the machine runs
  bool realtime_priority = true;
  int32_t max_objects = 64;
  // hand slots: a hand's ports and slot headers are made with the world, the rest of
  // it when the hand is added. At most kMaxHands: a snapshot's object keeps which
  // hands ignore it as bits of one word
  int32_t max_hands = 8;
  int32_t max_contacts_per_hand = 256;  // reported per snapshot; more are counted, not kept
  int32_t command_capacity = 256;
  // inputs are played this long behind the step's time (seconds), so a host whose
  // samples arrive late and in bursts still moves the hand as its samples say. The
  // default is the p99 of a 1 ms host loop's delivery lateness on a busy 2-core
  // machine (README, "Timed input")
  double input_delay = 0.010;
  // past its newest sample a hand moves on at its last velocity this long (seconds),
  // then holds: a stall longer than input_delay is bridged, a stream that stopped is
  // not run away with
  double max_extrapolation = 0.040;
};
// the largest input_delay and max_extrapolation: a hand's playback holds 256 samples
constexpr double kMaxInputDelay = 0.1;
// The step budget: the share of a period the hands' solves may take on the own thread
// (the rest is for the forces, the objects and the snapshot), split among the hands.
constexpr double kStepBudgetShare = 0.7;

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

constexpr int32_t kMaxHands = 64;
// The most candidates a hand's buffers are made for (SolverParams::candidate_capacity):
// about 100 MB a hand, what the grasp of a ball of 10^6 leaves at its leaves needs
constexpr int32_t kMaxCandidateCapacity = 1 << 18;

// Names an object slot; a removed object's handle turns stale through the generation.
struct ObjectHandle {
  int32_t slot = -1;
  uint32_t generation = 0;
};

// Names a hand slot, the same way.
struct HandHandle {
  int32_t slot = -1;
  uint32_t generation = 0;
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

}  // namespace frusta
