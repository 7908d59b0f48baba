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
  // the last step's patches, and as many fading ones beside this step's
  patches_.reserve(2 * static_cast<size_t>(capacity_));
  next_patches_.reserve(2 * static_cast<size_t>(capacity_));
  forces_.reserve(2 * static_cast<size_t>(capacity_));
}

void ContactForces::reset() {
  patches_.clear();
  limiting_ = false;
}

vec3 ContactForces::limit(const ForceMaterial& material, const vec3& had, const vec3& want,
                          const vec3& from, const vec3& to, ContactForceStats& stats) const {
  const double stiffness =
      std::max({material.normal_stiffness.x, material.normal_stiffness.y, material.normal_stiffness.z});
  const double step = stiffness * glm::length(to - from) + kLagForceSlack;
  const vec3 change = want - had;
  const double size = glm::length(change);
  if (!(size > step)) return want;
  ++stats.held_back;
  stats.held_back_by = std::max(stats.held_back_by, size - step);
  return had + (step / size) * change;
}

void ContactForces::fade(const Patch& gone, const HandPose& haptic, const ForceMaterial& material,
                         int32_t object_count, ContactForceStats& stats) {
  if (!limiting_ || gone.key.object >= object_count || !(glm::length(gone.push) > 0.0)) return;
  // the tables hold twice the contacts; fading pushes beyond that (a pathological churn
  // of patches) end at once rather than allocate
  if (next_patches_.size() == next_patches_.capacity() || forces_.size() == forces_.capacity()) return;
  const vec3 point = same_material_point(last_haptic_, haptic, gone.key.body, gone.point);
  const vec3 push = limit(material, gone.push, vec3(0.0), gone.point, point, stats);
  if (!(glm::length(push) > 0.0)) return;
  next_patches_.push_back({gone.key, FrictionAnchor{}, 0.0, push, point, gone.normal});
  ContactForce out;
  out.object = gone.key.object;
  out.leaf = -1;
  out.body = gone.key.body;
  out.graphic_point = point;
  out.haptic_point = point;
  out.normal = gone.normal;
  out.normal_force = push;
  forces_.push_back(out);
}

frusta_result ContactForces::set_time_step(double seconds) {
  if (frusta_result r = check_range(seconds, 0.0, 1.0, true, "time step")) return r;
  time_step_ = seconds;
  return FRUSTA_OK;
}

void ContactForces::update(const HandPose& graphic, const HandPose& haptic,
                           const SolverContact* contacts, int32_t contact_count,
                           const SolverObject* objects,
                           int32_t object_count,
                           const ForceMaterial* materials, ContactForceStats* stats, bool lagging) {
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
  limiting_ |= lagging;
  auto material_of = [&](int32_t object) -> const ForceMaterial& {
    return materials && object < object_count ? materials[object] : kDefaultMaterial;
  };
  size_t old = 0;  // the merge walk through the last step's patches
  for (const ContactPatch& patch : grouping_.patches()) {
    const RigidPose& object = objects[patch.key.object].pose;
    const ForceMaterial& material = material_of(patch.key.object);
    for (; old < patches_.size() && precedes(patches_[old].key, patch.key); ++old)
      fade(patches_[old], haptic, material_of(patches_[old].key.object), object_count, counts);
    const Patch* before =
        old < patches_.size() && !precedes(patch.key, patches_[old].key) ? &patches_[old++] : nullptr;

    const PatchPress press = patch_press(patch, before ? &before->depth : nullptr, time_step_);
    vec3 patch_force = normal_force(material, object.rotation, press);
    const vec3 point = patch.weight_sum > 0.0 ? patch.haptic_sum / patch.weight_sum : vec3(0.0);
    if (limiting_ && patch.weight_sum > 0.0) {
      const vec3 had = before ? before->push : vec3(0.0);
      const vec3 from = same_material_point(haptic, last_haptic_, patch.key.body, point);
      patch_force = limit(material, had, patch_force, from, point, counts);
    } else if (before) {
      fade(*before, haptic, material, object_count, counts);  // its contacts share nothing
    }
    const bool pressing = press.engaged > 0.0 && (press.depth > 0.0 || glm::length(patch_force) > 0.0);
    PatchFriction friction;
    if (pressing) {
      friction = patch_friction(material, object, haptic_body_frame(haptic, patch.key.body),
                                press.normal, point, patch_force,
                                before ? &before->friction : nullptr, time_step_);
      // nothing pressed, nothing held: a patch that lets go starts afresh
      next_patches_.push_back({patch.key, friction.anchor, press.depth, patch_force, point, press.normal});
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
  for (; old < patches_.size(); ++old)
    fade(patches_[old], haptic, material_of(patches_[old].key.object), object_count, counts);
  // patches absent this step are not carried over (but for a lag's fading pushes): their
  // stretch goes. The limit lets go once no push is held back.
  std::swap(patches_, next_patches_);
  limiting_ = lagging || counts.held_back > 0;
  last_haptic_ = haptic;
  if (stats) *stats = counts;
}

}  // namespace frusta
