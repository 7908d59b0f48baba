// SPDX-License-Identifier: MIT
// The normal force, seed eq. 12: F = G n |P_ig - P_ih| while P_ih lies inside, i.e.
// (P_ig - P_ih) . n > 0, and 0 otherwise. Each of a patch's k pressing contacts takes
// G / k, so a body feels one surface however finely the tree covers it. An optional
// damping on how fast the patch sinks in (ForceMaterial::normal_damping) settles a held
// object instead of letting it ring on the contact springs.
#pragma once

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "forces/contact_patches.h"
#include "forces/force_params.h"

namespace frusta {

// Both functions are inline: they run per patch and per contact on the 1 kHz path, where
// calls out of line cost the update about 9 % more instructions.

// How a patch presses this step.
struct PatchPress {
  double share = 1.0;      // of the patch's stiffness for each pressing contact: 1 / k
  double depth = 0.0;      // mean over the pressing contacts, metres
  double sink_rate = 0.0;  // how fast depth grew since the last step, m/s
};

// `depth_before`: the patch's depth at the last step, null where it is new; time_step
// in (0, 1] seconds.
inline PatchPress patch_press(const ContactPatch& patch, const double* depth_before,
                              double time_step) {
  PatchPress press;
  if (patch.pressing == 0) return press;
  press.share = 1.0 / patch.pressing;
  press.depth = patch.depth_sum * press.share;
  if (depth_before) press.sink_rate = (press.depth - *depth_before) / time_step;
  return press;
}

// The force on the hand at one pressing contact of a patch: its share of G (given in
// the frame of the object at `object_rotation`, turned into the world's) times the gap
// |P_ig - P_ih| along the unit `normal`, plus the patch's damping; never pulling.
inline vec3 normal_force(const ForceMaterial& material, const glm::dmat3& object_rotation,
                         const vec3& normal, double gap, const PatchPress& press) {
  const vec3 stiff_n =
      object_rotation * (material.normal_stiffness * (glm::transpose(object_rotation) * normal));
  const vec3 f = press.share * (stiff_n * gap + material.normal_damping * press.sink_rate * normal);
  return glm::dot(f, normal) < 0.0 ? vec3(0.0) : f;
}

}  // namespace frusta
