// SPDX-License-Identifier: MIT
// The solver benchmark's peer: the deep grasp done the way a MuJoCo user would do it
// (Debian's libmujoco-dev, MuJoCo 2.2.2), timed and measured like Frusta's own run.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "geometry/types.h"
#include "hand/hand_model.h"
#include "hand/kinematics.h"

namespace frusta::bench {

struct PeerResult {
  bool ok = false;
  std::string error;  // why not, when !ok
  int32_t steps = 0;
  double p50_us = 0, p99_us = 0, max_us = 0;  // wall time of mj_step per step, microseconds
  double max_penetration_mm = 0;  // deepest penetration over the run (see below)
  int32_t max_contacts = 0;       // most mjData::ncon in a step
  double load_s = 0;              // mj_loadXML's wall time, seconds
};

// The deep grasp as a MuJoCo user would build it: the 15 finger phalanges as capsules on
// hinge joints with position servos tracking the haptic angles, the palm fixed (mocap or
// welded to world at the haptic palm pose, which stays constant in the grasp), the ball
// as `leaves` (world-frame spheres, all static geoms of one body fixed in the world),
// timestep 1 ms, one mj_step per haptic step.
//
// Penetration is the largest -mjContact::dist (MuJoCo's capsule-sphere depth) over the
// contacts of each step; mj_step detects them before it integrates, so a step's contacts
// describe the pose the previous step left. Not thread-safe: MuJoCo's warning handler
// is a process global, silenced for the run (warnings are read from mjData instead).
//
// contact_time_constant: the contacts' solref time constant in seconds; 0 keeps
// MuJoCo's default (0.02, soft: fingers driven this hard sink centimetres in), 0.002 is
// the stiffest that stays stable at a 1 ms step.
PeerResult run_mujoco_grasp(const HandModel& model, const std::vector<Sphere>& leaves,
                            int32_t steps, const std::function<HandState(int32_t)>& haptic,
                            double contact_time_constant = 0.0);

}  // namespace frusta::bench
