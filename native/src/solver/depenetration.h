// SPDX-License-Identifier: MIT
// Where a graphic hand starts when its haptic hand starts inside objects: the haptic
// hand moved out along the shortest of 26 directions (a cube's faces, edges and
// corners). Run once, when a solver has no graphic hand yet; later steps keep it out.
#pragma once

#include "solver/detection.h"

namespace frusta {

// True when no part of the hand at `pose` sinks deeper than `tolerance` into any object.
bool hand_is_free(const HandModel& model, const HandReach& reach, const HandPose& pose,
                  const SolverObject* objects, int32_t object_count, double tolerance,
                  CandidateSet& scratch);

// Move state's palm (and so the whole hand) to the nearest free placement found; false
// when none lies within the objects' reach (state is then left unchanged).
bool depenetrate(const HandModel& model, const HandReach& reach, const SolverObject* objects,
                 int32_t object_count, double tolerance, CandidateSet& scratch, HandState& state);

}  // namespace frusta
