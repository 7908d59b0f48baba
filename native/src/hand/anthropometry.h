// SPDX-License-Identifier: MIT
// Default hand proportions: every dimension of a hand def from its length and
// breadth, and anatomical joint limits. Sources are cited in anthropometry.cpp.
#pragma once

#include "frusta/frusta.h"

namespace frusta {

// Fill segment lengths, joint radii, finger bases and palm of def from the hand's
// length (wrist crease to middle fingertip) and breadth (metacarpal), metres.
void fill_hand_geometry(frusta_hand_def& def, double hand_length, double hand_breadth);

// Fill joint_min / joint_max with anatomical ranges of motion.
void fill_joint_limits(frusta_hand_def& def);

}  // namespace frusta
