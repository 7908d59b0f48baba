// SPDX-License-Identifier: MIT
// One finger's four joint angles from the tracked positions of its moving chain points,
// in the finger's rest frame: an analytic guess (the finger's plane, then each bone's
// direction in it, a two-bone solve across a missing joint) refined by damped
// Gauss-Newton steps within the joint limits.
#pragma once

#include <array>
#include <cstdint>

#include "geometry/types.h"
#include "hand/hand_model.h"

namespace frusta {

// The finger as the fit sees it: its bones, the last to the fingertip's end.
struct FingerChain {
  std::array<double, 3> length{};  // metres
  std::array<double, 4> joint_min{}, joint_max{};  // radians: abduction, flexion 1..3
};

FingerChain finger_chain(const FingerModel& finger);

// Chain points 1..3 (second joint, third joint, fingertip's end) in the finger's rest
// frame: origin at its first joint, axes of base_rotation (a left hand's mirrored into
// the right hand's); present[k] false where the tracker gave none.
struct FingerPoints {
  std::array<vec3, 3> point{};
  std::array<bool, 3> present{};
};

struct FingerFitResult {
  std::array<double, 4> angles{};  // radians, within the limits
  int32_t flags = 0;               // frusta_fit_flag bits
  double residual = 0.0;           // metres, RMS over the present points
};

// Fit angles to the present points; `last` (within the limits) is the last good fit,
// kept for what the points do not determine: everything with fewer than two present
// points (FRUSTA_FIT_HELD), the angles beyond the last present point otherwise
// (FRUSTA_FIT_PARTIAL). At most max_iterations refining steps.
FingerFitResult fit_finger(const FingerChain& chain, const FingerPoints& points,
                           const std::array<double, 4>& last, int max_iterations);

// RMS distance of the present points from the chain at angles, metres (0 with none).
double finger_residual(const FingerChain& chain, const FingerPoints& points,
                       const std::array<double, 4>& angles);

}  // namespace frusta
