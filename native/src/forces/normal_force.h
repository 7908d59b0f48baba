// SPDX-License-Identifier: MIT
// The normal force, seed eq. 12 (F = G n |P_ig - P_ih|), once per patch: n and the gap
// P_ig - P_ih are the means over the patch's contacts, weighted as they fade in and out
// (forces/contact_patches.h), and the patch pushes while that gap points out of the
// object, (P_ig - P_ih) . n > 0. While its contacts press by less than 1 in all (its last
// contacts letting go, or its first taking hold) the force is scaled down with them, so
// it goes to 0 continuously. The patch's force is shared among its contacts by weight: a
// body feels one surface however finely the tree covers it, and a leaf joining or leaving
// the patch turns the force no faster than the hand moves. An optional damping on how
// fast the patch sinks in (ForceMaterial::normal_damping) settles a held object instead
// of letting it ring on the contact springs.
#pragma once

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "forces/contact_patches.h"
#include "forces/force_params.h"

namespace frusta {

// Both functions are inline: they run per patch on the 1 kHz path, where calls out of
// line cost the update about 9 % more instructions.

// How a patch presses this step.
struct PatchPress {
  vec3 normal{0.0};        // unit, the weighted mean normal; 0 where the patch has none
  double gap = 0.0;        // |P_ig - P_ih| of the weighted means, metres
  double depth = 0.0;      // that gap along the normal, metres: pressing when > 0
  double sink_rate = 0.0;  // how fast depth grew since the last step, m/s
  double engaged = 0.0;    // its contacts' presses added up, at most 1
};

// `depth_before`: the patch's depth at the last step, null where it is new; time_step
// in (0, 1] seconds.
inline PatchPress patch_press(const ContactPatch& patch, const double* depth_before,
                              double time_step) {
  PatchPress press;
  const double turn = glm::length(patch.normal_sum);
  if (!(patch.weight_sum > 0.0) || !(turn > 0.0)) return press;
  press.normal = patch.normal_sum / turn;
  press.engaged = std::min(1.0, patch.press_sum);
  const vec3 gap = patch.gap_sum / patch.weight_sum;
  press.gap = glm::length(gap);
  press.depth = glm::dot(gap, press.normal);
  if (depth_before) press.sink_rate = (press.depth - *depth_before) / time_step;
  return press;
}

// The force on the hand of a pressing patch: G (given in the frame of the object at
// `object_rotation`, turned into the world's) times the gap along the normal, plus the
// patch's damping; never pulling.
inline vec3 normal_force(const ForceMaterial& material, const glm::dmat3& object_rotation,
                         const PatchPress& press) {
  if (!(press.depth > 0.0)) return vec3(0.0);
  const vec3 stiff_n = object_rotation *
                       (material.normal_stiffness * (glm::transpose(object_rotation) * press.normal));
  const vec3 f = press.engaged *
                 (stiff_n * press.gap + material.normal_damping * press.sink_rate * press.normal);
  return glm::dot(f, press.normal) < 0.0 ? vec3(0.0) : f;
}

}  // namespace frusta
