// SPDX-License-Identifier: MIT
#include "runtime/scene_objects.h"

#include <algorithm>

#include "runtime/object_dynamics.h"

namespace frusta {

SceneObjects::SceneObjects(int32_t capacity)
    : slots_(static_cast<size_t>(capacity)), placed_(static_cast<size_t>(capacity), 0) {
  active_.reserve(static_cast<size_t>(capacity));
  active_slot_.reserve(static_cast<size_t>(capacity));
  active_material_.reserve(static_cast<size_t>(capacity));
}

void SceneObjects::apply(const WorldCommand& c) {
  Slot& slot = slots_[static_cast<size_t>(c.slot)];
  switch (c.kind) {
    case CommandKind::kAddObject:
      placed_[static_cast<size_t>(c.slot)] = 1;
      slot.tree = c.tree;
      slot.generation = c.generation;
      slot.def = c.def;
      slot.ignored_by = 0;
      break;
    case CommandKind::kRemoveObject:
      slot.tree = nullptr;
      slot.ignored_by = 0;
      break;
    case CommandKind::kObjectPose:
      placed_[static_cast<size_t>(c.slot)] = 1;
      slot.def.pose = c.def.pose;
      slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
      break;
    case CommandKind::kObjectDynamic:
      slot.def.dynamic = c.def.dynamic;
      slot.def.linear_velocity = slot.def.angular_velocity = vec3(0.0);
      break;
    case CommandKind::kAddHand:
    case CommandKind::kRemoveHand:
      break;  // the world's
  }
}

void SceneObjects::set_ignored(int32_t slot, int32_t hand, bool ignored) {
  const uint64_t bit = uint64_t{1} << hand;
  uint64_t& by = slots_[static_cast<size_t>(slot)].ignored_by;
  by = ignored ? by | bit : by & ~bit;
}

void SceneObjects::forget_hand(int32_t hand) {
  for (Slot& slot : slots_) slot.ignored_by &= ~(uint64_t{1} << hand);
}

void SceneObjects::rebuild_active() {
  moved_ = true;
  active_.clear();  // within the capacity reserved up front: no allocation
  active_slot_.clear();
  active_material_.clear();
  for (size_t s = 0; s < slots_.size(); ++s)
    if (slots_[s].tree) {
      active_.push_back({&slots_[s].tree->tree, slots_[s].def.pose});
      active_slot_.push_back(static_cast<int32_t>(s));
      active_material_.push_back(slots_[s].def.material);
    }
}

void SceneObjects::clear_reactions() {
  for (Slot& slot : slots_) slot.reaction = ObjectWrench{};
}

void SceneObjects::add_reaction(int32_t slot, const ObjectWrench& wrench) {
  ObjectWrench& total = slots_[static_cast<size_t>(slot)].reaction;
  total.force += wrench.force;
  total.torque += wrench.torque;
}

void SceneObjects::publish(std::vector<ObjectSnapshot>& snapshot) const {
  for (size_t s = 0; s < slots_.size(); ++s) {
    const Slot& slot = slots_[s];
    ObjectSnapshot& o = snapshot[s];
    o.present = slot.tree != nullptr;
    o.dynamic = slot.def.dynamic;
    o.generation = slot.generation;
    o.pose = slot.def.pose;  // where the hands met it this step
    o.linear_velocity = slot.def.linear_velocity;
    o.angular_velocity = slot.def.angular_velocity;
    o.reaction = slot.reaction;
    o.ignored_by = slot.ignored_by;
  }
}

void SceneObjects::end_step(const vec3& gravity, double dt) {
  std::fill(placed_.begin(), placed_.end(), 0);
  moved_ = false;
  bool any = false;
  for (Slot& slot : slots_) {
    if (!slot.tree || !slot.def.dynamic) continue;
    advance_object(slot.def, slot.reaction, gravity, dt);
    any = true;
  }
  if (any) rebuild_active();
}

}  // namespace frusta
