// SPDX-License-Identifier: MIT
#include "forces/contact_forces.h"

#include <algorithm>
#include <cassert>
#include <glm/geometric.hpp>

#include "core/validate.h"
#include "forces/normal_force.h"

namespace frusta {

namespace {

const ForceMaterial kDefaultMaterial{};

}  // namespace

ContactForces::ContactForces(int32_t capacity, double contact_distance)
    : capacity_(std::max(capacity, 0)), grouping_(capacity_, contact_distance) {
  patches_.reserve(static_cast<size_t>(capacity_));
  next_patches_.reserve(static_cast<size_t>(capacity_));
  forces_.reserve(static_cast<size_t>(capacity_));
}

void ContactForces::reset() { patches_.clear(); }

frusta_result ContactForces::set_time_step(double seconds) {
  if (frusta_result r = check_range(seconds, 0.0, 1.0, true, "time step")) return r;
  time_step_ = seconds;
  return FRUSTA_OK;
}

void ContactForces::update(const HandPose& graphic, const HandPose& haptic,
                           const SolverContact* contacts, int32_t contact_count,
                           const SolverObject* objects,
                           [[maybe_unused]] int32_t object_count,  // in the asserts only
                           const ForceMaterial* materials, ContactForceStats* stats) {
  assert(contact_count >= 0 && object_count >= 0);
  assert(check_hand_pose(graphic, "graphic") == FRUSTA_OK);
  assert(check_hand_pose(haptic, "haptic") == FRUSTA_OK);
  assert(check_force_objects(objects, object_count, materials) == FRUSTA_OK);
  assert(check_solver_contacts(contacts, contact_count, object_count) == FRUSTA_OK);

  ContactForceStats counts;
  const int32_t used = std::min(contact_count, capacity_);
  counts.dropped = contact_count - used;
  grouping_.group(graphic, haptic, contacts, used);
  const std::vector<PatchContact>& grouped = grouping_.contacts();

  forces_.resize(static_cast<size_t>(used));
  next_patches_.clear();
  size_t old = 0;  // the merge walk through the last step's patches
  for (const ContactPatch& patch : grouping_.patches()) {
    const RigidPose& object = objects[patch.key.object].pose;
    const ForceMaterial& material = materials ? materials[patch.key.object] : kDefaultMaterial;
    while (old < patches_.size() && precedes(patches_[old].key, patch.key)) ++old;
    const Patch* before =
        old < patches_.size() && !precedes(patch.key, patches_[old].key) ? &patches_[old] : nullptr;

    const PatchPress press = patch_press(patch, before ? &before->depth : nullptr, time_step_);
    const vec3 patch_force = normal_force(material, object.rotation, press);
    const bool pressing = press.engaged > 0.0 && press.depth > 0.0;
    PatchFriction friction;
    if (pressing) {
      friction = patch_friction(material, object, haptic_body_frame(haptic, patch.key.body),
                                press.normal, patch.haptic_sum / patch.weight_sum, patch_force,
                                before ? &before->friction : nullptr, time_step_);
      // nothing pressed, nothing held: a patch that lets go starts afresh
      next_patches_.push_back({patch.key, friction.anchor, press.depth});
    }
    for (int32_t k = patch.begin; k < patch.end; ++k) {
      const PatchContact& p = grouped[static_cast<size_t>(k)];
      const SolverContact& c = contacts[p.index];
      ContactForce& out = forces_[static_cast<size_t>(p.index)];
      out.object = c.object;
      out.leaf = c.leaf;
      out.body = c.body;
      out.part = c.part;
      out.graphic_point = c.hand_point;
      out.haptic_point = p.haptic_point;
      out.normal = c.normal;
      const bool shares = pressing && p.weight > 0.0;
      const double share = shares ? p.weight / patch.weight_sum : 0.0;
      out.normal_force = share * patch_force;
      out.friction = share * friction.force;
      out.slipping = shares && friction.slipping;
      counts.pressing += shares ? 1 : 0;
      counts.slipping += out.slipping ? 1 : 0;
    }
  }
  // patches absent this step are not carried over: their stretch goes
  std::swap(patches_, next_patches_);
  if (stats) *stats = counts;
}

}  // namespace frusta
