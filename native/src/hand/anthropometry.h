// SPDX-License-Identifier: MIT
// Default hand proportions: every dimension of a hand def from its length and
// breadth, and anatomical joint limits. Sources are cited in anthropometry.cpp.
#pragma once

#include "hand/hand_model.h"

namespace frusta {

// A right hand of 50th-percentile adult size (length 0.19 m, breadth 0.085 m) with
// anatomical joint limits.
HandDef default_hand_def();

// Fill segment lengths, joint radii, finger bases and palm of def from the hand's
// length (wrist crease to middle fingertip) and breadth (metacarpal), metres.
void fill_hand_geometry(HandDef& def, double hand_length, double hand_breadth);

// Fill joint_min / joint_max with anatomical ranges of motion.
void fill_joint_limits(HandDef& def);

}  // namespace frusta
