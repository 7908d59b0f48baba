// SPDX-License-Identifier: MIT
// A hand's creation parameters (HandDef) and the immutable part of a hand built from
// them once they are checked: dimensions, finger bases, limits and palm spheres.
#pragma once

#include <array>
#include <vector>

#include <glm/mat3x3.hpp>

#include "core/base.h"
#include "geometry/types.h"

namespace frusta {

// frusta_hand_def's fields, without the ABI's bookkeeping (the C ABI copies them in
// and out); default_hand_def() in anthropometry.h fills one. Frames, units and ranges
// are frusta_hand_def's.
struct HandDef {
  int32_t side = FRUSTA_HAND_RIGHT;  // frusta_hand_side
  double hand_length = 0.0;          // metres, wrist crease to middle fingertip
  double hand_breadth = 0.0;         // metres, across the metacarpal heads
  double segment_length[FRUSTA_FINGER_COUNT][FRUSTA_SEGMENTS_PER_FINGER] = {};  // metres
  double joint_radius[FRUSTA_FINGER_COUNT][4] = {};  // metres: first..third joint, tip
  double base_position[FRUSTA_FINGER_COUNT][3] = {};  // metres, hand frame
  double base_rotation[FRUSTA_FINGER_COUNT][3] = {};  // radians, x-y-z
  double joint_min[FRUSTA_FINGER_COUNT][FRUSTA_JOINTS_PER_FINGER] = {};  // radians
  double joint_max[FRUSTA_FINGER_COUNT][FRUSTA_JOINTS_PER_FINGER] = {};  // radians
  double palm_length = 0.0;     // metres
  double palm_breadth = 0.0;    // metres
  double palm_thickness = 0.0;  // metres; also the palm spheres' diameter
};

struct FingerModel {
  std::array<double, FRUSTA_SEGMENTS_PER_FINGER> length{};  // metres
  std::array<double, 4> radius{};     // first, second, third joint, tip; metres
  vec3 base_position{0.0};            // first joint centre in the hand frame (right hand)
  glm::dmat3 base_rotation{1.0};      // rest frame in the hand frame (right hand)
  std::array<double, FRUSTA_JOINTS_PER_FINGER> joint_min{}, joint_max{};  // radians
};

struct HandModel {
  bool left = false;  // a left hand is the right hand mirrored through the x-z plane
  std::array<FingerModel, FRUSTA_FINGER_COUNT> fingers{};
  std::vector<Sphere> palm_spheres;  // hand frame, already mirrored for a left hand
};

// A hand is centimetres long; a size beyond a few metres is a units mistake.
constexpr double kMaxHandSize = 5.0;
// The smallest hand (hand_length, hand_breadth): a doll's, metres.
constexpr double kMinHandSize = 0.01;
// The smallest part (segment, radius, palm dimension), metres: below it the solver's
// micrometre tolerances are no longer small against the part.
constexpr double kMinHandPart = 1e-4;
// The palm is a grid of spheres of its thickness: a palm too thin for its size would
// be millions of them.
constexpr int32_t kMaxPalmSpheres = 4096;

// Check every field of def; on failure the thread's error names the field.
frusta_result check_hand_def(const HandDef& def);

// Build the model of a def that passed check_hand_def.
HandModel make_hand_model(const HandDef& def);

}  // namespace frusta
