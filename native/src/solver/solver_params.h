// SPDX-License-Identifier: MIT
// The knobs of the graphic-hand solve, with the defaults the tests and benches use.
#pragma once

#include <array>
#include <cstdint>

#include "core/base.h"
#include "geometry/constraint.h"

namespace frusta {

struct SolverParams {
  // Delta_r: detection inflates every hand radius by this much (seed FIG. 7). It also
  // bounds how far any hand point moves per sub-step (half of it per stage), which is
  // what keeps fast motion from tunnelling; must stay below the smallest hand radius.
  double prediction_margin = 0.002;
  ConstraintForm form = ConstraintForm::kDistance;
  // Gr of seed eq. 6, per finger joint: abduction, then the three flexions
  std::array<double, FRUSTA_JOINTS_PER_FINGER> joint_stiffness{1.0, 1.0, 1.0, 1.0};
  // the palm's 6-DOF objective: per m^2 of translation and per rad^2 of rotation
  double palm_translation_stiffness = 1.0;
  double palm_rotation_stiffness = 0.19 * 0.19;  // a turn of 1 rad weighs as a hand length
  double penetration_tolerance = 1e-6;  // metres a solved hand may sink (rounding, curvature)
  double contact_distance = 1e-4;       // gap under which a pair is reported as a contact
  double convergence = 1e-10;           // stop re-linearising when no variable moves more
  // Re-linearise and re-solve at most this often per stage. The estimate carries over
  // to the next step, so few suffice: on the 10^4-leaf grasp, 2 instead of 20 cut the
  // p99 step from 1.04 ms to 0.33 ms for 0.0003 mm more penetration (tools/bench solver).
  int32_t max_iterations = 2;
  int32_t qp_iteration_cap = 64;        // active-set changes per QP
  int32_t max_substeps = 64;            // per step; beyond, the graphic hand lags behind
  // Continuity (a proxy's bound): in a step, no point of the graphic hand moves further
  // than follow_factor times the most any point of the haptic hand moved, plus
  // follow_slack (metres). Where the nearest free hand jumps (a fingertip rolling round
  // a sharp edge pressed deep, or stuck and let go) the graphic hand follows over a few
  // steps instead, and the forces with it. Moves the solver did not finish because its
  // deadline or sub-step cap stopped it are made up on later steps.
  double follow_factor = 2.0;
  double follow_slack = 5e-5;
  // ... where "moved" is the haptic hand's move this step or, when it slows, the last
  // steps' fading by this factor a step: a graphic hand held back while the haptic hand
  // closed fast round a ball catches up as the haptic hand stops, in a few steps rather
  // than at follow_slack a step (a second). At a steady speed it is this step's move.
  double follow_decay = 0.9;
  // -1: contact spheres are the leaves. A level >= 0 uses the tree's nodes there (and
  // leaves above it) instead: fewer, larger spheres, a hand stopping short of the
  // leaves by up to their excess. A time-against-error knob.
  int32_t tree_level = -1;
  // 0: leaves. Otherwise the level-of-detail error budget, metres: an inner node that
  // stands out of its leaves by no more than this (the tree's node_error) stands in for
  // them, so a hand may stop up to about this far short of the leaves; dense trees shed
  // most candidates. The knob to use.
  double lod_error = 0.0;
  // Buffers for this many candidates (object spheres near the hand) and their scratch,
  // about 400 bytes each, are made with the solver, every page written on the
  // thread that makes it: the 1 kHz thread then neither allocates nor faults memory in
  // while a hand meets no more. A scene that holds more near a hand grows them there,
  // once. The grasp of a ball of 10^4 leaves meets up to 951; one of 10^5, 8,760.
  int32_t candidate_capacity = 1024;
};

}  // namespace frusta
